"""An independent oracle for the trust campaign's book cases (never the solver's code): the loop
closure Φ(q, θ) = 0 of each mechanism written out by hand, solved by Newton; q' = −Φ_q⁻¹ Φ_θ
with the Jacobian by complex-step differentiation (exact to rounding); q'' = −Φ_q⁻¹ γ, γ the
second directional derivative of Φ along (q', 1) (a central difference of the complex-step
directional derivative: Φ is smooth, so this holds to ~1e-11 away from a toggle).  Time rates:
q̇ = q' ω, q̈ = q'' ω² + q' α."""
import numpy as np

_H = 1e-30


def jacobian(phi, q, th):
    """(Φ_q, Φ_θ) by complex steps."""
    q = np.asarray(q, float)
    cols = []
    for i in range(len(q)):
        z = q.astype(complex)
        z[i] += 1j * _H
        cols.append(np.imag(phi(z, th)) / _H)
    return np.array(cols).T, np.imag(phi(q.astype(complex), th + 1j * _H)) / _H


def newton(phi, q0, th, steps=60):
    q = np.array(q0, float)
    for _ in range(steps):
        J, _ = jacobian(phi, q, th)
        dq = np.linalg.solve(J, -np.real(phi(q.astype(complex), th)))
        q = q + dq
        if np.max(np.abs(dq)) < 1e-15 * (1 + np.max(np.abs(q))):
            break
    return q


def motion(phi, q0, th, omega, alpha):
    """(q, q̇, q̈) at input angle ``th`` turning at ``omega``, ``alpha`` (CCW positive)."""
    q = newton(phi, q0, th)
    J, jt = jacobian(phi, q, th)
    qp = np.linalg.solve(J, -jt)

    def g(e):
        z = q.astype(complex) + e * qp + 1j * _H * qp
        return np.imag(phi(z, th + e + 1j * _H)) / _H
    e = 1e-3
    gamma = (-g(2 * e) + 8 * g(e) - 8 * g(-e) + g(-2 * e)) / (12 * e)
    qpp = np.linalg.solve(J, -gamma)
    return q, qp * omega, qpp * omega ** 2 + qp * alpha
