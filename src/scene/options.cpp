// opt (analysis options, SPACAR Light names plus Sinew's), formfinding (CARAT++ names) and
// sensors (Exudyn output variables), and the option table shown by -help.
#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "elements/element_kinds.hpp"
#include "scene/nearest_name.hpp"
#include "scene/scene_detail.hpp"
#include "scene/scene_reader.hpp"

namespace sinew {

const std::vector<OptionDoc>& sceneOptionDocs() {
  static const std::vector<OptionDoc> docs = {
      {"loadsteps", "integer 1..100000", "10", "number of load steps of the static analysis (more is an error)"},
      {"load_ramp", "spacar | uniform", "spacar",
       "how loads ramp over the load steps; spacar = SPACAR Light's (step 1 under the initial loads and prescribed motions alone, the "
       "standard loads ramp over the remaining steps, (k-1)/(loadsteps-1)); uniform = Sinew's former k/loadsteps"},
      {"calcbuck", "bool", "false", "compute buckling load multipliers at every load step"},
      {"calccompl", "bool", "true", "compute compliance matrices of the nodes"},
      {"calcfreq", "bool", "auto (true when the scene has mass)", "compute natural frequencies"},
      {"gravity", "[gx, gy, gz]", "none", "gravitational acceleration (m/s^2), e.g. -gravity 0,0,-9.81"},
      {"rls", "{element: [modes]}", "none", "released deformation modes (1..6) per beam element, e.g. -rls \"{3: [2,3]}\""},
      {"transfer", "bool or [bool, zeta]", "false", "compute the state-space model; with modal damping ratio zeta"},
      {"filename", "string", "scene file name", "base name of the result file (<filename>.h5)"},
      {"stressperelement", "bool", "false", "report the maximum stress per element"},
      {"rigidstress", "bool", "false", "also report stresses in rigid deformation modes"},
      {"showinputonly", "bool", "false", "read and check the scene, print it, and stop"},
      {"silent", "bool", "false", "no summary on stdout"},
      {"spavisual", "bool", "false", "SPACAR Light: open the seed's viewer after the run (Sinew: the XDMF file is always written; accepted)"},
      {"customvis", "string (file) or map", "none", "SPACAR Light: custom visualization (Sinew: accepted, not drawn)"},
      {"compliance_nodes", "[node numbers]", "all nodes", "nodes whose compliance matrices are computed"},
      {"dynamics", "{tend, dt, spectral_radius, output_every, mass_proportional_damping, stiffness_proportional_damping, "
                   "modal_damping, modal_damping_modes, adaptive, start}", "none",
       "time integration to tend with step dt; generalized-alpha; spectral_radius in [0,1] defaults to 0.9; "
       "output_every k writes every k-th step (default 1); damping C = alpha M0 + beta K0 (Rayleigh, "
       "mass_/stiffness_proportional_damping) + modal damping zeta (one value for the lowest modal_damping_modes = 10 "
       "modes of the start state, or a list, one per mode); adaptive: {control: none|newton|error, dt_min, dt_max, "
       "target_iterations, tolerance} varies the step (dt = first step, rows at multiples of dt * output_every); "
       "start: rest (default: from the unloaded or form-found state) or static (from the end of the static load "
       "steps, loads at t = 0)"},
      {"nfreq", "integer >= 1 or all", "6", "number of natural frequencies; all: every finite one, as SPACAR Light's out.freq (models up to 2000 unknowns)"},
      {"continuation", "{method, ds, max_steps, stop_load_factor, node, direction, stop_displacement, constraint, psi, ds_max}",
       "none",
       "path following instead of load steps; arclength (Crisfield, cylindrical or spherical) or displacement control "
       "of node/direction (x|y|z); the applied loads are the reference load; stops at max_steps (100), "
       "stop_load_factor or stop_displacement"},
      {"nbuck", "integer >= 1", "3", "number of buckling load multipliers"},
      {"output_steps", "all | last | every:k | [steps]", "all",
       "load / time steps written, with their step analyses; the last step always, "
       "e.g. -output_steps last, -output_steps every:10, -output_steps 1,50,100"},
      {"step_analyses", "all | last | every:k | none", "auto (all for load steps; last for form finding, path following, dynamics)",
       "written rows at which the step analyses (frequencies, buckling, compliance, state space) run: every row, the last "
       "row of each procedure, a row every k rows (the first and the last too), or none; calcfreq/calcbuck/calccompl/"
       "transfer choose which analyses. Their datasets hold one row per analysed row, /step_analysis_rows says which"},
      {"target_error", "number in (0, 0.1]", "none",
       "refine until the estimated relative error is at most this; the discretization error of every watched result "
       "quantity, estimated by Richardson extrapolation over levels of nbeams x 2 (beams, cables, ANCF cables; "
       "membranes split in four; with opt.dynamics dt / 2, the time histories); the "
       "finest level's results are written, /accuracy holds the levels and estimates (docs/accuracy.md)"},
      {"accuracy_quantities", "[freq | buck | stressmax | limit | bifurcation | shape | node <n> p|r|Freac|Mreac|CMglob]", "auto",
       "quantities -target_error watches; e.g. [freq, node 2 p]; auto: those the scene asks for (docs/accuracy.md)"},
      {"accuracy_refine", "time | space | both", "auto",
       "what the levels of -target_error refine (auto: time with opt.dynamics, else space): the time step (dt / 2 "
       "per level, the mesh as written), the elements "
       "(nbeams x 2 or membranes split, dt as written) or both at once (the time histories' order is then the lower of "
       "the two); time and both only with opt.dynamics (docs/accuracy.md)"},
  };
  return docs;
}

namespace scene {

std::vector<std::string> optionNames() {
  std::vector<std::string> names;
  for (const auto& d : sceneOptionDocs()) names.push_back(d.name);
  return names;
}

namespace {

/// Every load step writes a row of every result dataset; beyond this bound a typo (-loadsteps 1e9)
/// would fill the disk before anything useful happens.
constexpr int kMaxLoadsteps = 100000;

int loadsteps(const YAML::Node& v, const std::string& path, std::size_t numNodes) {
  const int n = getIntAtLeast(v, path, 1);
  if (n > kMaxLoadsteps) {
    const double bytes = 24.0 * static_cast<double>(numNodes) * n;  // /node/p alone: 3 doubles per node and step
    fail(path, "expected at most " + std::to_string(kMaxLoadsteps) + " load steps, got " + std::to_string(n) +
                   " (the node positions alone would take " + fmt(bytes / 1e9) + " GB of results for " +
                   std::to_string(numNodes) + " nodes)");
  }
  return n;
}

const std::vector<std::string> kFormfindingKeys = {
    "formfinding_step", "max_iter_equilibrium", "equilibrium_accuracy", "formfinding_elements", "homotopy_curve",
    "stress_adaption",  "lambda_max",           "mue_relax",            "x_urs",                "x_urs_step",
    "elastic_restart_method", "formfinding_tolerance", "max_shape_change", "distortion_max"};
const std::vector<std::string> kSensorKeys = {"element", "node", "x", "variable", "name", "xi"};
const std::vector<std::string> kSensorVariables = {
    "Position",      "Displacement",   "Velocity",  "VelocityLocal", "Rotation",        "Director1",          "StrainLocal",
    "CurvatureLocal", "ForceLocal",     "TorqueLocal", "AngularVelocity", "Acceleration", "AngularAcceleration"};

void parseRls(const YAML::Node& v, const std::string& path, SceneContext& ctx) {
  Model& m = ctx.model;
  if (!v.IsMap()) fail(path, "expected a map from element numbers to released modes ({3: [2, 3]}), got " + describe(v));
  for (auto it = v.begin(); it != v.end(); ++it) {
    const std::string p = numberedPath(path, keyString(it->first, path));
    const int e = checkedKeyIndex(it->first, p, "element", m.elements.size());
    if (m.opt.rls.count(e)) fail(p, "element " + std::to_string(e + 1) + " is given twice");
    const int set = m.elementSet[static_cast<std::size_t>(e)];
    const ElementSet* s = set >= 0 ? &m.eprops[static_cast<std::size_t>(set)] : nullptr;
    if (s && s->type() != ElementType::Beam)
      fail(p, "element " + std::to_string(e + 1) + " is a " + elementTypeName(s->type()) +
                  " (" + epropsName(set) + "); rls releases deformation modes of beam elements");
    const auto modes = getInts(it->second, p, true);
    std::vector<int> released;
    for (std::size_t i = 0; i < modes.size(); ++i) {
      const std::string pi = it->second.IsSequence() ? indexPath(p, i) : p;
      if (modes[i] < 1 || modes[i] > 6) fail(pi, "expected a deformation mode 1..6, got " + std::to_string(modes[i]));
      if (std::find(released.begin(), released.end(), modes[i]) != released.end())
        fail(pi, "mode " + std::to_string(modes[i]) + " is listed twice");
      if (s && s->get<BeamProperties>().flex[static_cast<std::size_t>(modes[i] - 1)])
        fail(pi, "mode " + std::to_string(modes[i]) + " of element " + std::to_string(e + 1) + " is flexible (" +
                     epropsName(set) + ".flex); a mode is either flexible or released");
      released.push_back(modes[i]);
    }
    m.opt.rls[e] = released;
  }
}

// Rayleigh (alpha M0 + beta K0) and modal (zeta per mode) damping of opt.dynamics (src/dynamics/damping.hpp)
void parseDamping(const YAML::Node& v, const std::string& path, DynamicsOptions& d) {
  auto nonNegative = [&](const char* key) {
    const std::string p = childPath(path, key);
    const double x = getNonNegative(v[key], p);
    if (!(x >= 0) || !std::isfinite(x)) fail(p, "expected a damping coefficient >= 0, got " + fmt(x));
    return x;
  };
  if (v["mass_proportional_damping"].IsDefined()) d.mass_proportional_damping = nonNegative("mass_proportional_damping");
  if (v["stiffness_proportional_damping"].IsDefined())
    d.stiffness_proportional_damping = nonNegative("stiffness_proportional_damping");
  const std::string pz = childPath(path, "modal_damping"), pn = childPath(path, "modal_damping_modes");
  if (v["modal_damping"].IsDefined()) {
    const YAML::Node& z = v["modal_damping"];
    if (z.IsSequence()) {
      if (z.size() == 0) fail(pz, "expected a damping ratio zeta or a list of one per mode, got an empty list");
      for (std::size_t i = 0; i < z.size(); ++i) d.modal_damping.push_back(getNonNegative(z[i], indexPath(pz, i)));
    } else {
      d.modal_damping.push_back(getNonNegative(z, pz));
    }
    for (std::size_t i = 0; i < d.modal_damping.size(); ++i)
      if (!(d.modal_damping[i] >= 0) || !std::isfinite(d.modal_damping[i]))
        fail(z.IsSequence() ? indexPath(pz, i) : pz, "expected a damping ratio zeta >= 0, got " + fmt(d.modal_damping[i]));
  }
  if (v["modal_damping_modes"].IsDefined()) {
    if (d.modal_damping.size() != 1)
      fail(pn, d.modal_damping.empty() ? "given without modal_damping (the ratio zeta)"
                                       : "modal_damping is a list (one zeta per mode): its length is the number of modes");
    d.modal_damping_modes = getIntAtLeast(v["modal_damping_modes"], pn, 1);
  }
}

void parseAdaptive(const YAML::Node& v, const std::string& path, AdaptiveStepOptions& a) {
  checkKeys(v, path, {"control", "dt_min", "dt_max", "target_iterations", "tolerance"});
  a.control = v["control"].IsDefined() ? getString(v["control"], childPath(path, "control")) : "error";
  if (a.control != "none" && a.control != "newton" && a.control != "error")
    fail(childPath(path, "control"), "expected none, newton or error, got '" + a.control + "'");
  if (v["dt_min"].IsDefined()) a.dt_min = getPositive(v["dt_min"], childPath(path, "dt_min"), kTime);
  if (v["dt_max"].IsDefined()) a.dt_max = getPositive(v["dt_max"], childPath(path, "dt_max"), kTime);
  if (a.dt_min > 0 && a.dt_max > 0 && a.dt_min > a.dt_max)
    fail(childPath(path, "dt_min"), "expected dt_min <= dt_max (" + fmt(a.dt_max) + "), got " + fmt(a.dt_min));
  if (v["target_iterations"].IsDefined())
    a.target_iterations = getIntAtLeast(v["target_iterations"], childPath(path, "target_iterations"), 1);
  if (v["tolerance"].IsDefined()) a.tolerance = getPositive(v["tolerance"], childPath(path, "tolerance"));
}

void parseDynamics(const YAML::Node& v, const std::string& path, Options& opt) {
  checkKeys(v, path, {"tend", "dt", "spectral_radius", "output_every", "mass_proportional_damping",
                      "stiffness_proportional_damping", "modal_damping", "modal_damping_modes", "adaptive",
                      "start"});
  DynamicsOptions d;
  if (!v["tend"].IsDefined()) fail(childPath(path, "tend"), "missing: dynamics needs tend (end time) > 0");
  d.tend = getPositive(v["tend"], childPath(path, "tend"), kTime);
  if (!v["dt"].IsDefined()) fail(childPath(path, "dt"), "missing: dynamics needs dt (time step) > 0");
  d.dt = getPositive(v["dt"], childPath(path, "dt"), kTime);
  if (d.dt > d.tend) fail(childPath(path, "dt"), "expected dt <= tend (" + fmt(d.tend) + "), got " + fmt(d.dt));
  if (d.tend / d.dt > kMaxTimeSteps)
    fail(childPath(path, "dt"), "tend / dt = " + fmt(d.tend / d.dt) + " time steps; Sinew takes at most " + fmt(kMaxTimeSteps));
  if (v["spectral_radius"].IsDefined()) d.spectral_radius = getInRange(v["spectral_radius"], childPath(path, "spectral_radius"), 0.0, 1.0);
  if (v["output_every"].IsDefined()) d.output_every = getIntAtLeast(v["output_every"], childPath(path, "output_every"), 1);
  parseDamping(v, path, d);
  if (v["adaptive"].IsDefined()) parseAdaptive(v["adaptive"], childPath(path, "adaptive"), d.adaptive);
  if (v["start"].IsDefined()) d.start_static = getChoice(v["start"], childPath(path, "start"), {"rest", "static"}) == "static";
  opt.dynamics = d;
}

void parseContinuation(const YAML::Node& v, const std::string& path, SceneContext& ctx) {
  Options& opt = ctx.model.opt;
  checkKeys(v, path, {"method", "ds", "max_steps", "stop_load_factor", "node", "direction", "stop_displacement",
                      "constraint", "psi", "ds_max"});
  ContinuationOptions c;
  if (v["method"].IsDefined()) {
    c.method = getString(v["method"], childPath(path, "method"));
    if (c.method != "arclength" && c.method != "displacement")
      fail(childPath(path, "method"), "expected arclength or displacement, got '" + c.method + "'");
  }
  if (v["constraint"].IsDefined()) {
    c.constraint = getString(v["constraint"], childPath(path, "constraint"));
    if (c.constraint != "cylindrical" && c.constraint != "spherical")
      fail(childPath(path, "constraint"), "expected cylindrical or spherical, got '" + c.constraint + "'");
  }
  if (v["psi"].IsDefined()) c.psi = getPositive(v["psi"], childPath(path, "psi"));
  if (!v["ds"].IsDefined()) fail(childPath(path, "ds"), "missing: continuation needs ds (arc length or displacement increment)");
  c.ds = getNumber(v["ds"], childPath(path, "ds"));
  if (!(std::abs(c.ds) > 0.0) || !std::isfinite(c.ds)) fail(childPath(path, "ds"), "expected a nonzero number, got " + fmt(c.ds));
  if (c.method == "arclength" && c.ds < 0) fail(childPath(path, "ds"), "an arc length is positive, got " + fmt(c.ds));
  c.ds_max = v["ds_max"].IsDefined() ? getPositive(v["ds_max"], childPath(path, "ds_max")) : 0.0;  // 0: the analysis's default
  if (v["max_steps"].IsDefined()) {
    // every path point is a result row, and the checkpoint keeps 17 values per possible point
    c.max_steps = getIntAtLeast(v["max_steps"], childPath(path, "max_steps"), 1);
    if (c.max_steps > kMaxLoadsteps)
      fail(childPath(path, "max_steps"), "expected at most " + std::to_string(kMaxLoadsteps) + " path points (as many as load steps), got " +
                                             std::to_string(c.max_steps));
  }
  if (v["stop_load_factor"].IsDefined()) c.stop_load_factor = getNumber(v["stop_load_factor"], childPath(path, "stop_load_factor"));
  if (v["node"].IsDefined())
    c.node = checkedIndex(v["node"], childPath(path, "node"), "node", ctx.model.nodes.size());
  if (v["direction"].IsDefined()) {
    const std::string d = getString(v["direction"], childPath(path, "direction"));
    if (d != "x" && d != "y" && d != "z") fail(childPath(path, "direction"), "expected x, y or z, got '" + d + "'");
    c.direction = d[0] - 'x';
  }
  if (v["stop_displacement"].IsDefined()) c.stop_displacement = getNumber(v["stop_displacement"], childPath(path, "stop_displacement"));
  if ((c.method == "displacement" || c.stop_displacement) && c.node < 0)
    fail(childPath(path, "node"), "missing: displacement control and stop_displacement need the control node");
  opt.continuation = c;
}

}  // namespace

namespace {

/// "every:k" -> k; 0 when what follows "every:" is not an integer >= 1; -1 when s is not "every:...".
int everyCount(const std::string& s) {
  if (s.rfind("every:", 0) != 0) return -1;
  const std::string k = s.substr(6);
  std::size_t used = 0;
  int every = 0;
  try {
    every = std::stoi(k, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  return used == 0 || used != k.size() || every < 1 ? 0 : every;
}

OutputSteps parseOutputSteps(const YAML::Node& v, const std::string& p) {
  OutputSteps out;
  const std::string expected = "expected all, last, every:k or a list of step numbers, got ";
  if (v.IsSequence()) {
    out.kind = OutputSteps::Kind::List;
    for (std::size_t i = 0; i < v.size(); ++i) out.steps.push_back(getIntAtLeast(v[i], indexPath(p, i), 0));
    return out;
  }
  if (!v.IsScalar()) fail(p, expected + describe(v));
  const std::string s = v.Scalar();
  if (s == "all") return out;
  if (s == "last") {
    out.kind = OutputSteps::Kind::Last;
    return out;
  }
  if (const int every = everyCount(s); every >= 0) {
    if (every == 0) fail(p, "every:k needs an integer k >= 1, got " + describe(v));
    out.kind = OutputSteps::Kind::Every;
    out.every = every;
    return out;
  }
  if (isNumber(v)) {  // a single step number
    out.kind = OutputSteps::Kind::List;
    out.steps.push_back(getIntAtLeast(v, p, 0));
    return out;
  }
  fail(p, expected + describe(v));
}

StepAnalysisRows parseStepAnalyses(const YAML::Node& v, const std::string& p) {
  const std::string expected = "expected all, last, every:k (k >= 1) or none, got ";
  if (!v.IsScalar()) fail(p, expected + describe(v));
  const std::string s = v.Scalar();
  StepAnalysisRows out;
  if (s == "all") return out;
  if (s == "last" || s == "none") {
    out.kind = s == "last" ? StepAnalysisRows::Kind::Last : StepAnalysisRows::Kind::None;
    return out;
  }
  if (const int every = everyCount(s); every >= 0) {
    if (every == 0) fail(p, expected + describe(v));
    out.kind = StepAnalysisRows::Kind::Every;
    out.every = every;
    return out;
  }
  fail(p, expected + describe(v));
}

/// opt.accuracy_quantities: "freq", "buck", "stressmax", "limit", "bifurcation", "shape", "node <n> <p|r|Freac|Mreac|CMglob>".
std::vector<std::string> parseAccuracyQuantities(const YAML::Node& v, const std::string& path, std::size_t numNodes) {
  if (!v.IsSequence() && !v.IsScalar()) fail(path, "expected a list of quantities ([freq, node 2 p]), got " + describe(v));
  static const std::vector<std::string> kWhole = {"freq", "buck", "stressmax", "limit", "bifurcation", "shape"};
  static const std::vector<std::string> kNodeFields = {"p", "r", "Freac", "Mreac", "CMglob"};
  std::vector<std::string> out;
  for (std::size_t i = 0; i < (v.IsSequence() ? v.size() : 1); ++i) {
    const std::string pi = v.IsSequence() ? indexPath(path, i) : path;
    const std::string q = getString(v.IsSequence() ? v[i] : v, pi);
    std::istringstream words(q);
    std::string first, node, field, extra;
    words >> first >> node >> field >> extra;
    if (first == "node") {
      char* end = nullptr;
      const long n = std::strtol(node.c_str(), &end, 10);
      if (node.empty() || *end != '\0' || n < 1 || static_cast<std::size_t>(n) > numNodes)
        fail(pi, "expected a node number 1.." + std::to_string(numNodes) + " after 'node', got '" + q + "'");
      if (std::find(kNodeFields.begin(), kNodeFields.end(), field) == kNodeFields.end() || !extra.empty())
        fail(pi, "expected 'node " + node + " <p|r|Freac|Mreac|CMglob>', got '" + q + "'");
    } else if (std::find(kWhole.begin(), kWhole.end(), q) == kWhole.end()) {
      fail(pi, "expected freq, buck, stressmax, limit, bifurcation, shape or 'node <n> <p|r|Freac|Mreac|CMglob>', got '" + q + "'");
    }
    out.push_back(q);
  }
  return out;
}

}  // namespace

void parseOptions(const YAML::Node& opt, SceneContext& ctx) {
  Model& m = ctx.model;
  Options& o = m.opt;
  if (!opt.IsDefined() || opt.IsNull()) return;
  checkKeys(opt, "opt", optionNames());
  for (auto it = opt.begin(); it != opt.end(); ++it) {
    const std::string k = it->first.Scalar();
    const YAML::Node v = it->second;
    const std::string p = childPath("opt", k);
    if (k == "loadsteps") o.loadsteps = loadsteps(v, p, m.nodes.size());
    else if (k == "load_ramp") o.load_ramp = getChoice(v, p, {"spacar", "uniform"});
    else if (k == "calcbuck") o.calcbuck = getBool(v, p);
    else if (k == "calccompl") o.calccompl = getBool(v, p);
    else if (k == "calcfreq") o.calcfreq = getBool(v, p);
    else if (k == "gravity") o.gravity = getVec3(v, p, m.dimension == 2, kLoad);
    else if (k == "rls") parseRls(v, p, ctx);
    else if (k == "transfer") {
      if (v.IsSequence()) {
        if (v.size() != 2) fail(p, "expected true, false or [true, zeta], got a list of " + std::to_string(v.size()));
        o.transfer = getBool(v[0], indexPath(p, 0));
        o.transfer_zeta = getNonNegative(v[1], indexPath(p, 1), kRatio);
      } else if (v.IsScalar()) {
        if (isNumber(v) && v.Scalar() != "0" && v.Scalar() != "1")
          fail(p, "expected true, false or [true, zeta], got " + describe(v));
        o.transfer = getBool(v, p);
      } else {
        fail(p, "expected true, false or [true, zeta], got " + describe(v));
      }
    } else if (k == "filename") {
      o.filename = getString(v, p);
      if (o.filename.empty()) fail(p, "expected a file name, got an empty string");
    } else if (k == "stressperelement") o.stressperelement = getBool(v, p);
    else if (k == "rigidstress") o.rigidstress = getBool(v, p);
    else if (k == "showinputonly") o.showinputonly = getBool(v, p);
    else if (k == "silent") o.silent = getBool(v, p);
    else if (k == "spavisual") o.spavisual = getBool(v, p);
    else if (k == "customvis") o.customvis = true;
    else if (k == "compliance_nodes") {
      if (!v.IsSequence() && !v.IsScalar()) fail(p, "expected a list of node numbers, got " + describe(v));
      std::set<int> seen;
      for (std::size_t i = 0; i < (v.IsSequence() ? v.size() : 1); ++i) {
        const std::string pi = v.IsSequence() ? indexPath(p, i) : p;
        const int n = checkedIndex(v.IsSequence() ? v[i] : v, pi, "node", m.nodes.size());
        if (!seen.insert(n).second) fail(pi, "node " + std::to_string(n + 1) + " is listed twice");
        o.compliance_nodes.push_back(n);
      }
    } else if (k == "dynamics") parseDynamics(v, p, o);
    else if (k == "continuation") parseContinuation(v, p, ctx);
    else if (k == "nfreq") o.nfreq = v.IsScalar() && v.Scalar() == "all" ? Options::kAllFrequencies : getIntAtLeast(v, p, 1);
    else if (k == "nbuck") o.nbuck = getIntAtLeast(v, p, 1);
    else if (k == "output_steps") o.output_steps = parseOutputSteps(v, p);
    else if (k == "step_analyses") o.step_analyses = parseStepAnalyses(v, p);
    else if (k == "target_error") {
      o.target_error = getInRange(v, p, 0.0, 0.1);
      if (o.target_error <= 0) fail(p, "expected a relative error in (0, 0.1], got " + describe(v));
    } else if (k == "accuracy_quantities") o.accuracy_quantities = parseAccuracyQuantities(v, p, m.nodes.size());
    else if (k == "accuracy_refine") o.accuracy_refine = getChoice(v, p, {"time", "space", "both"});
  }
  // path following writes every path point (output_steps does not thin a path)
  // (a restart's list is checked against the restart's plan, once its checkpoint is read)
  if (o.output_steps.kind == OutputSteps::Kind::List && !o.continuation && !ctx.restart) checkOutputSteps(o, o.loadsteps);
  if (opt["loadsteps"].IsDefined() && o.dynamics && !o.dynamics->start_static)
    m.warnings.push_back("opt.loadsteps is not used: opt.dynamics starts at rest from the unloaded (or form-found) state; "
                         "give opt.dynamics.start: static to run the load steps first and start the time loop from their end");
}

void parseFormfinding(const YAML::Node& ff, SceneContext& ctx) {
  Model& m = ctx.model;
  FormFinding f;
  if (ff.IsNull()) {
    m.formfinding = f;
    return;
  }
  checkKeys(ff, "formfinding", kFormfindingKeys);
  auto p = [](const char* k) { return childPath("formfinding", k); };
  auto sets = [&](const char* k) {
    std::vector<int> out;
    const YAML::Node v = ff[k];
    if (!v.IsSequence() && !v.IsScalar()) fail(p(k), "expected a list of eprops set numbers (1-based), got " + describe(v));
    for (std::size_t i = 0; i < (v.IsSequence() ? v.size() : 1); ++i) {
      const std::string pi = v.IsSequence() ? indexPath(p(k), i) : p(k);
      const int s = checkedIndex(v.IsSequence() ? v[i] : v, pi, "eprops set", m.eprops.size());
      if (std::find(out.begin(), out.end(), s) != out.end()) fail(pi, epropsName(s) + " is listed twice");
      out.push_back(s);
    }
    return out;
  };
  if (ff["formfinding_step"].IsDefined()) f.formfinding_step = getIntAtLeast(ff["formfinding_step"], p("formfinding_step"), 1);
  if (ff["max_iter_equilibrium"].IsDefined())
    f.max_iter_equilibrium = getIntAtLeast(ff["max_iter_equilibrium"], p("max_iter_equilibrium"), 1);
  if (ff["equilibrium_accuracy"].IsDefined()) f.equilibrium_accuracy = getPositive(ff["equilibrium_accuracy"], p("equilibrium_accuracy"), kRatio);
  if (ff["formfinding_elements"].IsDefined()) f.formfinding_elements = sets("formfinding_elements");
  if (const YAML::Node v = ff["homotopy_curve"]; v.IsDefined()) {
    if (!v.IsSequence()) fail(p("homotopy_curve"), "expected a list of numbers in [0, 1] (one per step), got " + describe(v));
    for (std::size_t i = 0; i < v.size(); ++i) f.homotopy_curve.push_back(getInRange(v[i], indexPath(p("homotopy_curve"), i), 0.0, 1.0));
  }
  if (ff["stress_adaption"].IsDefined()) f.stress_adaption = sets("stress_adaption");
  if (ff["lambda_max"].IsDefined()) f.lambda_max = getPositive(ff["lambda_max"], p("lambda_max"), kRatio);
  if (ff["mue_relax"].IsDefined()) f.mue_relax = getInRange(ff["mue_relax"], p("mue_relax"), 0.0, 1.0, false);
  if (ff["distortion_max"].IsDefined()) f.distortion_max = getNonNegative(ff["distortion_max"], p("distortion_max"), kRatio);
  if (ff["x_urs"].IsDefined()) f.x_urs = getBool(ff["x_urs"], p("x_urs"));
  if (ff["x_urs_step"].IsDefined()) f.x_urs_step = getIntAtLeast(ff["x_urs_step"], p("x_urs_step"), 1);
  if (ff["elastic_restart_method"].IsDefined())
    f.elastic_restart_method = getChoice(ff["elastic_restart_method"], p("elastic_restart_method"), {"NONE", "FORCE", "DISPLACEMENT"});
  if (ff["formfinding_tolerance"].IsDefined())
    f.formfinding_tolerance = getNonNegative(ff["formfinding_tolerance"], p("formfinding_tolerance"), kRatio);
  if (ff["max_shape_change"].IsDefined()) f.max_shape_change = getPositive(ff["max_shape_change"], p("max_shape_change"), kRatio);
  for (int s : f.formfinding_elements)
    if (!elementKind(m.eprops[static_cast<std::size_t>(s)].type()).formFindable)
      fail(p("formfinding_elements"), epropsName(s) + " is not a cable or membrane set (only those can be form-found)");
  for (int s : f.stress_adaption)
    if (std::find(f.formfinding_elements.begin(), f.formfinding_elements.end(), s) == f.formfinding_elements.end() &&
        !f.formfinding_elements.empty())
      fail(p("stress_adaption"), epropsName(s) + " is not in formfinding_elements");
  // stress adaption that cannot act (issue 10 item 16): N0 <- (1 - mue_relax) s N0 + mue_relax N0 with
  // s = stretch / clamp(stretch, 1/lambda_max, lambda_max) (docs/formfinding.md)
  if (f.lambda_max < 1.0)
    fail(p("lambda_max"), "expected a stretch bound >= 1 (1 only with distortion_max > 1), got " + fmt(f.lambda_max));
  if (!f.stress_adaption.empty()) {
    if (f.lambda_max <= 1.0 && !(f.distortion_max > 1.0))
      fail(p("lambda_max"), "expected a stretch bound > 1 for stress_adaption, got " + fmt(f.lambda_max) +
                                " (lambda_max <= 1 adapts nothing; lambda_max: 1 is meant to go with distortion_max > 1)");
    // CARAT++ accepts mue_relax in [0, 1]; 1 keeps the prestress unchanged (no adaption): run, and say so
    if (f.mue_relax >= 1.0 && f.lambda_max > 1.0 && !(f.distortion_max > 1.0))
      m.warnings.push_back(p("mue_relax") + " = 1 keeps the prestress unchanged: stress_adaption adapts nothing (CARAT++ "
                           "allows it; give mue_relax < 1 to adapt the prestress, 0 to adapt it fully)");
  }
  m.formfinding = f;
}

void parseSensors(const YAML::Node& sensors, SceneContext& ctx) {
  Model& m = ctx.model;
  if (!sensors.IsDefined() || sensors.IsNull()) return;
  if (!sensors.IsSequence())
    fail("sensors", "expected a list of sensors ({element, x, variable, name}), got " + describe(sensors));
  for (std::size_t i = 0; i < sensors.size(); ++i) {
    const std::string path = indexPath("sensors", i);
    const YAML::Node n = sensors[i];
    checkKeys(n, path, kSensorKeys);
    Sensor s;
    if (n["node"].IsDefined()) {
      // node sensor (Exudyn's SensorNode): a beam node's position, displacement, rotation and rates
      if (n["element"].IsDefined() || n["x"].IsDefined() || n["xi"].IsDefined())
        fail(childPath(path, "node"), "a sensor samples either a node (node) or a position along an element (element, xi or x)");
      s.node = checkedIndex(n["node"], childPath(path, "node"), "node", m.nodes.size());
      static const std::vector<std::string> nodeVariables = {"Position", "Displacement", "Velocity", "Acceleration",
                                                             "Rotation", "AngularVelocity", "AngularAcceleration"};
      if (!n["variable"].IsDefined()) fail(childPath(path, "variable"), "missing: a sensor needs a variable (e.g. Position)");
      s.variable = getChoice(n["variable"], childPath(path, "variable"), nodeVariables);
    } else if (!n["element"].IsDefined()) {
      fail(childPath(path, "element"), "missing: a sensor needs the element it samples (or a node)");
    }
    if (s.node < 0) {
      s.element = checkedIndex(n["element"], childPath(path, "element"), "element", m.elements.size());
      if (m.elements[static_cast<std::size_t>(s.element)].size() != 2)
        fail(childPath(path, "element"), "sensors sample along 2-node elements; element " + std::to_string(s.element + 1) + " has " +
                                             std::to_string(m.elements[static_cast<std::size_t>(s.element)].size()) + " nodes");
      if (n["x"].IsDefined()) {
        const double L = elementLength(m, s.element);
        s.x = getNumber(n["x"], childPath(path, "x"), kCoordinate);
        if (s.x < -1e-12 * L || s.x > L * (1 + 1e-12))
          fail(childPath(path, "x"), "expected a position in [0, " + fmt(L) + "] along element " + std::to_string(s.element + 1) +
                                         " (its length), got " + fmt(s.x));
        s.x = std::clamp(s.x, 0.0, L);
        s.xi = s.x / L;
      }
      if (n["xi"].IsDefined()) {
        // position as a fraction of the element (Exudyn's localPosition divided by the length)
        if (n["x"].IsDefined()) fail(childPath(path, "xi"), "give the position either as x (length) or as xi (fraction), not both");
        s.xi = getNumber(n["xi"], childPath(path, "xi"));
        if (!(s.xi >= 0.0 && s.xi <= 1.0))
          fail(childPath(path, "xi"), "expected a fraction in [0, 1] along element " + std::to_string(s.element + 1) +
                                          " (0 at its first node, 1 at its second), got " + fmt(s.xi));
        s.x = s.xi * elementLength(m, s.element);
      }
      if (!n["variable"].IsDefined()) fail(childPath(path, "variable"), "missing: a sensor needs a variable (e.g. Position)");
      s.variable = getChoice(n["variable"], childPath(path, "variable"), kSensorVariables);
    }
    if (!n["name"].IsDefined()) fail(childPath(path, "name"), "missing: a sensor needs a name (its dataset /sensors/<name>)");
    s.name = getString(n["name"], childPath(path, "name"));
    if (s.name.empty() || s.name.find('/') != std::string::npos || s.name == "." )
      fail(childPath(path, "name"), "expected a name without '/', got '" + s.name + "'");
    for (std::size_t j = 0; j < m.sensors.size(); ++j)
      if (m.sensors[j].name == s.name)
        fail(childPath(path, "name"), "sensor name '" + s.name + "' is already used by " + indexPath("sensors", j));
    m.sensors.push_back(s);
  }
}

}  // namespace scene

// The step numbers of a list must be steps the run has: load steps 1..lastLoadStep (statics, also
// before a time loop with start: static) or written time steps 0..tend/dt (multiples of
// output_every); a step the run never reaches wrote nothing but the last step before (issue 24).
void checkOutputSteps(const Options& o, int lastLoadStep) {
  const std::string p = "opt.output_steps";
  const bool statics = !o.dynamics || o.dynamics->start_static;
  long nsteps = 0, every = 1;
  if (o.dynamics) {
    nsteps = std::max(1L, static_cast<long>(std::ceil(o.dynamics->tend / o.dynamics->dt - 1e-9)));
    every = o.dynamics->output_every;
  }
  std::string range;
  if (statics) range = "load steps 1.." + std::to_string(lastLoadStep);
  if (o.dynamics)
    range += (range.empty() ? "" : " or ") + std::string("time steps 0..") + std::to_string(nsteps) +
             (every > 1 ? " that are multiples of output_every " + std::to_string(every) : "");
  for (const int k : o.output_steps.steps) {
    const bool loadStep = statics && k >= 1 && k <= lastLoadStep;
    const bool timeStep = o.dynamics && k >= 0 && k <= nsteps && k % every == 0;
    if (!loadStep && !timeStep)
      throw SceneError(p, "step " + std::to_string(k) + " is not a step of this run: expected " + range +
                              " (the last step is always written)");
  }
}

}  // namespace sinew
