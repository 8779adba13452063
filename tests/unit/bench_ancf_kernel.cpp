// Micro benchmark: time per AncfCable2D::evaluate on one core, residual only and residual + tangent,
// for the A1g cantilever's element (EA = 1e6, EI = 833.33, rhoA = 78, L = 2/65536) at small deformed,
// moving states, with velocities given (as in dynamics); CPU time of the process. Not a ctest: a tool to compare kernel versions.
// Build: cmake --build build --target bench_ancf_kernel (then build/tests/bench_ancf_kernel).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <random>
#include <vector>

#include "elements/ancf_cable2d.hpp"

using namespace sinew;

namespace {
double nsPerCall(const AncfCable2D& el, const std::vector<double>& states, const KernelNeeds& needs, int reps,
                 double* sink) {
  KernelOutput out;
  const int nStates = static_cast<int>(states.size() / 16);
  // CPU time of this process (the machine is shared: wall time would count other jobs' slices)
  const std::clock_t t0 = std::clock();
  for (int r = 0; r < reps; ++r) {
    const double* q = &states[16 * (r % nStates)];
    KernelInput in{q, q + 8, nullptr, 0.01};
    el.evaluate(in, needs, out);
    *sink += out.f[1] + (needs.tangent ? out.K[9] : 0.0);
  }
  const double s = static_cast<double>(std::clock() - t0) / CLOCKS_PER_SEC;
  return 1e9 * s / reps;
}
}  // namespace

int main(int argc, char** argv) {
  const int reps = argc > 1 ? std::atoi(argv[1]) : 2000000;
  const double L = 2.0 / 65536;
  AncfCable2DParameters p;
  p.physicsMassPerLength = 78.0;
  p.physicsAxialStiffness = 1e6;
  p.physicsBendingStiffness = 833.3333333333333;
  const std::array<double, 8> qRef = {0.0, 0.0, 1.0, 0.0, L, 0.0, 1.0, 0.0};
  const AncfCable2D el(qRef, L, p);
  std::mt19937 g(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  constexpr int nStates = 64;
  std::vector<double> states(16 * nStates);
  for (int k = 0; k < nStates; ++k)
    for (int i = 0; i < 8; ++i) {
      states[16 * k + i] = qRef[i] + 1e-3 * (i % 2 == 0 && i % 4 == 0 ? L : 1.0) * u(g);
      states[16 * k + 8 + i] = 0.1 * u(g);
    }
  double sink = 0;
  KernelNeeds res, tan;
  tan.tangent = true;
  // three alternating rounds, median
  std::vector<double> tr, tt;
  for (int round = 0; round < 3; ++round) {
    tr.push_back(nsPerCall(el, states, res, reps, &sink));
    tt.push_back(nsPerCall(el, states, tan, reps / 2, &sink));
  }
  std::sort(tr.begin(), tr.end());
  std::sort(tt.begin(), tt.end());
  std::printf("ancf_cable2d evaluate: residual %.0f ns, residual + tangent %.0f ns per element (median of 3)%s\n", tr[1], tt[1],
              sink == 12345.0 ? " " : "");
  return 0;
}
