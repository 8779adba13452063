// Micro benchmark: residual + tangent evaluations per second of BeamCorotational on one core.
// Build: g++ -std=c++20 -O2 -Iinclude -Isrc src/math/rotation.cpp src/elements/beam_section.cpp
//        src/elements/beam_corotational.cpp tests/unit/bench_beam_kernel.cpp -o /tmp/bench_beam
#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

#include "elements/beam_corotational.hpp"
#include "sinew/rotation.hpp"

using namespace sinew;

int main() {
  BeamProperties set;
  set.flex = {true, true, true, true, true, true};
  set.emod = 210e9;
  set.smod = 80e9;
  set.dens = 7800;
  set.cshape = CrossSection::Rect;
  set.dim = {0.05, 0.0002};
  const Vec3 Xp{0, 0, 0}, Xq{0.1, 0.02, 0.0};
  const BeamSection s = beamSection(set, norm(Xq - Xp));
  constexpr auto F = BeamMode::Flexible;
  const BeamCorotational flex(Xp, Xq, Vec3{0, 0, 1}, s, {F, F, F, F, F, F}, true, 1.0);
  const BeamCorotational mixed(Xp, Xq, Vec3{0, 0, 1}, s, {BeamMode::Rigid, F, F, F, BeamMode::Rigid, F}, true, 1e9);

  // a pool of deformed states
  std::mt19937 g(7);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  constexpr int nStates = 64;
  std::vector<double> states(24 * nStates);
  for (int k = 0; k < nStates; ++k) {
    double* q = &states[24 * k];
    for (int node = 0; node < 2; ++node) {
      const Vec3 X = node == 0 ? Xp : Xq;
      const Mat3 R = expSO3({u(g), u(g), u(g)});
      for (int i = 0; i < 3; ++i) q[12 * node + i] = X[i] + 0.01 * u(g);
      for (int i = 0; i < 9; ++i) q[12 * node + 3 + i] = R[i];
    }
  }
  const double lambda[2] = {0.3, -0.2};
  KernelNeeds needs;
  needs.tangent = true;
  for (const BeamCorotational* b : {&flex, &mixed}) {
    KernelOutput out;
    KernelInput in;
    in.lambda = b->numConstraints() ? lambda : nullptr;
    double sink = 0;
    const long n = 2000000;
    const auto t0 = std::chrono::steady_clock::now();
    for (long i = 0; i < n; ++i) {
      in.q = &states[24 * (i % nStates)];
      b->evaluate(in, needs, out);
      sink += out.K[13];
    }
    const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%s (%d constraints): %.0f residual+tangent evaluations/s (%.1f ns each; checksum %.3e)\n",
                b == &flex ? "all flexible" : "2 rigid modes", b->numConstraints(), n / dt, 1e9 * dt / n, sink);
  }
  return 0;
}
