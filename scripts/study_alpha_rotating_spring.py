#!/usr/bin/python3
"""Linear stability of Sinew's generalized-alpha loop (Arnold & Bruls; src/dynamics/generalized_alpha_scheme.hpp)
about a steady spin: a point mass m = 1 on a stiff radial spring (stiffness m omega^2, rest length 10 m) in
the plane, circling the origin at Omega = 6 rad/s, h = 0.02 s (the spin-up of test_dynamics_spinup.py and
its axial element modes, omega h up to ~330). The discrete relative equilibrium (the step map followed by
a turn back by -h Omega) is found by Newton, and the spectral radius of the linearized step map is printed:
> 1 is a linear instability of the scheme itself (docs/dynamics.md, "Not yet")."""
import numpy as np


def params(rho):
    am, af = (2 * rho - 1) / (rho + 1), rho / (rho + 1)
    g = 0.5 + af - am
    return am, af, g, 0.25 * (g + 0.5) ** 2


def step(s, h, rho, k, L0):
    q, v, a, qdd = s
    am, af, g, b = params(rho)
    Cu = q + h * v + h * h * (0.5 - b) * a
    x = q + h * v + h * h * 0.5 * a
    for _ in range(50):
        a1 = (x - Cu) / (b * h * h)
        qdd1 = ((1 - am) * a1 + am * a - af * qdd) / (1 - af)
        r = np.linalg.norm(x)
        e = x / r
        R = qdd1 + k * (r - L0) * e
        J = (1 - am) / ((1 - af) * b * h * h) * np.eye(2) + k * np.outer(e, e) + k * (r - L0) / r * (np.eye(2) - np.outer(e, e))
        dx = np.linalg.solve(J, -R)
        x = x + dx
        if np.linalg.norm(dx) < 1e-14 * np.linalg.norm(x):
            break
    a1 = (x - Cu) / (b * h * h)
    return x, v + h * (1 - g) * a + h * g * a1, a1, ((1 - am) * a1 + am * a - af * qdd) / (1 - af)


def spectral_radius(rho, omega, h=0.02, Om=6.0, L0=10.0):
    k = omega ** 2
    c, s = np.cos(-h * Om), np.sin(-h * Om)
    Q = np.array([[c, -s], [s, c]])

    def corotated(z):
        return np.concatenate([Q @ w for w in step((z[0:2], z[2:4], z[4:6], z[6:8]), h, rho, k, L0)])

    r = k * L0 / (k - Om * Om)
    z = np.array([r, 0, 0, Om * r, -Om * Om * r, 0, -Om * Om * r, 0])
    for _ in range(30):
        F = corotated(z) - z
        eps = 1e-7 * np.abs(z).max()
        J = np.array([(corotated(z + eps * e) - corotated(z - eps * e)) / (2 * eps) for e in np.eye(8)]).T
        if np.linalg.norm(F) < 1e-12 * np.linalg.norm(z):
            break
        z = z - np.linalg.solve(J - np.eye(8), F)
    ev = np.linalg.eigvals(J)
    return ev[np.argmax(np.abs(ev))]


if __name__ == "__main__":
    for rho in (1.0, 0.9, 0.8, 0.6):
        lam = [(w * 0.02, spectral_radius(rho, w)) for w in (200, 759, 3000, 15000)]
        print(f"rho_inf {rho}: " + ", ".join(f"omega h {wh:g}: |lambda| {abs(l):.4f} ({l.real:+.3f}{l.imag:+.3f}i)" for wh, l in lam))
