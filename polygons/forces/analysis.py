"""Every state a scene asks for: one instant (kinetostatic or torque-driven), or the release
position and the positions after the given rotations (:mod:`polygons.forces.release`)."""
from __future__ import annotations

from dataclasses import replace
from types import MappingProxyType

from ..errors import SceneError
from ..evaluate import solve
from ..loads import HANDLES
from ..model import check_handles, running
from ..scene import Scene
from .answers import check_expr
from .model import ForceModel, spring_refs
from .release import release
from .states import Analysis, kinetostatic, torque_driven


#: the method's name when it is called from Python (a command names itself)
METHOD = "polygons forces"


def load_model(scene: Scene, method: str | None = None) -> ForceModel:
    """The force model of ``scene`` (its tables were checked when it loaded), the answers'
    quantities checked against the kinematic and force functions.  A mechanism holding a
    kind the force analysis does not handle (:data:`polygons.loads.HANDLES`) is refused in one
    line naming ``method``, by default the command the user ran ('polygons solve', 'polygons
    check': :func:`polygons.model.running`)."""
    if scene.loads is None:
        raise SceneError("the scene was built without its force tables", file=scene.file)
    if scene.loads.active:
        check_handles(method or running(METHOD), HANDLES, scene.model, scene.file)
    for i, a in enumerate(scene.loads.answers):
        check_expr(a.quantity, a.unit, scene, f"force_answers[{i}]")
    return ForceModel(scene, scene.loads)


def analyse(scene: Scene, model: ForceModel | None = None, method: str | None = None
            ) -> Analysis:
    """The force analysis of ``scene``: the springs' references are taken at the scene's
    instant, then each state is solved (``method``: the command asking, named in a
    refusal)."""
    model = load_model(scene, method) if model is None else model
    base = solve(scene)
    model = replace(model, ref=MappingProxyType(spring_refs(model, base)))
    if model.mode == "kinetostatic":
        states = [kinetostatic(model, scene)]
        return Analysis(model, states, None)
    if model.mode == "torque-driven":
        return Analysis(model, [torque_driven(model, scene)], None)
    return release(model, scene)
