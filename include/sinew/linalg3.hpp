// Small fixed-size 3-vectors and 3x3 matrices used by element kernels.
// Row-major Mat3: m[3*i + j] is row i, column j.
#pragma once
#include <array>
#include <cmath>

namespace sinew {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<double, 9>;

inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 operator-(const Vec3& a) { return {-a[0], -a[1], -a[2]}; }
inline Vec3 operator*(double s, const Vec3& a) { return {s * a[0], s * a[1], s * a[2]}; }
inline Vec3& operator+=(Vec3& a, const Vec3& b) { a[0] += b[0]; a[1] += b[1]; a[2] += b[2]; return a; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }

inline Mat3 identity3() { return {1, 0, 0, 0, 1, 0, 0, 0, 1}; }
inline Mat3 zero3() { return {}; }
/// skew(a) b = a x b
inline Mat3 skew(const Vec3& a) { return {0, -a[2], a[1], a[2], 0, -a[0], -a[1], a[0], 0}; }
inline Vec3 operator*(const Mat3& m, const Vec3& v) {
  return {m[0] * v[0] + m[1] * v[1] + m[2] * v[2], m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
          m[6] * v[0] + m[7] * v[1] + m[8] * v[2]};
}
inline Mat3 operator*(const Mat3& a, const Mat3& b) {
  Mat3 c{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) c[3 * i + j] += a[3 * i + k] * b[3 * k + j];
  return c;
}
inline Mat3 operator+(const Mat3& a, const Mat3& b) {
  Mat3 c;
  for (int i = 0; i < 9; ++i) c[i] = a[i] + b[i];
  return c;
}
inline Mat3 operator-(const Mat3& a, const Mat3& b) {
  Mat3 c;
  for (int i = 0; i < 9; ++i) c[i] = a[i] - b[i];
  return c;
}
inline Mat3 operator*(double s, const Mat3& a) {
  Mat3 c;
  for (int i = 0; i < 9; ++i) c[i] = s * a[i];
  return c;
}
inline Mat3 transpose(const Mat3& a) { return {a[0], a[3], a[6], a[1], a[4], a[7], a[2], a[5], a[8]}; }
/// a b^T
inline Mat3 outer(const Vec3& a, const Vec3& b) {
  return {a[0] * b[0], a[0] * b[1], a[0] * b[2], a[1] * b[0], a[1] * b[1],
          a[1] * b[2], a[2] * b[0], a[2] * b[1], a[2] * b[2]};
}
inline Vec3 column(const Mat3& m, int j) { return {m[j], m[3 + j], m[6 + j]}; }
inline Mat3 fromColumns(const Vec3& a, const Vec3& b, const Vec3& c) {
  return {a[0], b[0], c[0], a[1], b[1], c[1], a[2], b[2], c[2]};
}

}  // namespace sinew
