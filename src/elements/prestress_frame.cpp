#include "elements/prestress_frame.hpp"

#include <stdexcept>

namespace sinew {

namespace {
Vec3 unit(const Vec3& v, const char* what) {
  const double n = norm(v);
  if (!(n > 0.0)) throw std::invalid_argument(std::string(what) + " must be a nonzero vector");
  return (1.0 / n) * v;
}
}  // namespace

PrestressFrame PrestressFrame::direction(const Vec3& d) {
  PrestressFrame f;
  f.kind_ = Kind::Direction;
  f.v_ = unit(d, "prestress_dir");
  return f;
}

PrestressFrame PrestressFrame::radial(const Vec3& axis) {
  PrestressFrame f;
  f.kind_ = Kind::Radial;
  f.v_ = unit(axis, "prestress_radial_axis");
  return f;
}

void PrestressFrame::axesAt(const Vec3& n, const Vec3& p, Vec3& e1, Vec3& e2) const {
  axes<double>(n, seed<double>(p), e1, e2);
}

}  // namespace sinew
