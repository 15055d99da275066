"""Independent closed-form check for the slider-crank (in-line or offset): the loop closure
differentiated by hand, numpy only (no polygons import), for Klein's construction's tests.

O at the origin, the line of stroke y = e (along +x), crank OA = r at θ (CCW from +x) turning
at ω (CCW positive, uniform), rod AB = L, the piston B at (x_B, e) on the ``side`` (+1: x_B
right of A, -1: left).
"""
import math


def slider_crank(r, L, theta, omega, e=0.0, side=1.0, alpha=0.0):
    """dict: x_B, v_B, a_B (along +x), omega_rod, alpha_rod (CCW positive)."""
    ax, ay = r * math.cos(theta), r * math.sin(theta)
    vax, vay = -omega * ay, omega * ax
    aax = -omega ** 2 * ax - alpha * ay
    aay = -omega ** 2 * ay + alpha * ax
    dy = e - ay
    dx = side * math.sqrt(L * L - dy * dy)
    # (x_B − A_x)² + (e − A_y)² = L², differentiated once and twice
    ddx = dy * vay / dx                       # ẋ_B − Ȧ_x
    ddy = -vay
    vb = vax + ddx
    dddx = (-dy * -aay - ddx ** 2 - ddy ** 2) / dx   # ẍ_B − Ä_x
    dddy = -aay
    ab = aax + dddx
    w_rod = (dx * ddy - dy * ddx) / (L * L)
    a_rod = (dx * dddy - dy * dddx) / (L * L)
    return {"x_B": ax + dx, "v_B": vb, "a_B": ab, "omega_rod": w_rod, "alpha_rod": a_rod}
