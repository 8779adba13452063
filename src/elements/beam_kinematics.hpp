// The corotational beam's kinematic quantities at one state (BeamCorotational::kinematics): shared by
// the kernel (beam_corotational.cpp) and its energy-momentum step force (beam_step_force.cpp).
#pragma once
#include "elements/beam_corotational.hpp"

namespace sinew {

struct BeamCorotational::Kinematics {
  Vec3 lhat{};
  double L = 0;
  Mat3 P{};
  Vec3 nyp{}, nzp{}, nyq{}, nzq{};
  double e[6]{};
  double g[6][12]{};   // grad e_i
  double Qe[6]{};      // d(arc - chord quadratic)/d e_i (i = 2..5)
  double eps[6]{};
  double ge[6][12]{};  // grad eps_i
};

}  // namespace sinew
