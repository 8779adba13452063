// What the membrane kernel unit tests share: a skew, non-planar patch (a triangle or a quad) with a
// prestress of all three components, so that every term of the forces and tangents shows.
#pragma once
#include <vector>

#include "elements/membrane.hpp"

namespace sinew {

struct MembranePatch {
  std::vector<Vec3> X;  ///< reference positions
  MembraneProps props;
};

/// nn = 3: a triangle, 4: a quad.
inline MembranePatch skewMembranePatch(int nn) {
  MembranePatch p;
  p.X = nn == 3 ? std::vector<Vec3>{{0, 0, 0}, {1.0, 0.1, 0}, {0.3, 0.9, 0.1}}
                : std::vector<Vec3>{{0, 0, 0}, {1.0, 0, 0.1}, {1.1, 0.9, 0}, {0, 1.0, -0.05}};
  p.props.thickness = 1e-3;
  p.props.emod = 2e8;
  p.props.nu = 0.3;
  p.props.dens = 1000;
  p.props.prestress = {2e5, 1e5, 3e4};
  return p;
}

}  // namespace sinew
