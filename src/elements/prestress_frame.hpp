// Local prestress directions of a membrane (design.md section 2: `prestress_dir`,
// `prestress_radial_axis`).
//
// The frame at a surface point with unit normal n is (e1, e2, n):
//   e1 = (s - (s.n) n) / |s - (s.n) n|,   e2 = n x e1,
// where the seed s is
//   Direction : s = d (default d = global x),
//   Radial    : s = p - (p.a) a, the perpendicular from the axis to the point p, where the axis is
//               the line through the global ORIGIN along the unit vector a = axis/|axis|, and p is
//               the centroid of the element in the configuration the frame belongs to (reference
//               for S0, current for the Cauchy prestress of form finding). e1 is then the radial
//               direction projected on the element plane and e2 the in-plane tangential (hoop) one.
// Fallbacks (degenerate seeds): a radial seed shorter than 1e-12 (1 + |p|) is replaced by global x;
// a seed whose in-plane projection is shorter than 1e-8 |s| is replaced by global x, then global y.
// The functions are templates so that the membrane kernel can differentiate the current frame
// (automatic differentiation of the form-finding tangent).
#pragma once
#include <array>
#include <cmath>

#include "sinew/linalg3.hpp"

namespace sinew {

namespace pf {
/// Value part of a scalar (double here; the AD type of the membrane kernel provides its own overload).
inline double primalValue(double x) { return x; }

template <class T> using V3 = std::array<T, 3>;

template <class T> inline T dot(const V3<T>& a, const V3<T>& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
template <class T> inline V3<T> cross(const V3<T>& a, const V3<T>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class T> inline V3<T> axpy(const T& s, const V3<T>& a, const V3<T>& b) {  // s a + b
  return {s * a[0] + b[0], s * a[1] + b[1], s * a[2] + b[2]};
}
template <class T> inline V3<T> scale(const T& s, const V3<T>& a) { return {s * a[0], s * a[1], s * a[2]}; }
template <class T> inline V3<T> lift(const Vec3& a) { return {T(a[0]), T(a[1]), T(a[2])}; }
}  // namespace pf

class PrestressFrame {
 public:
  enum class Kind { Direction, Radial };

  /// Default: first axis = global x projected on the element plane.
  PrestressFrame() = default;
  static PrestressFrame direction(const Vec3& d);
  static PrestressFrame radial(const Vec3& axis);

  Kind kind() const { return kind_; }
  const Vec3& vector() const { return v_; }  ///< unit direction d or unit axis a

  /// Seed direction s at the element centroid p (see the file comment).
  template <class T> pf::V3<T> seed(const pf::V3<T>& p) const {
    using std::sqrt;
    if (kind_ == Kind::Direction) return pf::lift<T>(v_);
    const pf::V3<T> a = pf::lift<T>(v_);
    const pf::V3<T> r = pf::axpy(T(-pf::dot(p, a)), a, p);
    const double rn = std::sqrt(primal(pf::dot(r, r)));
    const double pn = std::sqrt(primal(pf::dot(p, p)));
    if (rn < 1e-12 * (1.0 + pn)) return pf::lift<T>(Vec3{1, 0, 0});
    return r;
  }

  /// In-plane axes e1, e2 for the unit normal n and the seed s.
  template <class T>
  static void axes(const pf::V3<T>& n, const pf::V3<T>& s, pf::V3<T>& e1, pf::V3<T>& e2) {
    using std::sqrt;
    pf::V3<T> v = pf::axpy(T(-pf::dot(s, n)), n, s);
    T vv = pf::dot(v, v);
    const double ss = primal(pf::dot(s, s));
    if (primal(vv) <= 1e-16 * ss) {
      for (int k = 0; k < 2; ++k) {  // fallback: global x, then global y
        pf::V3<T> g{T(k == 0 ? 1.0 : 0.0), T(k == 1 ? 1.0 : 0.0), T(0.0)};
        v = pf::axpy(T(-pf::dot(g, n)), n, g);
        vv = pf::dot(v, v);
        if (primal(vv) > 1e-16) break;
      }
    }
    e1 = pf::scale(T(1.0 / sqrt(vv)), v);
    e2 = pf::cross(n, e1);
  }

  /// Double convenience: axes at a point p of a surface with unit normal n.
  void axesAt(const Vec3& n, const Vec3& p, Vec3& e1, Vec3& e2) const;

 private:
  template <class T> static double primal(const T& x) {
    using pf::primalValue;
    return primalValue(x);
  }
  Kind kind_ = Kind::Direction;
  Vec3 v_{1, 0, 0};
};

}  // namespace sinew
