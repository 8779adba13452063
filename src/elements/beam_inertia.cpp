// The complete consistent mass of the corotational beam (docs/dynamics.md, "Inertia"). The kernel's
// consistent mass lives in the current element frame Lambda(q) = [e1 e2 e3] (chord, averaged rotated
// y axis made normal to it): M(q) = T Ml T^T, T = blockdiag(Lambda) over the four 3-blocks
// [x_p, w_p, x_q, w_q]. Its kinetic energy T = 1/2 v^T M(q) v (v: nodal velocities and spatial spins)
// is invariant under rigid motions. The inertia force is its Euler-Lagrange force, for the spins in
// the Euler-Poincare form of SO(3) with spatial angular velocities (R' = skew(w) R, dR = skew(eta) R):
//   f = d/dt (M v) - W(v) M v - dT/dq,      W(v) p = (0, w_p x p_wp, 0, w_q x p_wq),
// where the frame turns with the spin omega(v) = E(q) v (Lambda' = skew(omega) Lambda), so
//   d/dt (M v) = M a + Omega M v - M Omega v,  Omega = blockdiag(skew(omega)),
//   dT/dq . dq = -(E dq) . c,                  c = sum_b v_b x (M v)_b.
// M(q) a alone (-beam_mass consistent_frozen) leaves out the last three terms: exact for small
// motions, but under fast rotation it is not the force of any kinetic energy (no momentum balance)
// and its Jacobian misses d(M(q) a)/dq. The frame spin is omega = 1/2 sum_i e_i x e_i' with
//   e1' = (l' - e1 (e1 . l')) / |l|,  u = ybar - (ybar . e1) e1,  e2 = u / |u|,  e2' = (u' - e2 (e2 . u')) / |u|,
//   e3' = e1' x e2 + e1 x e2',  ybar = R_p ey0 + R_q ey0,  ybar' = w_p x R_p ey0 + w_q x R_q ey0.
// The tangent (d f / d q at fixed v and a, d f / d v) is exact: the same code run with dual numbers.
#include <array>
#include <cmath>

#include "elements/beam_corotational.hpp"
#include "math/dual.hpp"

namespace sinew {
namespace {

constexpr int kDofs = 12;
using D24 = Dual<2 * kDofs>;  // derivatives by the 12 dofs (translations, spatial spins) and the 12 rates


double sqrtT(double a) { return std::sqrt(a); }
D24 sqrtT(const D24& a) {
  const double r = std::sqrt(a.v);
  D24 c(r);
  for (int k = 0; k < 2 * kDofs; ++k) c.d[k] = a.d[k] / (2.0 * r);
  return c;
}

inline Vec3 load3(const double* p) { return {p[0], p[1], p[2]}; }
inline Mat3 load9(const double* p) { return {p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7], p[8]}; }
template <class T> V3<T> block(const T* v, int b) { return {v[3 * b], v[3 * b + 1], v[3 * b + 2]}; }

/// f = M a + Omega M v - M Omega v - W(v) M v + E^T c for the element frame built from the chord
/// x_q - x_p and the directors y[0] = R_p n0, y[1] = R_q n0 (file comment); Ml the local mass.
template <class T>
void inertiaForceT(const V3<T> x[2], const V3<T> y[2], const T* v, const double* a, const double* Ml, T* f) {
  const V3<T> l = sub(x[1], x[0]);
  const T L = sqrtT(dotT(l, l));
  const T iL = inverse(L);
  V3<T> e[3];
  e[0] = scale(iL, l);
  const V3<T> ybar = add(y[0], y[1]);
  const T ye = dotT(ybar, e[0]);
  const V3<T> u = sub(ybar, scale(ye, e[0]));
  const T iu = inverse(sqrtT(dotT(u, u)));
  e[1] = scale(iu, u);
  e[2] = crossT(e[0], e[1]);
  // the frame's spin is linear in the chord rate l' and the rate ybar' of the y directors:
  // omega = G1 l' + G2 ybar'; the columns of G1, G2 are the spins of unit rates
  auto spinOf = [&](const V3<T>& ld, const V3<T>& yd) {
    const V3<T> e1d = scale(iL, sub(ld, scale(dotT(e[0], ld), e[0])));
    const V3<T> ud = sub(sub(yd, scale(dotT(yd, e[0]) + dotT(ybar, e1d), e[0])), scale(ye, e1d));
    const V3<T> e2d = scale(iu, sub(ud, scale(dotT(e[1], ud), e[1])));
    const V3<T> e3d = add(crossT(e1d, e[1]), crossT(e[0], e2d));
    return scale(0.5, add(add(crossT(e[0], e1d), crossT(e[1], e2d)), crossT(e[2], e3d)));
  };
  V3<T> G1[3], G2[3];  // columns
  const V3<T> zero{T(0.0), T(0.0), T(0.0)};
  for (int j = 0; j < 3; ++j) {
    V3<T> u = zero;
    u[j] = T(1.0);
    G1[j] = spinOf(u, zero);
    G2[j] = spinOf(zero, u);
  }
  auto times = [](const V3<T>* G, const V3<T>& x) { return add(add(scale(x[0], G[0]), scale(x[1], G[1])), scale(x[2], G[2])); };
  auto timesT = [](const V3<T>* G, const V3<T>& c) { return V3<T>{dotT(G[0], c), dotT(G[1], c), dotT(G[2], c)}; };
  auto omega = [&](const T* r) {
    const V3<T> ld = sub(block(r, 2), block(r, 0));
    const V3<T> yd = add(crossT(block(r, 1), y[0]), crossT(block(r, 3), y[1]));
    return add(times(G1, ld), times(G2, yd));
  };
  // out = M r = T Ml T^T r
  auto massTimes = [&](const T* r, T* out) {
    T rl[kDofs];
    for (int b = 0; b < 4; ++b)
      for (int i = 0; i < 3; ++i) rl[3 * b + i] = dotT(e[i], block(r, b));
    for (int b = 0; b < 4; ++b) {
      T pl[3];
      for (int i = 0; i < 3; ++i) {
        T s(0.0);
        for (int c = 0; c < kDofs; ++c) {
          const double m = Ml[(3 * b + i) * kDofs + c];
          if (m != 0.0) s = s + m * rl[c];  // Ml is sparse (axial, torsion, two bending planes)
        }
        pl[i] = s;
      }
      for (int j = 0; j < 3; ++j) out[3 * b + j] = pl[0] * e[0][j] + pl[1] * e[1][j] + pl[2] * e[2][j];
    }
  };
  T p[kDofs], Ma[kDofs], Ov[kDofs], MOv[kDofs], at[kDofs];
  for (int k = 0; k < kDofs; ++k) at[k] = T(a[k]);
  massTimes(v, p);
  massTimes(at, Ma);
  const V3<T> w = omega(v);
  for (int b = 0; b < 4; ++b) {
    const V3<T> o = crossT(w, block(v, b));
    for (int i = 0; i < 3; ++i) Ov[3 * b + i] = o[i];
  }
  massTimes(Ov, MOv);
  V3<T> c{T(0.0), T(0.0), T(0.0)};
  for (int b = 0; b < 4; ++b) {
    const V3<T> vb = block(v, b), pb = block(p, b);
    const V3<T> vxp = crossT(vb, pb);
    c = add(c, vxp);
    const V3<T> op = crossT(w, pb);
    for (int i = 0; i < 3; ++i) {
      f[3 * b + i] = Ma[3 * b + i] + op[i] - MOv[3 * b + i];
      if (b % 2 == 1) f[3 * b + i] = f[3 * b + i] - vxp[i];  // spin rows: -w x (M v)_w
    }
  }
  // + E^T c, E = d omega / d r: l' = v_q - v_p, ybar' = w_p x y_p + w_q x y_q
  const V3<T> g1 = timesT(G1, c), g2 = timesT(G2, c);
  const V3<T> sp = crossT(y[0], g2), sq = crossT(y[1], g2);  // (w x y) . g = w . (y x g)
  for (int i = 0; i < 3; ++i) {
    f[i] = f[i] - g1[i];
    f[6 + i] = f[6 + i] + g1[i];
    f[3 + i] = f[3 + i] + sp[i];
    f[9 + i] = f[9 + i] + sq[i];
  }
}

}  // namespace

