// Forward-mode dual numbers with N derivative components: f(x + dx) = f.v + f.d . dx to first order.
// Element kernels instantiate a force computation with Dual<N> to obtain its exact Jacobian
// (e.g. the energy-momentum step force of the corotational beam, beam_step_force.cpp).
#pragma once
#include <array>
#include <cmath>

namespace sinew {

template <int N>
struct Dual {
  double v = 0.0;
  std::array<double, N> d{};
  Dual() = default;
  Dual(double value) : v(value) {}  // NOLINT: constants convert implicitly
  /// The k-th independent variable with value `value`.
  static Dual variable(double value, int k) {
    Dual x(value);
    x.d[k] = 1.0;
    return x;
  }
};

template <int N> inline Dual<N> operator+(const Dual<N>& a, const Dual<N>& b) {
  Dual<N> c(a.v + b.v);
  for (int k = 0; k < N; ++k) c.d[k] = a.d[k] + b.d[k];
  return c;
}
template <int N> inline Dual<N> operator-(const Dual<N>& a, const Dual<N>& b) {
  Dual<N> c(a.v - b.v);
  for (int k = 0; k < N; ++k) c.d[k] = a.d[k] - b.d[k];
  return c;
}
template <int N> inline Dual<N> operator-(const Dual<N>& a) {
  Dual<N> c(-a.v);
  for (int k = 0; k < N; ++k) c.d[k] = -a.d[k];
  return c;
}
template <int N> inline Dual<N> operator*(const Dual<N>& a, const Dual<N>& b) {
  Dual<N> c(a.v * b.v);
  for (int k = 0; k < N; ++k) c.d[k] = a.d[k] * b.v + a.v * b.d[k];
  return c;
}
template <int N> inline Dual<N> operator*(double s, const Dual<N>& a) {
  Dual<N> c(s * a.v);
  for (int k = 0; k < N; ++k) c.d[k] = s * a.d[k];
  return c;
}
template <int N> inline Dual<N> operator*(const Dual<N>& a, double s) { return s * a; }
template <int N> inline Dual<N> operator+(const Dual<N>& a, double s) {
  Dual<N> c = a;
  c.v += s;
  return c;
}
template <int N> inline Dual<N> operator+(double s, const Dual<N>& a) { return a + s; }
template <int N> inline Dual<N> operator-(const Dual<N>& a, double s) { return a + (-s); }
template <int N> inline Dual<N> operator-(double s, const Dual<N>& a) { return (-a) + s; }
/// 1 / a
template <int N> inline Dual<N> inverse(const Dual<N>& a) {
  const double r = 1.0 / a.v;
  Dual<N> c(r);
  for (int k = 0; k < N; ++k) c.d[k] = -r * r * a.d[k];
  return c;
}
inline double inverse(double a) { return 1.0 / a; }
/// The value of a plain or dual number.
inline double valueOf(double a) { return a; }
template <int N> inline double valueOf(const Dual<N>& a) { return a.v; }

/// 3-vectors of any scalar (double or Dual<N>), for kernels run with dual numbers.
template <class T> using V3 = std::array<T, 3>;
template <class T> V3<T> add(const V3<T>& a, const V3<T>& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
template <class T> V3<T> sub(const V3<T>& a, const V3<T>& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
template <class T, class S> V3<T> scale(const S& s, const V3<T>& a) { return {s * a[0], s * a[1], s * a[2]}; }
template <class T> T dotT(const V3<T>& a, const V3<T>& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
template <class T> V3<T> crossT(const V3<T>& a, const V3<T>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

}  // namespace sinew
