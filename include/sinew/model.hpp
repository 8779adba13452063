// The scene as plain, validated data (design.md section 2). Node and element numbers are
// stored 0-based here; the scene file and every message use SPACAR Light's 1-based numbers.
#pragma once
#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "sinew/element_properties.hpp"
#include "sinew/linalg3.hpp"

namespace sinew {

/// A scene error: `path` is the field path (e.g. "eprops[2].dim"), `what()` the full message.
class SceneError : public std::runtime_error {
 public:
  SceneError(const std::string& path, const std::string& message)
      : std::runtime_error(path.empty() ? message : path + ": " + message), path_(path) {}
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

struct NodeProps {
  bool fix = false, fix_pos = false, fix_orien = false, fix_x = false, fix_y = false, fix_z = false;
  std::optional<std::array<int, 4>> fix_coords;  ///< ANCF: x, y, slope_x, slope_y (1 = fixed)
  std::optional<std::array<double, 2>> slope;    ///< ANCF reference slope (nonzero; default: averaged chords)
  double mass = 0.0;
  std::array<double, 6> mominertia{};  ///< Ixx Ixy Ixz Iyy Iyz Izz (global frame, at the node)
  Vec3 force{}, force_initial{}, moment{}, moment_initial{};
  std::array<std::optional<double>, 3> displ{}, displ_initial{};  ///< prescribed x/y/z displacement
  std::optional<Vec3> rot, rot_initial;                          ///< prescribed rotation (axis * angle)
  /// Sinew: components given as functions of time (expression strings of t, docs/scene.md "Loads and
  /// motions as functions of time"); "" = the number above. The numbers hold the functions' values at
  /// t = 0, which is what statics applies (ramped by the load factor); dynamics evaluates them at t.
  std::array<std::string, 3> force_t, moment_t, displ_t;
  std::string rot_t;  ///< rot: [angle(t), axis_x, axis_y, axis_z]; the axis (unit) is rot_axis
  Vec3 rot_axis{};
  bool hasTimeFunctions() const {
    for (int k = 0; k < 3; ++k)
      if (!force_t[k].empty() || !moment_t[k].empty() || !displ_t[k].empty()) return true;
    return !rot_t.empty();
  }
  std::vector<std::string> transfer_in;   ///< force_x force_y force_z (moment_x ...)
  std::vector<std::string> transfer_out;  ///< displ_x ... veloc_x ...
};

/// The element kind of an eprops set (`type`); the order of ElementSet::Properties.
enum class ElementType { Beam, Cable, Membrane, AncfCable2D };
/// The scene's name of an element type (eprops type).
inline const char* elementTypeName(ElementType t) {
  switch (t) {
    case ElementType::Beam: return "beam";
    case ElementType::Cable: return "cable";
    case ElementType::Membrane: return "membrane";
    case ElementType::AncfCable2D: return "ancf_cable2d";
  }
  return "beam";
}

/// Scene field paths number list entries from 1, as SPACAR Light (MATLAB) does: `eprops(2).emod`,
/// `dim(1)`; an index into an indexed path is a matrix entry: `nodes(3,2)`, `elements(2,1)`. index0 is
/// the 0-based position.
inline std::string indexedPath(const std::string& path, std::size_t index0) {
  const std::string n = std::to_string(index0 + 1);
  if (!path.empty() && path.back() == ')') return path.substr(0, path.size() - 1) + "," + n + ")";
  return path + "(" + n + ")";
}
/// `eprops(set + 1)`: the name of eprops set `set` (0-based) in messages and field paths.
inline std::string epropsName(int set) { return indexedPath("eprops", static_cast<std::size_t>(set)); }
/// `nprops(node + 1).field`: the path of a field of node `node` (0-based).
inline std::string npropsPath(int node, const std::string& field) {
  return indexedPath("nprops", static_cast<std::size_t>(node)) + "." + field;
}

/// An eprops set: the fields every kind has, and the properties of its kind (element_properties.hpp).
struct ElementSet {
  using Properties = std::variant<BeamProperties, CableProperties, MembraneProperties, AncfCable2DProperties>;
  std::vector<int> elems;  ///< 0-based scene element numbers
  int nbeams = 1;          ///< FE elements per scene element (beams, ANCF cables)
  // look (SPACAR Light)
  std::optional<std::array<double, 3>> color;
  double opacity = 1.0;
  bool hide = false;
  Properties props;  ///< the kind's properties (default: a beam)

