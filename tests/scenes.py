"""Scene builders shared by the property tests (staged solver and vectorised sweep)."""
import math

import numpy as np
from hypothesis import assume

import analytic
from polygons.scene import parse_scene


def m(x):
    return f"{float(x)!r} m"


def rad(x):
    return f"{float(x)!r} rad"


def crank_driver(link, theta, omega, alpha):
    d = {"crank": link, "angle": rad(theta), "omega": f"{abs(omega)!r} rad/s",
         "sense": "CCW" if omega > 0 else "CW"}
    if alpha:
        d |= {"alpha": f"{abs(alpha)!r} rad/s^2", "alpha_sense": "CCW" if alpha > 0 else "CW"}
    return d


def slider_crank_case(r, ratio, theta, omega, alpha, line_dir, offset, branch):
    """(scene, closed-form reference) of a slider-crank OA-AB with B on a guide at ``line_dir``
    offset by ``offset`` crank radii; hypothesis rejects geometries that cannot assemble."""
    L = r * ratio
    e = np.array([math.cos(line_dir), math.sin(line_dir)])
    through = offset * r * np.array([-e[1], e[0]])
    try:
        ref = analytic.slider_crank((0, 0), r, L, theta, omega, alpha, through, line_dir, branch)
    except ValueError:
        assume(False)
    scene = parse_scene({
        "ground": {"O": ["0 m", "0 m"]},
        "links": {"OA": m(r), "AB": m(L)},
        "driver": crank_driver("OA", theta, omega, alpha),
        "sliders": {"B": {"through": [m(through[0]), m(through[1])], "direction": rad(line_dir)}},
        "assembly": {"B": {"near": [m(ref["B"][0]), m(ref["B"][1])]}},
    })
    return scene, ref


#: the four-bar of S001-WE6's proportions (A, D 200 mm apart; AB 80, BC 136, CD 160 mm) as scene
#: text: ``driver`` is the [driver] table's lines, ``extra`` more [links] lines and tables
FOUR_BAR_TEXT = """
[ground]
A = ["0 mm", "0 mm"]
D = ["200 mm", "0 mm"]
[links]
AB = "80 mm"
BC = "136 mm"
CD = "160 mm"
{extra}
[driver]
crank = "AB"
{driver}
[assembly]
C = "C {side} AD"
"""


def four_bar_text(driver: str, extra: str = "", side: str = "above") -> str:
    return FOUR_BAR_TEXT.format(driver=driver.strip(), extra=extra.strip(), side=side)
