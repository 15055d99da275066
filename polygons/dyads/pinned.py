"""The construction shared by the dyads whose point X is pinned to a placed point P by a link
of known length (RRR, RRP): a line ⟂ PX through p, met by a second line — ⟂ QX through q for a
second link, or along the guide through the pole for a slider.

Velocity: v_X = v_P + ω_PX × PX.  Acceleration: a_X = a_P − ω² PX + α × PX.
"""
from __future__ import annotations

from ..steps import Builder, Component, Kind, Op


def emit_two_lines(b: Builder, P: str, X: str, LP: str, other) -> None:
    """Steps for X from P (link ``LP``) and ``other`` = (Q, LQ) or None (X on a guide)."""
    V = b.names.of
    p, x, pole = V(P), V(X), b.names.pole
    # the resultant named from the second link's fixed pivot when it has one ('dc' about the
    # fixed D, as the book writes it; the pole is 'a = d')
    # (the intersection's args: that pivot, read by the resultant's symbol)
    fixed = (other[0],) if other is not None and other[0] in b.scene.ground else ()
    about = b.names.named(fixed[0]) if fixed else pole
    C = Component
    if b.velocity:
        n1 = b.add(Kind.LINE, Op.LINE_PERP, (P, X), f"line ⟂ {P}{X}", p, None,
                   "relative_velocity", f"(v_{X})_{P}", f"(v_{X})_{P} ⟂ {P}{X}",
                   f"Through {p} draw a line perpendicular to {P}{X}: the velocity of {X} "
                   f"relative to {P}, of unknown length.", component=C.RELATIVE, link=LP,
                   relative=(X, P))
        if other is not None:
            Q, LQ = other
            q_ = V(Q)
            n2 = b.add(Kind.LINE, Op.LINE_PERP, (Q, X), f"line ⟂ {Q}{X}", q_, None,
                       "relative_velocity", f"(v_{X})_{Q}", f"(v_{X})_{Q} ⟂ {Q}{X}",
                       f"Through {q_} draw a line perpendicular to {Q}{X}: the velocity of "
                       f"{X} relative to {Q}, of unknown length.", component=C.RELATIVE,
                       link=LQ, relative=(X, Q))
        else:
            n2 = b.add(Kind.LINE, Op.LINE_GUIDE, (X,), "slider line", pole, None,
                       "slider_line", f"v_{X}", f"v_{X} ∥ guide of {X}",
                       f"Through {pole} draw a line along the guide of {X}: the slider "
                       f"can only move along it.", component=C.RESULTANT)
        b.add(Kind.INTERSECTION, Op.INTERSECT, fixed, x, None, x, "intersection", f"v_{X}",
              f"{x} = intersection of the two lines",
              f"The two lines meet at {x}: {about}{x} is the velocity of {X}.", (n1, n2),
              component=C.RESULTANT)
        b.add(Kind.MEASURE, Op.OMEGA, (LP, P, X), f"ω_{LP}", None, None, "angular_velocity",
              f"ω_{LP}", f"ω_{LP} = {p}{x} / {P}{X}",
              f"The angular velocity of {LP} is the relative velocity divided by its length.",
              component=C.RELATIVE, link=LP, reads=f"{p}{x}")
        if other is not None:
            Q, LQ = other
            b.add(Kind.MEASURE, Op.OMEGA, (LQ, Q, X), f"ω_{LQ}", None, None,
                  "angular_velocity", f"ω_{LQ}", f"ω_{LQ} = {b.names.named(Q)}{x} / {Q}{X}",
                  f"The angular velocity of {LQ} is its relative velocity divided "
                  f"by its length.", component=C.RELATIVE, link=LQ,
                  reads=f"{b.names.named(Q)}{x}")
        else:
            b.add(Kind.MEASURE, Op.SLIDER_VELOCITY, (X,), f"v_{X}", None, None, "slider",
                  f"v_{X} along guide", f"v_{X} = {pole}{x}",
                  f"The slider velocity is {pole}{x}, along its guide.",
                  component=C.RESULTANT)
        return
    # acceleration
    x1 = b.fresh(X)
    # a vector from the pole named from its centre's own letter, as the book writes it (dc₂
    # about the fixed D where the pole is a = d)
    pn = b.names.named(P)
    b.add(Kind.VECTOR, Op.CENTRIPETAL, (LP, P, X), f"{pn}{x1}", p, x1, "centripetal",
          f"(a_{X})_{P}^n", f"(a_{X})_{P}^n = ω_{LP}² × {P}{X} = v²/{P}{X}",
          f"From {pn} draw the centripetal acceleration of {X} relative to {P}, parallel to "
          f"{P}{X} and pointing from {X} towards {P}; call its end {x1}.",
          component=C.CENTRIPETAL, link=LP)
    n1 = b.add(Kind.LINE, Op.LINE_PERP, (P, X), f"line ⟂ {P}{X}", x1, None,
               "tangential", f"(a_{X})_{P}^t", f"(a_{X})_{P}^t = α_{LP} × {P}{X} ⟂ {P}{X}",
               f"Through {x1} draw a line perpendicular to {P}{X} for the tangential "
               f"acceleration of unknown length.", component=C.TANGENTIAL,
               link=LP, relative=(X, P))
    if other is not None:
        Q, LQ = other
        q_, qn = V(Q), b.names.named(Q)
        x2 = b.fresh(X)
        b.add(Kind.VECTOR, Op.CENTRIPETAL, (LQ, Q, X), f"{qn}{x2}", q_, x2, "centripetal",
              f"(a_{X})_{Q}^n", f"(a_{X})_{Q}^n = ω_{LQ}² × {Q}{X} = v²/{Q}{X}",
              f"From {qn} draw the centripetal acceleration of {X} relative to {Q}, "
              f"pointing from {X} towards {Q}; call its end {x2}.", component=C.CENTRIPETAL,
              link=LQ)
        n2 = b.add(Kind.LINE, Op.LINE_PERP, (Q, X), f"line ⟂ {Q}{X}", x2, None, "tangential",
                   f"(a_{X})_{Q}^t", f"(a_{X})_{Q}^t = α_{LQ} × {Q}{X} ⟂ {Q}{X}",
                   f"Through {x2} draw a line perpendicular to {Q}{X} for the tangential "
                   f"acceleration of {X} relative to {Q}, of unknown length.",
                   component=C.TANGENTIAL, link=LQ, relative=(X, Q))
    else:
        n2 = b.add(Kind.LINE, Op.LINE_GUIDE, (X,), "slider line", pole, None, "slider_line",
                   f"a_{X}", f"a_{X} ∥ guide of {X}",
                   f"Through {pole} draw a line along the guide of {X}: the slider's "
                   f"acceleration lies along it.", component=C.RESULTANT)
    b.add(Kind.INTERSECTION, Op.INTERSECT, fixed, x, None, x, "intersection", f"a_{X}",
          f"{x} = intersection of the two lines",
          f"The lines meet at {x}: {about}{x} is the acceleration of {X}.", (n1, n2),
          component=C.RESULTANT)
    b.add(Kind.MEASURE, Op.ALPHA, (LP, P, X), f"α_{LP}", None, None, "angular_acceleration",
          f"α_{LP}", f"α_{LP} = {x1}{x} / {P}{X}",
          f"The angular acceleration of {LP} is its tangential acceleration {x1}{x} "
          f"divided by {P}{X}.", component=C.TANGENTIAL, link=LP, reads=f"{x1}{x}")
    if other is not None:
        Q, LQ = other
        b.add(Kind.MEASURE, Op.ALPHA, (LQ, Q, X), f"α_{LQ}", None, None,
              "angular_acceleration", f"α_{LQ}", f"α_{LQ} = {x2}{x} / {Q}{X}",
              f"The angular acceleration of {LQ} is {x2}{x} divided by {Q}{X}.",
              component=C.TANGENTIAL, link=LQ, reads=f"{x2}{x}")
    else:
        b.add(Kind.MEASURE, Op.SLIDER_ACCELERATION, (X,), f"a_{X}", None, None, "slider",
              f"a_{X} along guide", f"a_{X} = {pole}{x}",
              f"The slider acceleration is {pole}{x}, along its guide.",
              component=C.RESULTANT)
