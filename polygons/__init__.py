"""polygons: planar mechanisms solved the way a drawing board does.

    scene (TOML) → plan (dyads → construction steps) → evaluate (numbers) → render

>>> from polygons import load_scene, solve
>>> sol = solve(load_scene("cases/s003-fig7.toml"))      # doctest: +SKIP
>>> sol.links["O4P4"].omega                                # doctest: +SKIP
1.2145955942749975
"""
from .errors import PolygonsError
from .evaluate import Solution, solve
from .scene import Scene, load_scene

__all__ = ["load_scene", "solve", "Scene", "Solution", "PolygonsError"]
__version__ = "0.1.0"
