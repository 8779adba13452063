#include "app/flags.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "scene/scene_reader.hpp"

namespace sinew {

namespace groups {
const FlagGroup output{"Sinew: result file", "README.md"};
const FlagGroup scene{"Sinew: scene opt fields (each overrides the scene's opt block)", "docs/scene.md"};
const FlagGroup statics{"Sinew: statics (load stepping, Newton)", "docs/beam.md"};
const FlagGroup ancf{"Sinew: fine ANCF cables (element-wise tangent, cable coarse space)", "docs/ancf_cable2d.md"};
const FlagGroup check{"Sinew: model check (mechanisms, redundant constraints)", "docs/compliance.md"};
const FlagGroup modal{"Sinew: frequencies and buckling (SLEPc)", "docs/modal.md"};
const FlagGroup compliance{"Sinew: compliance matrices", "docs/compliance.md"};
const FlagGroup dynamics{"Sinew: dynamics", "docs/ancf_cable2d.md"};
const FlagGroup formfinding{"Sinew: form finding", "docs/formfinding.md"};
}  // namespace groups

const std::vector<const FlagGroup*>& flagGroups() {
  static const std::vector<const FlagGroup*> all = {&groups::output,  &groups::scene, &groups::statics,
                                                    &groups::ancf,    &groups::check, &groups::modal,
                                                    &groups::compliance, &groups::dynamics, &groups::formfinding};
  return all;
}

const std::vector<Flag>& sinewFlags() {
  using namespace groups;
  static const std::vector<Flag> flags = [] {
    // One line per flag: name, accepted values, -help group, default, meaning.
    std::vector<Flag> f = {
        {"o", text("a file name"), &output, "<filename>.h5", "result file (HDF5; the XDMF file for ParaView is written beside it)"},
        {"output_fsync_interval", realIn(0, 1e9, false, true), &output, "10", "one process: seconds between commits of the result file that are forced to the disk (fsync; 0: every commit; several processes: every commit). A killed run never loses committed steps; a machine crash loses at most this interval"},
        {"restart", text("a result file"), &output, "none", "continue the run that wrote this result file from its last written step (same scene; docs/results.md, Restart)"},
        {"checkpoint", boolean(), &output, "true", "write /checkpoint (the restart state) with every written step; false: the run cannot be continued"},
        {"stop_after_step", integerAtLeast(0), &output, "0 (off)", "testing aid: stop as on SIGTERM once the result file holds this many step rows (exit 5)"},
        {"force_rtol", realIn(0, 1, true, true), &statics, "1e-11", "equilibrium tolerance: residual relative to the element forces (dynamics: default 1e-10)"},
        {"max_cuts", integerIn(0, 50), &statics, "10", "halvings of a failing load increment (dynamics: of a failing time step)"},
        {"predictor", boolean(), &statics, "true (false for beams under the mixed-stress Newton)", "secant predictor from the last converged increment"},
        {"newton_mixed_stresses", boolean(), &statics, "true", "beams, statics and dynamics: Newton with mixed stresses (stress part of the tangent from linearized stresses; docs/beam.md)"},
        {"newton_diverged_its", integerAtLeast(0), &statics, "6 for beams under the mixed-stress Newton, else 0", "an increment still above its start residual after this many Newton iterations is cut (0: never)"},
        {"continuation_rtol", realIn(0, 1, true, true), &statics, "1e-9", "path following: residual tolerance relative to |dR/dlambda| max(1, |lambda|) (docs/continuation.md)"},
        {"continuation_max_it", integerAtLeast(1), &statics, "15", "path following: corrector iterations before a step is cut"},
        {"continuation_desired_its", integerAtLeast(1), &statics, "5", "path following: corrector iterations the adaptive step aims at"},
        {"continuation_inertia", boolean(), &statics, "true", "path following: count the tangent's negative eigenvalues at every point (MUMPS LDL^T)"},
        {"continuation_initial_steps", integerAtLeast(1), &statics, "10", "path following: increments in which the initial loads (force_initial, displ_initial, ...) are applied before the path starts from their equilibrium"},
        {"branch_switch", boolean(), &statics, "false", "path following: at the first bifurcation, switch onto the bifurcated branch along the critical eigenvector (symmetric bifurcations; docs/continuation.md)"},
        {"continuation_lowest_eigenvalue", boolean(), &statics, "false", "path following: also the tangent's eigenvalue closest to 0 (lowest of 4, SLEPc shift-and-invert) per point, /path/lowest_eigenvalue"},
        {"adaptive_increments", boolean(), &statics, "true", "after a cut, grow the increment again when Newton converges quickly"},
        {"increment_grow_its", integerAtLeast(0), &statics, "5", "Newton iterations that count as quick (the next increment doubles)"},
        {"tangent_operator", oneOf({"auto", "elementwise", "assembled"}), &statics, "auto", "Newton systems: GMRES on the element-wise tangent preconditioned by LU, or the LU alone (auto: element-wise for ANCF cables)"},
        {"assembly_coo", boolean(), &statics, "true", "COO assembly of the Jacobian (false: MatSetValuesLocal)"},
        {"ancf_coarse_ratio", integerAtLeast(0), &ancf, "auto", "fine ANCF elements per coarse element of the two-level preconditioner (0: none; auto: ~2 sqrt(n) from 1024 elements per scene element)"},
        {"ancf_coarse_predictor", boolean(), &ancf, "true", "predict each increment by a nonlinear coarse solve (SNES prefix coarse_snes_)"},
        {"constraint_check", boolean(), &check, "true", "mechanism / redundant constraint check before solving"},
        {"constraint_check_max_unknowns", integerAtLeast(0), &check, "200000", "skip the check above this many unknowns"},
        {"constraint_check_tol", realIn(0, 1, true, true), &check, "1e-11", "null vectors: ||J v|| <= tol ||D v||"},
        {"constraint_check_vectors", integerAtLeast(1), &check, "3", "null vectors looked for and reported"},
        {"eigen_operator", oneOf({"auto", "elementwise", "assembled"}), &modal, "auto", "frequencies and buckling: K applied element by element (rigid-motion free) with GMRES + LU inner solves, or the assembled K and its LU alone (auto: element-wise where available)"},
        {"freq_shift_rel", realIn(0, 1, true, false), &modal, "1e-8", "shift-and-invert target -freq_shift_rel * min diag(K)/diag(M)"},
        {"eps_nev", integerAtLeast(1), &modal, "nfreq", "(SLEPc) frequencies computed; overrides opt.nfreq"},
        {"eps_target", anyReal(), &modal, "automatic", "(SLEPc) shift-and-invert target of the frequency analysis, replaces -freq_shift_rel"},
        {"buck_eps_nev", integerAtLeast(1), &modal, "automatic", "(SLEPc) buckling multipliers computed (default: grown until nbuck positive ones)"},
        {"compliance_method", oneOf({"selinv", "sparse", "dense"}), &compliance, "selinv", "how the compliance blocks of the inverse tangent are computed"},
        {"compliance_batch", integerAtLeast(1), &compliance, "96", "unit-load columns per solve (sparse, dense)"},
        {"compl_mat_mumps_icntl_27", anyInteger(), &compliance, "2048", "(MUMPS) right-hand-side columns per block of the compliance solve"},
        {"dynamics_scheme", oneOf({"arnold_bruls", "tsalpha2", "midpoint"}), &dynamics, "arnold_bruls", "Exudyn's generalized-alpha loop, PETSc TS alpha2, or the implicit midpoint rule (Lie group; linear and angular momentum exact, no numerical damping)"},
        {"dynamics_modified_newton", oneOf({"auto", "true", "false"}), &dynamics, "auto", "keep the factored Jacobian across Newton iterations and time steps while each iteration halves the residual (false: a new Jacobian at every iteration; auto: true from 200 unknowns)"},
        {"dynamics_corotated_jacobian", boolean(), &dynamics, "true", "ANCF cables under modified Newton: a kept Jacobian that stops contracting is first rebuilt from its element blocks rotated with the elements (no element kernel), a fresh one only if that does not help (docs/dynamics.md)"},
        {"dynamics_refine", oneOf({"auto", "true", "false"}), &dynamics, "auto", "ANCF cables under modified Newton: each Newton step's linear solve refined with the Newton matrix applied element by element (the smooth modes of fine cables to full accuracy: 2 Newton iterations per step at 65536 elements instead of 3.75; docs/dynamics.md); true: once; auto: one more refinement (up to 3) each time Newton's updates on one matrix contract by less than 1e-3"},
        {"dynamics_node_rotation", oneOf({"auto", "true", "false"}), &dynamics, "auto", "ANCF cables under modified Newton: the kept factored Newton matrix B preconditions as R B^-1 R^T, R turning each node's position and slope by the node's turn since B was built, and refined solves apply the kept element blocks turned to the iterate (fine cables keep a matrix for several steps instead of rebuilding it in every one: 65536 elements, 20 steps: 8 matrices against 18; docs/dynamics.md); auto: when the first kept matrix that stalls does so at an element turn below 2e-3 rad (fine cables; coarser ones rebuild cheaply)"},
        {"dynamics_chain_lu", oneOf({"auto", "cut", "redundant"}), &dynamics, "auto", "ANCF cables on several ranks: rank-local LU with an exact correction of the unknowns coupling the ranks (cut), or every rank factoring the whole chain (redundant); auto: cut when at most 64 unknowns couple the ranks"},
        {"mat_mumps_icntl_14", anyInteger(), &dynamics, "100 when dynamics factors with MUMPS, else MUMPS' own", "(MUMPS) percentage of extra workspace for pivoting; dynamics reserves 100 so wild Newton iterates do not fail the factorization (INFOG(1) = -9)"},
        {"dynamics_predictor", oneOf({"auto", "acceleration", "state"}), &dynamics, "auto", "Newton's start of a time step: q_n + h qd_n + h^2/2 a_n (acceleration) or q_n (state; the extrapolation of a fine mesh's unresolved stiff modes lands far off); auto: state from 200 unknowns and for beams"},
        {"dt_grow_after", integerAtLeast(0), &dynamics, "3", "after a halving, double the time step after this many successes (0: never)"},
        {"dynamics_adapt", oneOf({"none", "newton", "error"}), &dynamics, "opt.dynamics.adaptive.control (none)", "time-step control: fixed dt (none), from the Newton iteration count (newton) or a local error estimate (error); docs/dynamics.md"},
        {"dynamics_dt_min", realIn(0, 1e300, true, false), &dynamics, "opt.dynamics.adaptive.dt_min (dt/1e4)", "adaptive steps: smallest step"},
        {"dynamics_dt_max", realIn(0, 1e300, true, false), &dynamics, "opt.dynamics.adaptive.dt_max (dt * output_every)", "adaptive steps: largest step"},
        {"dynamics_adapt_its", integerAtLeast(1), &dynamics, "opt.dynamics.adaptive.target_iterations (4)", "adaptive steps (newton): Newton iterations per step aimed at"},
        {"dynamics_adapt_tol", realIn(0, 1e300, true, false), &dynamics, "opt.dynamics.adaptive.tolerance (1e-4)", "adaptive steps (error): local error estimate / largest displacement accepted per step"},
        {"beam_mass", oneOf({"consistent", "lumped"}), &dynamics, "consistent", "beam inertia: the consistent mass in the current element frame, or lumped on the nodes (rhoA l/2 and the section's rotary inertia with its exact gyroscopic moment: momentum-exact with -dynamics_scheme midpoint)"},
        {"dynamics_energy", boolean(), &dynamics, "false", "write /energy/{kinetic,strain,external_work,total} and /momentum/{linear,angular} per output step (beams, ANCF)"},
        {"ff_mat_mumps_icntl_7", integerIn(0, 7), &formfinding, "3", "(MUMPS) fill-reducing ordering of the form-finding factorization (3: SCOTCH)"},
    };
    // Every scene opt field is a flag of the same name (the scene reader checks its value).
    for (const OptionDoc& d : sceneOptionDocs()) {
      FlagValue v;
      v.kind = FlagValue::Kind::SceneOpt;
      v.sceneType = d.type;
      f.push_back({d.name, v, &scene, d.defaultValue, d.help});
    }
    return f;
  }();
  return flags;
}

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

/// An optional sign and digits only (PETSc's DEFAULT/DECIDE words are not Sinew values).
bool parseInteger(const std::string& s, double* v) {
  std::size_t i = (!s.empty() && (s[0] == '+' || s[0] == '-')) ? 1 : 0;
  if (i == s.size() || s.size() > 19) return false;
  for (std::size_t k = i; k < s.size(); ++k)
    if (!std::isdigit(static_cast<unsigned char>(s[k]))) return false;
  *v = std::strtod(s.c_str(), nullptr);
  return true;
}

bool parseReal(const std::string& s, double* v) {
  if (s.empty()) return false;
  char* end = nullptr;
  errno = 0;
  *v = std::strtod(s.c_str(), &end);
  return end && *end == '\0' && errno == 0 && std::isfinite(*v);
}

bool inRange(const FlagValue& r, double v) {
  return (r.loOpen ? v > r.lo : v >= r.lo) && (r.hiOpen ? v < r.hi : v <= r.hi);
}

}  // namespace