void BeamCorotational::inertiaForce(const double* q, const double* v, const double* a, bool tangent,
                                    InertiaOutput& out) const {
  double Ml[kDofs * kDofs];
  localMass(Ml);
  const Vec3 xp = load3(q), xq = load3(q + 12);
  const Mat3 Rp = load9(q + 3), Rq = load9(q + 15);
  // the directors whose sum gives the frame's y axis (currentFrame's choice, including its fallback
  // for ends twisted by ~pi relative to each other: node p's z axis alone)
  Vec3 yv[2] = {Rp * ey0_, Rq * ey0_};
  {
    const Vec3 ex = (1.0 / norm(xq - xp)) * (xq - xp), ys = yv[0] + yv[1];
    if (norm(ys - dot(ys, ex) * ex) < 1e-8) yv[0] = Rp * ez0_, yv[1] = Vec3{};
  }
  out.f.assign(kDofs, 0.0);
  if (!tangent) {
    const V3<double> x[2] = {xp, xq}, y[2] = {yv[0], yv[1]};
    inertiaForceT<double>(x, y, v, a, Ml, out.f.data());
    return;
  }
  V3<D24> x[2], y[2];
  D24 vd[kDofs], fd[kDofs];
  for (int b = 0; b < 2; ++b) {
    const Vec3& xb = b == 0 ? xp : xq;
    for (int i = 0; i < 3; ++i) {
      x[b][i] = D24::variable(xb[i], 6 * b + i);
      y[b][i] = D24(yv[b][i]);
    }
    for (int k = 0; k < 3; ++k) {  // d y / d w_k = e_k x y
      Vec3 ek{};
      ek[k] = 1.0;
      const Vec3 dy = cross(ek, yv[b]);
      for (int i = 0; i < 3; ++i) y[b][i].d[6 * b + 3 + k] = dy[i];
    }
  }
  for (int k = 0; k < kDofs; ++k) vd[k] = D24::variable(v[k], kDofs + k);
  inertiaForceT<D24>(x, y, vd, a, Ml, fd);
  out.Kq.assign(kDofs * kDofs, 0.0);
  out.Dv.assign(kDofs * kDofs, 0.0);
  for (int i = 0; i < kDofs; ++i) {
    out.f[i] = fd[i].v;
    for (int k = 0; k < kDofs; ++k) {
      out.Kq[i * kDofs + k] = fd[i].d[k];
      out.Dv[i * kDofs + k] = fd[i].d[kDofs + k];
    }
  }
}

}  // namespace sinew
