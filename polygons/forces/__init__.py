"""Forces: inertia forces, the input torque, every pin reaction, torque-driven and released motion.

The force tables are parsed and checked when the scene loads (:mod:`polygons.loads`, a frozen
model on ``Scene.loads``); this package reads them against the kinematic solution:

* :mod:`.model` — the model at an instant: images of centres of mass in the polygons, loads,
  springs, friction senses, inertia terms;
* :mod:`.newton_euler` — three equations per moving body, one linear solve (pins, guides,
  slots, the input torque or the input's α), and the internal forces at a section;
* :mod:`.virtual_work` — the input effort from the power balance, term by term;
* :mod:`.states` — one analysed instant, kinetostatic or torque-driven;
* :mod:`.release` — a mechanism released from rest: energy against RK4 integration;
* :mod:`.machine` — a flywheel on the crank shaft (α = (T − T_R)/I) and the efficiency;
* :mod:`.answers` — named force quantities and the check of ``[[force_answers]]``;
* :mod:`.analysis` — the model of a scene and every state it asks for.

Imports go one way: model → newton_euler, virtual_work → states → release, machine →
answers → analysis.
"""
from __future__ import annotations

from .analysis import analyse, load_model
from .answers import (FORCE_FUNCTIONS, ForceCheck, check_force_answers, force_quantity,
                      to_unit)
from .model import (ForceModel, Inertia, Load, has_forces, image, inertias, position,
                    spring_state)
from .newton_euler import NEResult, contact_force, newton_euler, section
from .states import Analysis, State, driver_state, virtual_solution
from .virtual_work import virtual_work

__all__ = ["analyse", "Analysis", "State", "ForceModel", "Inertia", "Load", "NEResult",
           "ForceCheck", "FORCE_FUNCTIONS", "check_force_answers", "force_quantity", "to_unit",
           "has_forces", "image", "inertias", "load_model", "position", "spring_state",
           "contact_force", "newton_euler", "section", "driver_state", "virtual_solution",
           "virtual_work"]