FlagValue integerIn(double lo, double hi) {
  FlagValue v;
  v.kind = FlagValue::Kind::Int;
  v.lo = lo;
  v.hi = hi;
  return v;
}
FlagValue integerAtLeast(double lo) { return integerIn(lo, INT_MAX); }
FlagValue anyInteger() { return integerIn(INT_MIN, INT_MAX); }
FlagValue realIn(double lo, double hi, bool loOpen, bool hiOpen) {
  FlagValue v;
  v.kind = FlagValue::Kind::Real;
  v.lo = lo;
  v.hi = hi;
  v.loOpen = loOpen;
  v.hiOpen = hiOpen;
  return v;
}
FlagValue anyReal() { return realIn(-HUGE_VAL, HUGE_VAL, true, true); }
FlagValue boolean() { return FlagValue{}; }
FlagValue oneOf(std::vector<std::string> choices) {
  FlagValue v;
  v.kind = FlagValue::Kind::Choice;
  v.choices = std::move(choices);
  return v;
}
FlagValue text(std::string what) {
  FlagValue v;
  v.kind = FlagValue::Kind::Text;
  v.what = std::move(what);
  return v;
}

const Flag* findFlag(const std::string& name) {
  const std::string n = lower(name);
  for (const Flag& f : sinewFlags())
    if (f.name == n) return &f;
  return nullptr;
}

