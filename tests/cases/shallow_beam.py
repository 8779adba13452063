"""Shallow-beam (Marguerre) theory of a clamped-clamped beam under a mid-span point load, the reference
of test_continuation_flexures.py and scripts/study_continuation.py:
EI (w - w0)'''' + P w'' = -F delta(x - L/2), clamped ends, P L / EA = Delta + 1/2 int (w0'^2 - w'^2) dx
(uniform axial compression P, stress-free shape w0, end shortening Delta). For each P, w = a + F b
(fourth-order finite differences on N intervals, banded solves); the compatibility is a quadratic in F."""
import numpy as np
from scipy.linalg import solve_banded
from scipy.optimize import minimize_scalar


class Shallow:
    """Shallow-beam theory on N intervals: w = a(P) + F b(P) at the interior points."""

    def __init__(self, L, EI, EA, w0f, Delta, N=400):
        self.L, self.EI, self.EA = L, EI, EA
        self.hx = hx = L / N
        self.x = np.arange(1, N) * hx
        self.w0 = w0f(self.x)
        m = N - 1
        self.c = N // 2 - 1
        # EI D4 (clamped: ghost w_-1 = w_1) and D2, banded
        d4 = np.zeros((5, m))
        d4[0, 2:], d4[1, 1:], d4[2, :], d4[3, :-1], d4[4, :-2] = 1, -4, 6, -4, 1
        d4[2, 0] += 1
        d4[2, -1] += 1
        self.D4 = EI * d4 / hx ** 4
        self.D2 = np.zeros((5, m))
        self.D2[1, 1:], self.D2[2, :], self.D2[3, :-1] = 1 / hx ** 2, -2 / hx ** 2, 1 / hx ** 2
        self.r0 = self.apply(self.D4, self.w0)
        self.e = np.zeros(m)
        self.e[self.c] = 1 / hx
        self.C0 = Delta + 0.5 * self.g(self.w0, self.w0)
        self.P1 = 4 * np.pi ** 2 * EI / L ** 2
        self.P2 = 80.763 * EI / L ** 2  # antisymmetric buckling of a clamped beam, (2 x 4.4934)^2 EI / L^2

    @staticmethod
    def apply(B, v):
        out = B[2] * v
        out[:-1] += B[1, 1:] * v[1:]
        out[:-2] += B[0, 2:] * v[2:]
        out[1:] += B[3, :-1] * v[:-1]
        out[2:] += B[4, :-2] * v[:-2]
        return out

    def g(self, u, v):
        du, dv = np.diff(np.r_[0, u, 0]), np.diff(np.r_[0, v, 0])
        return np.sum(du * dv) / self.hx

    def ab(self, P):
        A = self.D4 + P * self.D2
        return solve_banded((2, 2), A, self.r0), solve_banded((2, 2), A, -self.e)

    def roots(self, P):
        """(F, mid-span w) of both roots of the compatibility at axial force P (upper root first)."""
        a, b = self.ab(P)
        aa, ab, bb = self.g(a, a), self.g(a, b), self.g(b, b)
        C = self.C0 - P * self.L / self.EA
        disc = ab ** 2 - bb * (aa - 2 * C)
        if disc < 0:
            return None
        return [((-ab + s * np.sqrt(disc)) / bb, a[self.c] + (-ab + s * np.sqrt(disc)) / bb * b[self.c]) for s in (1, -1)]

    def extreme(self, lo, hi, branch, sign):
        """Largest (sign 1) / smallest (sign -1) F for P in [lo, hi] of the root branch that starts as root
        `branch` at lo (followed by continuity of the mid-span deflection)."""
        Ps = np.linspace(lo, hi, 150)
        idx, last = [], None
        for P in Ps:
            r = self.roots(P)
            if r is None:
                break
            j = branch if last is None else int(np.argmin([abs(z[1] - last) for z in r]))
            idx.append(j)
            last = r[j][1]
        Ps = Ps[:len(idx)]
        vals = [-sign * self.roots(P)[j][0] for P, j in zip(Ps, idx)]
        k = int(np.argmin(vals))
        branch = idx[k]
        f = lambda P: -sign * self.roots(P)[branch][0] if self.roots(P) else np.inf
        r = minimize_scalar(f, bounds=(Ps[max(k - 1, 0)], Ps[min(k + 1, len(Ps) - 1)]), method="bounded",
                            options={"xatol": 1e-10 * hi})
        return self.roots(r.x)[branch]

    def trace(self, n=3000):
        """The path from the unloaded state (F = 0, w = w0): (F, mid-span w) arrays, P increasing from 0
        and, past a fold in P (where the two roots meet), decreasing on the other root. A root is chosen
        by the mid-span deflection extrapolated from the last two points."""
        Ps = np.linspace(0.0, 0.99999 * self.P2, n)
        F, w = [], []
        k = 0
        for k, P in enumerate(Ps):
            z = self.roots(P)
            if z is None:
                break
            if not w:
                j = int(np.argmin([abs(q[0]) for q in z]))
            else:
                pred = w[-1] + (w[-1] - w[-2] if len(w) > 1 else 0.0)
                j = int(np.argmin([abs(q[1] - pred) for q in z]))
            F.append(z[j][0])
            w.append(z[j][1])
        else:
            return np.array(F), np.array(w)
        for m, P in enumerate(Ps[k - 1::-1]):  # back along the other root
            z = self.roots(P)
            if z is None:
                break
            if m == 0:  # at the last forward P: the root we did not come along
                j = int(np.argmax([abs(q[1] - w[-1]) for q in z]))
            else:
                pred = w[-1] + (w[-1] - w[-2])
                j = int(np.argmin([abs(q[1] - pred) for q in z]))
            F.append(z[j][0])
            w.append(z[j][1])
        return np.array(F), np.array(w)
