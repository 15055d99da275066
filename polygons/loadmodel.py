"""The frozen records of a scene's force tables (built by :mod:`polygons.loads`), all SI."""
from __future__ import annotations

import math
from dataclasses import dataclass

from .errors import UnsupportedError

# (the records of a scene without force tables, split out so that such a scene's load does
# not create the dozen records below: re-exported)
from .loadbodies import Body, Joint, Loads, bodies_of  # noqa: F401

Vec = tuple[float, float]


#: a cam's / curved slot's equivalent link stands for the contact: it carries no load
EQUIVALENT_LINK = ("{0} is the equivalent link of the {1.kind} at {1.at}: it stands for the "
                   "contact at this instant and carries no load or mass; put it on the cam or "
                   "the follower")


@dataclass(frozen=True)
class SlotContact:
    pin: str            # the pin label (on ``carrier``)
    lever: str          # the slotted body (a lever, or a Scotch yoke's slider block)
    pivot: str | None   # the lever's pivot (the slot runs through it); None for a yoke
    carrier: str
    direction: Vec | None = None   # a yoke's slot keeps this direction
    coincident: str | None = None  # the lever's point under the pin
    far: str | None = None         # an offset slot runs along pivot → far, not pivot → pin


@dataclass(frozen=True)
class MassItem:
    name: str
    body: str
    kind: str                   # 'link' | 'block' | 'point'
    mass: float
    inertia: float              # about its own centre of mass
    how: str                    # how the inertia was obtained, in words
    along: float | None = None  # link items: centre along a → b
    left: float = 0.0
    at: str | None = None       # point items
    rod: bool = False           # uniform slender rod between the link's ends
    free: bool = False          # turns freely on a frictionless pin: no rotational coupling
    spin: float | None = None   # free disc: its constant spin (rad/s)


@dataclass(frozen=True)
class AppliedForce:
    name: str
    body: str
    at: str
    force: Vec
    how: str
    #: it acts only while it opposes its point's motion (a cutting force: none on the return)
    resisting: bool = False


@dataclass(frozen=True)
class AppliedTorque:
    name: str
    body: str
    at: str | None
    torque: float               # CCW positive


@dataclass(frozen=True)
class Friction:
    name: str
    at: str
    first: str
    second: str | None          # None: the ground
    torque: float               # magnitude


@dataclass(frozen=True)
class Spring:
    name: str
    kind: str                   # 'linear' | 'directional' | 'torsional'
    stiffness: float
    ends: tuple = ()            # linear: ((label, body|None), (label, body|None))
    free_length: float | None = None
    extension: float | None = None   # at the scene's instant (linear / directional)
    at: str | None = None
    body: str | None = None          # directional: the body carrying ``at``
    direction: Vec | None = None     # directional: from ``at`` towards the far end
    first: str | None = None         # torsional
    second: str | None = None
    twist: float = 0.0               # torsional: at the scene's instant, CCW of first rel. second


@dataclass(frozen=True)
class ForceAnswer:
    quantity: str
    unit: str
    tutorial: float | None
    exact: float | None
    mode: str
    positive: int               # +1 CCW, -1 CW: sense of positive normal components / moments
    state: str | None
    tolerance: float
    slip: bool
    ref: str | None
    desc: str
    note: str
    sense: str | None


@dataclass(frozen=True)
class Flywheel:
    """A flywheel on the crank shaft: I = m k² (or given) and the resisting torque T_R (given,
    or from the power taken off, T_R = P/ω)."""
    inertia: float
    how: str
    resisting_torque: float | None
    power: float | None


@dataclass(frozen=True)
class Efficiency:
    """The mechanism's efficiency η and, optionally, the effort applied at the driver."""
    eta: float
    input_effort: float | None        # N m for a crank driver, N for a slider driver


@dataclass(frozen=True)
class Effort:
    """Where the force analysis finds the balancing effort ([dynamics] effort), the driver
    staying the kinematic input: ``kind`` 'torque' (a couple on ``body``, CCW positive),
    'force' (a force on the slider block ``body`` along its guide, positive along the guide's
    direction) or 'actuator' (a massless actuator between ``ends`` = ((E, body or None),
    (F, body or None)), positive pushing E and F apart); ``text`` as written."""
    kind: str
    text: str
    body: str | None = None
    ends: tuple = ()


def slot_contacts(model, members, file: str | None) -> list[SlotContact]:
    """Each pin sliding in the slot of a lever or of a yoke, as a contact between the body
    carrying the pin and the slotted body (the massless block between them left out)."""
    out = []
    for s in model.sliding:
        if s.prescribed or s.carrier == "frame":
            continue
        carriers = [b for b in members.get(s.at, []) if b != s.carrier]
        yoke = s.line.toward is None
        if not carriers:
            what = f"the yoke {s.carrier}" if yoke else s.carrier
            raise UnsupportedError(f"the pin {s.at} in the slot of {what} is on no moving body",
                                   file=file, where=s.key)
        if yoke:
            out.append(SlotContact(s.at, s.carrier, None, carriers[0],
                                   (math.cos(s.line.angle), math.sin(s.line.angle))))
        else:
            out.append(SlotContact(s.at, s.carrier, s.line.origin, carriers[0],
                                   coincident=s.coincident,
                                   far=s.line.toward if s.line.offset else None))
    return out