std::string describeAccepted(const FlagValue& v) {
  using K = FlagValue::Kind;
  switch (v.kind) {
    case K::Int:
      if (v.lo <= INT_MIN && v.hi >= INT_MAX) return "an integer";
      if (v.hi >= INT_MAX) return "an integer >= " + number(v.lo);
      return "an integer in " + number(v.lo) + ".." + number(v.hi);
    case K::Real:
      if (std::isinf(v.lo) && std::isinf(v.hi)) return "a finite number";
      return std::string("a finite number in ") + (v.loOpen ? "(" : "[") + number(v.lo) + ", " + number(v.hi) +
             (v.hiOpen ? ")" : "]");
    case K::Bool:
      return "true or false (also yes/no, on/off, 1/0; the flag alone means true)";
    case K::Choice: {
      std::string s = "one of ";
      for (std::size_t i = 0; i < v.choices.size(); ++i) s += (i ? ", " : "") + v.choices[i];
      return s;
    }
    case K::Text:
      return v.what;
    case K::SceneOpt:
      return "a value (" + v.sceneType + ")";
  }
  return "";
}

std::string checkFlagValue(const Flag& flag, const char* value) {
  using K = FlagValue::Kind;
  const FlagValue& v = flag.value;
  const bool given = value && value[0];
  const std::string got = given ? std::string("got ") + value : (value ? "got an empty value" : "got no value");
  const std::string bad = "-" + flag.name + ": expected " + describeAccepted(v) + ", " + got;
  double x = 0;
  switch (v.kind) {
    case K::Int:
      return given && parseInteger(value, &x) && inRange(v, x) ? "" : bad;
    case K::Real:
      return given && parseReal(value, &x) && inRange(v, x) ? "" : bad;
    case K::Bool: {
      if (!given) return "";  // PETSc: a bool flag alone is true
      const std::string s = lower(value);
      for (const char* w : {"true", "false", "yes", "no", "on", "off", "1", "0"})
        if (s == w) return "";
      return bad;
    }
    case K::Choice:
      return given && std::find(v.choices.begin(), v.choices.end(), std::string(value)) != v.choices.end() ? "" : bad;
    case K::Text:
      return given ? "" : bad;
    case K::SceneOpt:
      // An empty value means true to the scene reader (-calcbuck alone): only bool fields may omit it.
      return given || v.sceneType.rfind("bool", 0) == 0 ? "" : bad;
  }
  return "";
}

}  // namespace sinew
