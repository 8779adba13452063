"""Shallow-arch theory (Marguerre: EI (w - w0)'''' + N w'' = -P delta(x - L/2), N = EA/L int (w0'^2 - w'^2)/2)
of a pinned arch with immovable supports under a central point load, solved exactly for the point
load by a sine series (Galerkin with the odd modes n = 1, 3, ..., 2M - 1; see Bazant & Cedolin,
Stability of Structures, section 2.? on shallow arches). Symmetric path: for a thrust N the modal
amplitudes are linear in P, a_n = (N k_n^2 b_n - 2 P s_n / L) / (EI k_n^4 - N k_n^2) (b_n: the
initial shape's sine coefficients, s_n = sin(n pi / 2)); the centre deflection wc fixes P, and
compatibility g(N, wc) = 0 is one equation: the path is the curve g = 0 in the (wc, N) plane, traced
by pseudo-arclength. The antisymmetric mode n = 2 bifurcates where N reaches N2 = 4 pi^2 EI / L^2."""
import numpy as np
from scipy.optimize import brentq


class PinnedShallowArch:
    def __init__(self, L, h, b, t, E, shape="circle", modes=400):
        self.L, A, I = L, b * t, b * t ** 3 / 12
        self.EI, self.EA = E * I, E * A
        n = np.arange(1, 2 * modes, 2)
        self.k, self.s = n * np.pi / L, np.sin(n * np.pi / 2)
        x = np.linspace(0, L, 200001)
        if shape == "circle":
            R = (L ** 2 / 4 + h ** 2) / (2 * h)
            w0 = np.sqrt(R ** 2 - (x - L / 2) ** 2) - (R - h)
        else:
            w0 = 4 * h * x * (L - x) / L ** 2
        self.b = np.array([2 / L * np.trapz(w0 * np.sin(kk * x), x) for kk in self.k])
        self.N1, self.N2 = self.EI * (np.pi / L) ** 2, self.EI * (2 * np.pi / L) ** 2

    def load(self, N, wc):
        """P and the amplitudes at thrust N and centre deflection wc (positive up)."""
        k, s, b = self.k, self.s, self.b
        d = self.EI * k ** 4 - N * k ** 2
        al, be = N * k ** 2 * b / d, -2 / self.L * s / d
        P = (wc - np.sum(s * al)) / np.sum(s * be)
        return P, al + P * be

    def g(self, N, wc):
        P, a = self.load(N, wc)
        return self.EA / 4 * np.sum(self.k ** 2 * (self.b ** 2 - (a + self.b) ** 2)) - N

    def symmetric_path(self, wc_end=-0.026, h=2e-3, max_points=50000):
        """Points (wc, P, N) along the symmetric path from the unloaded arch, pseudo-arclength h in
        (wc / 0.026 m, N / N1), until wc passes wc_end (h = 1e-2 and 2e-3 give the features of
        __main__ to 5 digits; h = 3e-2 jumps across the path's loop)."""
        ws, Ns = 0.026, self.N1
        z = np.array([0.0, 0.0])  # (wc/ws, N/N1)
        t = np.array([-1.0, 0.0])
        out = []
        G = lambda z: self.g(z[1] * Ns, z[0] * ws) / Ns
        for _ in range(max_points):
            # tangent of g = 0: orthogonal to grad g
            e = 1e-7
            gr = np.array([(G(z + [e, 0]) - G(z - [e, 0])) / (2 * e), (G(z + [0, e]) - G(z - [0, e])) / (2 * e)])
            tn = np.array([-gr[1], gr[0]])
            tn /= np.linalg.norm(tn)
            if tn @ t < 0:
                tn = -tn
            t = tn
            y = z + h * t
            for _ in range(30):  # Newton on [g(y) = 0, (y - z).t = h]
                gy = G(y)
                gr = np.array([(G(y + [e, 0]) - G(y - [e, 0])) / (2 * e), (G(y + [0, e]) - G(y - [0, e])) / (2 * e)])
                J = np.array([gr, t])
                dy = np.linalg.solve(J, -np.array([gy, (y - z) @ t - h]))
                y = y + dy
                if np.linalg.norm(dy) < 1e-13:
                    break
            z = y
            wc, N = z[0] * ws, z[1] * Ns
            out.append((wc, self.load(N, wc)[0], N))
            if wc < wc_end:
                break
        return np.array(out)


def features(path, N2):
    """Located along the traced path (wc, P, N): limit points (P extrema), turning points of wc,
    crossings of N = N2 (antisymmetric bifurcations) and of P = 0, each as (kind, wc, P) in path order,
    by quadratic (extrema) or linear (crossings) interpolation between the path points."""
    wc, P, N = path.T
    out = []
    for i in range(1, len(wc) - 1):
        for kind, y in (("limit", P), ("turn", wc)):
            if (y[i] - y[i - 1]) * (y[i + 1] - y[i]) < 0:
                # parabola through three points in the path parameter
                c = np.polyfit([-1, 0, 1], y[i - 1:i + 2], 2)
                tt = -c[1] / (2 * c[0])
                other = wc if kind == "limit" else P
                co = np.polyfit([-1, 0, 1], other[i - 1:i + 2], 2)
                v = np.polyval(c, tt)
                out.append((kind, np.polyval(co, tt), v) if kind == "limit" else (kind, v, np.polyval(co, tt)))
    for i in range(len(wc) - 1):
        for kind, y, level in (("bifurcation", N, N2), ("zero", P, 0.0)):
            if (y[i] - level) * (y[i + 1] - level) < 0:
                f = (level - y[i]) / (y[i + 1] - y[i])
                out.append((kind, wc[i] + f * (wc[i + 1] - wc[i]), P[i] + f * (P[i + 1] - P[i]), i + f))
    return out


if __name__ == "__main__":
    # the issue 24 arch: the values test_continuation_shallow_arch.py compares with (printed there too)
    arch = PinnedShallowArch(1.0, 0.01, 0.02, 0.004, 210e9, modes=200)
    for f in features(arch.symmetric_path(wc_end=-0.0205), arch.N2):
        print(f"{f[0]:12s} wc {f[1]:.6f} m  P {f[2]:.4f} N")