  ElementType type() const { return static_cast<ElementType>(props.index()); }
  /// The properties of kind P, nullptr when the set is of another kind.
  template <class P> const P* as() const { return std::get_if<P>(&props); }
  template <class P> P* as() { return std::get_if<P>(&props); }
  /// The properties of kind P (throws std::bad_variant_access for another kind).
  template <class P> const P& get() const { return std::get<P>(props); }
  template <class P> P& get() { return std::get<P>(props); }
};

/// Sinew: opt.dynamics.adaptive, optional time-step control (docs/dynamics.md "Time-step control").
struct AdaptiveStepOptions {
  std::string control = "none";  ///< none (fixed dt) | newton (Newton iteration count) | error (local error estimate)
  double dt_min = 0;             ///< smallest step (0: dt / 1e4)
  double dt_max = 0;             ///< largest step (0: the output interval dt * output_every)
  int target_iterations = 4;     ///< newton: iterations per step the step size aims at
  double tolerance = 1e-4;       ///< error: local error / largest displacement (inf-norms) accepted per step
};

struct DynamicsOptions {
  double tend = 0, dt = 0, spectral_radius = 0.9;
  AdaptiveStepOptions adaptive;  ///< Sinew: off by default
  int output_every = 1;  ///< Sinew: write every k-th time step (and the last)
  // damping (docs/dynamics.md "Damping"; Exudyn's massProportionalDamping/stiffnessProportionalDamping)
  double mass_proportional_damping = 0;       ///< Rayleigh alpha (1/s): C += alpha M0
  double stiffness_proportional_damping = 0;  ///< Rayleigh beta (s): C += beta K0 (tangent of the start state)
  std::vector<double> modal_damping;          ///< zeta: one value for the lowest modal_damping_modes modes, or one per mode
  int modal_damping_modes = 10;               ///< modes a scalar modal_damping applies to
  /// Sinew: where the time loop starts (docs/dynamics.md "Starting from a loaded state"): false
  /// (`start: rest`, default) the unloaded or form-found state at rest; true (`start: static`) the
  /// end of the static load steps (opt.loadsteps, loads at t = 0), at rest
  bool start_static = false;
};

/// Sinew: opt.output_steps, the load / time steps at which results are written and the step
/// analyses (frequencies, buckling, compliance, stress, sensors) run. The last step is always written.
struct OutputSteps {
  enum class Kind { All, Last, Every, List } kind = Kind::All;
  int every = 1;           ///< Kind::Every: steps k with k % every == 0
  std::vector<int> steps;  ///< Kind::List: step numbers (load steps from 1, time step 0 = initial state)
  bool selects(int step, bool last) const {
    switch (kind) {
      case Kind::All: return true;
      case Kind::Last: return last;
      case Kind::Every: return last || step % every == 0;
      default: return last || std::find(steps.begin(), steps.end(), step) != steps.end();
    }
  }
};

/// Sinew: opt.step_analyses, the written rows at which the step analyses (frequencies, buckling,
/// compliance, state space) run; which analyses run is decided by calcfreq, calcbuck, calccompl,
/// transfer. Unset: every row of load-stepped statics (SPACAR Light's out.freq / CMglob per load
/// step), the last row of form finding, path following and dynamics.
struct StepAnalysisRows {
  enum class Kind { All, Last, Every, None } kind = Kind::All;
  int every = 1;  ///< Kind::Every: a row once `every` rows have passed since the last analysed row (the first row of a run has them)
  bool operator==(const StepAnalysisRows&) const = default;
};

/// Path following (opt.continuation) instead of load stepping; the applied loads are the reference load.
struct ContinuationOptions {
  std::string method = "arclength";       ///< arclength | displacement
  std::string constraint = "cylindrical"; ///< arclength: cylindrical | spherical
  double psi = 1.0;                       ///< spherical: scale of the load term (psi^2 |q|^2 dlambda^2)
  double ds = 0.0;                        ///< arc length (arclength) or displacement increment (displacement)
  double ds_max = 0.0;                    ///< largest step; 0: from the model (arclength) or |ds| (displacement)
  int max_steps = 100;
  std::optional<double> stop_load_factor;
  int node = -1;                          ///< 0-based scene node of the control DOF (displacement control, output)
  int direction = 0;                      ///< 0..2: x, y, z
  std::optional<double> stop_displacement;  ///< of the control DOF
};

struct Options {
  int loadsteps = 10;
  /// Sinew: "spacar" (SPACAR Light's load steps: step 1 = initial loads alone, then (k-1)/(n-1)) or
  /// "uniform" (k/n, Sinew's former steps)
  std::string load_ramp = "spacar";
  bool calcbuck = false;
  bool calccompl = true;
  std::optional<bool> calcfreq;       ///< Sinew: default = scene has inertia
  std::optional<Vec3> gravity;
  std::map<int, std::vector<int>> rls;  ///< 0-based element -> released modes 1..6
  bool transfer = false;
  double transfer_zeta = 0.0;
  std::string filename;
  bool stressperelement = false, rigidstress = false;
  bool showinputonly = false, silent = false;
  bool spavisual = false, customvis = false;  ///< SPACAR Light visualization options (accepted; Sinew writes XDMF)
  std::vector<int> compliance_nodes;  ///< 0-based; empty = all nodes
  std::optional<DynamicsOptions> dynamics;
  std::optional<ContinuationOptions> continuation;
  int nfreq = 6;   ///< Sinew: number of frequencies (also -eps_nev); kAllFrequencies: all (SPACAR Light's out.freq, nfreq: all)
  static constexpr int kAllFrequencies = 0;
  int nbuck = 3;   ///< Sinew: number of buckling multipliers
  OutputSteps output_steps;
  std::optional<StepAnalysisRows> step_analyses;  ///< Sinew: nullopt = the default of each procedure
  /// Sinew: solve on refinements until every result quantity's estimated relative discretization
  /// error is at most this (0: off, the scene's mesh as given; docs/accuracy.md)
  double target_error = 0;
  /// Sinew: the quantities target_error watches ("freq", "buck", "stressmax", "node 3 p", ...);
  /// empty: those the scene asks for (docs/accuracy.md)
  std::vector<std::string> accuracy_quantities;
  /// Sinew: what the levels of target_error refine with opt.dynamics: "time" (dt / 2 per level, the
  /// mesh as written), "space" (the elements, dt as written) or "both"; empty: time with
  /// opt.dynamics, else space (docs/accuracy.md)
  std::string accuracy_refine;
};

struct FormFinding {
  int formfinding_step = 10;
  int max_iter_equilibrium = 100;
  double equilibrium_accuracy = 1e-6;
  std::vector<int> formfinding_elements;  ///< 0-based eprops set indices
  std::vector<double> homotopy_curve;     ///< lambda per step
  std::vector<int> stress_adaption;       ///< 0-based eprops set indices
  double lambda_max = 1.1;
  double mue_relax = 0.0;
  double distortion_max = 0.0;          ///< Sinew: shape distortion bound of stress adaption (<= 1: off)
  bool x_urs = false;
  int x_urs_step = 3;
  std::string elastic_restart_method = "FORCE";
  /// Sinew: stop when a step's normal shape change / model size is below this (0: no stop rule).
  /// Not given: CARAT++'s run, formfinding_step steps, the shape converged when the last step's
  /// normal change is below kShapeConverged.
  std::optional<double> formfinding_tolerance;
  /// Normal shape change per step that separates a found shape from a drifting one (measured with
  /// formfinding_tolerance 0: converged shapes plateau at 1e-8 .. 5e-8 after 5 .. 15 steps (catenoid,
  /// sails), a drifting constant-force cable net is still at 5e-5 after 40 steps).
  static constexpr double kShapeConverged = 1e-6;
  double max_shape_change = 0.5;        ///< Sinew: a larger shape change / model size in one step is an error
};

struct Sensor {
  int node = -1;    ///< 0-based scene node of a node sensor (beam Frame6 nodes; Exudyn's SensorNode), else -1
  int element = 0;  ///< 0-based scene element
  double x = 0;     ///< axial position along the scene element (length units, 0..L)
  double xi = 0;    ///< the same position as a fraction of the element, 0..1 (beam sensors use it)
  std::string variable, name;
};

struct Model {
  std::string title;
  std::string sceneText;               ///< the scene as read, stored in the result file
  int dimension = 3;                   ///< 2 when every node has two coordinates
  std::vector<Vec3> nodes;             ///< z = 0 for 2D nodes
  std::vector<std::vector<int>> elements;  ///< 0-based node numbers
  std::map<int, NodeProps> nprops;     ///< 0-based node -> properties
  std::vector<ElementSet> eprops;
  std::vector<int> elementSet;         ///< per element: eprops index, -1 = rigid (no set)
  /// Nodes 0 .. connectedNodes-1 reach the last node an element connects; the nodes after it are
  /// trailing unconnected nodes (allowed as in SPACAR Light: held fixed, no unknowns)
  std::size_t connectedNodes = 0;
  Options opt;
  std::optional<FormFinding> formfinding;
  std::vector<Sensor> sensors;
  std::vector<std::string> warnings;   ///< found while reading (printed by the runner on rank 0)
};

}  // namespace sinew
