#include "accuracy/refinement_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "accuracy/found_shape_reuse.hpp"
#include "accuracy/level_reuse.hpp"
#include "accuracy/membrane_refinement.hpp"
#include "accuracy/path_quantities.hpp"
#include "accuracy/time_refinement.hpp"
#include "elements/element_kinds.hpp"

namespace sinew::accuracy {

namespace {

/// Levels at most: nbeams x 2^15 is beyond any -accuracy_max_unknowns a model reaches first.
constexpr int kMaxLevels = 16;
/// A level meets the target when safety x its worst estimate does (the factor of Roache's grid
/// convergence index for three levels): Richardson's estimate leaves out the higher-order terms,
/// measured 0.4 % of the error in the roll-up at 1e-4 (docs/accuracy.md).
constexpr double kSafety = 1.25;
/// The exit code of a run whose analysis did not converge (sinew/simulation.hpp).
constexpr int kAnalysisFailed = 3;

std::string sci(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2e", v);
  return b;
}

/// The estimates of level `fine` from the two levels before it; worst and limiting quantity.
void estimate(LevelRecord& fine, const LevelRecord& coarse, const LevelRecord& middle, const std::vector<QuantityDef>& qs,
              const RunResults& fineResults, const StudyOptions& options) {
  fine.worst = 0;
  double worstTrusted = -1, worstErratic = -1;
  for (std::size_t i = 0; i < qs.size(); ++i) {
    const std::vector<double>& q0 = coarse.values[i];
    const std::vector<double>& q1 = middle.values[i];
    const std::vector<double>& q2 = fine.values[i];
    Estimate e;
    if (q0.empty() || q0.size() != q1.size() || q1.size() != q2.size()) {  // missing on a level (fewer modes found)
      e.order = e.error = std::numeric_limits<double>::quiet_NaN();
    } else {
      const std::size_t rowSize = qs[i].kind == QuantityDef::Kind::DisplacementHistory ? 3 : 0;  // the worst time row
      const double order = rowSize > 0 ? historyOrder(options)
                                       : theoreticalOrder(qs[i], options.lumpedMass, options.membranes, options.orders);
      // a bifurcation load is a buckling eigenvalue (the elements' modal order) where the path before it
      // is straight, the prebuckling state linear in the load (a perfect column); the nodal order where
      // that state bends and enters the tangent: either is trusted
      const double upper = qs[i].kind == QuantityDef::Kind::BifurcationLoad ? options.orders.modal : 0;
      e = richardson(q0, q1, q2, quantityScale(qs[i], fineResults), order, options.target, rowSize, upper);
    }
    const double err = std::isfinite(e.error) ? e.error : std::numeric_limits<double>::infinity();
    fine.worst = std::max(fine.worst, err);
    if (!e.trusted()) {
      fine.erratic = true;
      if (err > worstErratic) worstErratic = err, fine.limiting = static_cast<int>(i);
    } else if (!fine.erratic && err > worstTrusted) {
      worstTrusted = err, fine.limiting = static_cast<int>(i);
    }
    fine.estimates.push_back(std::move(e));
  }
}

/// The worst estimate one more level would have if every quantity kept its observed order.
double predictedNext(const LevelRecord& r) {
  double worst = 0;
  for (const Estimate& e : r.estimates)
    worst = std::max(worst, e.status == EstimateStatus::Converging ? e.error / std::pow(2.0, e.order) : e.error);
  return worst;
}

std::string levelLine(const LevelRecord& r, const std::vector<QuantityDef>& qs, const StudyOptions& options) {
  std::string s = "  accuracy level " + std::to_string(r.level) + ": " + levelName(r.level, options.time, options.space) + ", " +
                  std::to_string(r.unknowns) + (options.dynamics ? " unknowns x time steps, " : " unknowns, ");
  char t[32];
  std::snprintf(t, sizeof t, "%.3g s", r.seconds);
  s += t;
  if (r.worst < 0) return s + (qs.empty() ? "" : " (an estimate needs 3 levels)");
  if (r.limiting < 0) return s + ", nothing to estimate";
  const Estimate& e = r.estimates[static_cast<std::size_t>(r.limiting)];
  const std::string& name = qs[static_cast<std::size_t>(r.limiting)].name;
  char o[32];
  std::snprintf(o, sizeof o, "%.2f", e.order);
  s += ", worst estimate " + sci(r.worst) + " (" + name;
  if (r.erratic) return s + ": observed order " + (std::isfinite(e.order) ? std::string(o) : "undefined") +
                        " erratic, refining further)";
  return s + (e.status == EstimateStatus::Resolved ? ", resolved)" : ", order " + std::string(o) + ")");
}

long numberOr(const RunResults& r, const char* name, long fallback) {
  const auto it = r.numbers.find(name);
  return it == r.numbers.end() ? fallback : it->second;
}

}  // namespace

std::string levelName(int level, bool time, bool space) {
  const std::string f = std::to_string(1L << level);
  if (time && space) return "nbeams x" + f + ", dt / " + f;
  return (time ? "dt / " : "nbeams x") + f;
}

double historyOrder(const StudyOptions& options) {
  const double space = options.membranes ? 2.0 : options.orders.nodal;
  if (!options.space) return kTimeSchemeOrder;
  return options.time ? std::min(space, kTimeSchemeOrder) : space;
}

ElementOrders elementOrders(const Model& m) {
  ElementOrders o{1e9, 1e9};
  bool any = false;
  for (const ElementSet& set : m.eprops) {
    const ElementKind& k = elementKind(set.type());
    o.nodal = std::min(o.nodal, k.nodalOrder), o.modal = std::min(o.modal, k.modalOrder), any = true;
  }
  return any ? o : ElementOrders{};
}

long newtonIterationsOf(const std::string& output) {
  static const std::string tail = " Newton iterations)";  // the summary's "statics 0.1 s (12 Newton iterations)"
  long total = -1;
  for (std::size_t at = output.find(tail); at != std::string::npos; at = output.find(tail, at + 1)) {
    const std::size_t open = output.rfind('(', at);
    if (open == std::string::npos) continue;
    try {
      total = std::max(total, 0L) + std::stol(output.substr(open + 1, at - open - 1));
    } catch (const std::exception&) {
    }
  }
  return total;
}

void pathStepsOf(const std::string& output, long* steps, long* rejected) {
  // the path summary's "path: 41 points, ..., 0 cut steps[, 2 steps repeated shorter ...]"
  *steps = *rejected = -1;
  const std::size_t at = output.find("  path: ");
  if (at == std::string::npos) return;
  const std::string line = output.substr(at, output.find('\n', at) - at);
  auto before = [&line](const std::string& tail) -> long {
    const std::size_t end = line.find(tail);
    if (end == std::string::npos) return 0;
    const std::size_t open = line.find_last_of(" ,:", end - 1);
    try {
      return std::stol(line.substr(open + 1, end - open - 1));
    } catch (const std::exception&) {
      return 0;
    }
  };
  *steps = before(" points");
  *rejected = before(" cut steps") + before(" steps repeated shorter");
}

StudyOptions studyOptions(const Model& m, double target, long maxUnknowns, bool lumpedMass, bool reuse) {
  StudyOptions o;
  o.reuse = reuse && reusesStates(m);
  o.target = target;
  o.maxUnknowns = maxUnknowns;
  o.lumpedMass = lumpedMass;
  o.time = refinesTime(m);
  o.space = refinesSpace(m);
  o.dynamics = m.opt.dynamics.has_value();
  o.membranes = hasMembranes(m) && o.space;
  o.orders = elementOrders(m);
  return o;
}

namespace {

/// The map of the coarser level's node states onto the FE nodes of `fine` (none when they do not nest).
std::function<std::vector<double>(const std::vector<double>&)> coarseNodeMap(const Model& coarse, const Model& fine) {
  auto map = std::make_shared<const LevelNodeMap>(coarse, fine, BeamMidRotation::HermiteTangent);
  if (!map->valid()) return {};
  return [map](const std::vector<double>& states) { return map->apply(states); };
}

/// Level `level` in space: nbeams x 2^level, or every membrane element split `level` times.
Model spaceRefinedModel(const Model& base, int level) {
  Model m = base;
  m.opt.target_error = 0;
  m.opt.accuracy_quantities.clear();
  adaptPathLevel(m, level);
  if (hasMembranes(m)) return splitMembraneModel(m, level);  // h / 2^level by splitting every element
  std::vector<char> line(m.eprops.size(), 0);  // sets of 2-node elements: nbeams splits them
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    const int set = m.elementSet[e];
    if (set >= 0 && m.elements[e].size() == 2) line[static_cast<std::size_t>(set)] = 1;
  }
  for (std::size_t s = 0; s < m.eprops.size(); ++s)
    if (line[s]) m.eprops[s].nbeams <<= level;
  return m;
}

}  // namespace

Model refinedModel(const Model& base, int level) {
  if (!refinesSpace(base)) return timeRefinedModel(base, level);  // dt / 2^level, the mesh as written
  Model m = spaceRefinedModel(base, level);
  return refinesTime(base) ? timeRefinedModel(m, level) : m;  // both: the refined mesh with dt / 2^level
}

StudyResult runRefinementStudy(const Model& base, const StudyOptions& options, const LevelRunner& run,
                               const std::function<void(const std::string&)>& print) {
  const double target = options.target;
  const long maxUnknowns = options.maxUnknowns;
  StudyResult s;
  s.target = target;
  s.time = options.time;
  s.space = options.space;
  bool mayBeLast = false;  // the next level's predicted estimate meets the target
  bool failed = false;
  int first = 0;  // the coarsest level of the sequence
  LevelRun last;
  std::shared_ptr<StaticsHandover> coarser;  // the last level's record (-accuracy_reuse)
  Model coarserModel;
  std::vector<LevelState> lastGuesses;  // the guesses the last level started from
  for (int level = 0; level < kMaxLevels; ++level) {
    if (level > first) {  // unknowns grow with the elements, g = 2 per level (lines) or 4 (membranes):
      // U(L+1) - U(L) = g (U(L) - U(L-1))
      const std::size_t n = s.levels.size();
      const long g = (options.space ? (options.membranes ? 4 : 2) : 1) * (options.time ? 2 : 1);
      const long next = n == 1 ? g * s.levels[0].unknowns : (g + 1) * s.levels[n - 1].unknowns - g * s.levels[n - 2].unknowns;
      if (next > maxUnknowns) {
        s.stopReason = "level " + std::to_string(level) + " (" + levelName(level, options.time, options.space) + ") would have about " +
                       std::to_string(next) + (options.time ? " unknowns x time steps" : " unknowns") +
                       ", more than -accuracy_max_unknowns " + std::to_string(maxUnknowns);
        break;
      }
    }
    const bool toFile = mayBeLast;
    const Model model = refinedModel(base, level);
    std::shared_ptr<StaticsHandover> handover;  // the coarser level's states, this level's record
    if (options.reuse) {
      handover = std::make_shared<StaticsHandover>();
      handover->fromStart = model.formfinding.has_value();  // displacements from each level's found shape
      if (coarser)
        handover->guesses = handover->fromStart
                                ? interpolateDisplacements(coarserModel, model, coarser->record, coarser->start)
                                : interpolateStates(coarserModel, model, coarser->record);
      if (options.dynamics) {  // the coarser level's time steps; this level records its own
        if (coarser) {
          handover->coarseHistory = std::move(coarser->history);
          coarser->coarseHistory.reset();  // two levels back: no longer needed
          if (options.space) handover->coarseNodeMap = coarseNodeMap(coarserModel, model);
        }
        handover->history = std::make_shared<TimeHandover>();
        handover->history->byNode = options.space;  // the elements refined: by FE node, mapped onto the next level's
      }
    }
    LevelRun r = run(model, level, toFile, datasetsUsed(s.quantities), handover);
    if (handover) {  // a level that did not converge hands on the states it reached
      lastGuesses = std::move(handover->guesses);  // kept for a repeat of this level into the file
      coarser = handover;
      coarserModel = model;
    }
    s.totalSeconds += r.seconds;
    // a coarse level whose analysis does not converge (one element cannot roll up a cantilever) is
    // dropped while there is no estimate yet: the sequence starts again from the next level
    if (r.exitCode == kAnalysisFailed && s.levels.size() < 2) {
      print("  accuracy level " + std::to_string(level) + ": " + levelName(level, options.time, options.space) +
            ", the analysis did not converge; the levels start again from level " + std::to_string(level + 1));
      s.levels.clear();
      s.quantities.clear();
      first = level + 1;
      continue;
    }
    if (r.exitCode != 0) {
      s.stopReason = "level " + std::to_string(level) + " (" + levelName(level, options.time, options.space) + ") failed (exit " +
                     std::to_string(r.exitCode) + ")";
      s.finalRun = std::move(r);
      failed = true;
      break;
    }
    if (level == first) s.quantities = selectQuantities(base, r.results, base.opt.accuracy_quantities);
    LevelRecord rec;
    rec.level = level;
    rec.factor = 1L << level;
    rec.unknowns = numberOr(r.results, "nunknowns", r.unknowns);
    if (options.dynamics) rec.unknowns *= timeSteps(refinedModel(base, level));  // space-time
    rec.seconds = r.seconds;
    rec.newtonIterations = newtonIterationsOf(r.output);
    rec.guessesUsed = handover ? handover->guessesUsed : 0;
    rec.plannedSteps = handover ? handover->plannedSteps : 0;
    pathStepsOf(r.output, &rec.pathSteps, &rec.rejectedSteps);
    rec.toFile = toFile;
    for (const QuantityDef& q : s.quantities) rec.values.push_back(readQuantity(q, r.results));
    if (s.levels.size() >= 2) estimate(rec, s.levels[s.levels.size() - 2], s.levels.back(), s.quantities, r.results, options);
    print(levelLine(rec, s.quantities, options));
    s.levels.push_back(std::move(rec));
    last = std::move(r);
    const LevelRecord& now = s.levels.back();
    if (s.quantities.empty()) {
      s.stopReason = "no result quantity to estimate (nothing loaded moves, no frequencies, buckling or stress asked for)";
      break;
    }
    if (now.worst >= 0 && !now.erratic && kSafety * now.worst <= target) {
      s.met = true;
      s.stopReason = "target met";
      break;
    }
    mayBeLast = now.worst >= 0 && !now.erratic && kSafety * predictedNext(now) <= target;
  }
  if (s.levels.empty() || failed) return s;
  if (s.stopReason.empty()) s.stopReason = "the last level (" + std::to_string(kMaxLevels - 1) + ") was reached";
  if (s.levels.back().toFile) {
    s.finalRun = std::move(last);
  } else {  // the reported level ran in memory: once more, into the result file
    LevelRecord& rec = s.levels.back();
    std::shared_ptr<StaticsHandover> handover;  // the same start as its run in memory
    if (options.reuse) {
      handover = std::make_shared<StaticsHandover>();
      handover->guesses = std::move(lastGuesses);
      handover->fromStart = base.formfinding.has_value();
      if (coarser) {  // dynamics; it records nothing
        handover->coarseHistory = coarser->coarseHistory;
        handover->coarseNodeMap = coarser->coarseNodeMap;
      }
      coarser.reset();  // its own record: no finer level follows
    }
    s.finalRun = run(refinedModel(base, rec.level), rec.level, true, datasetsUsed(s.quantities), handover);
    s.totalSeconds += s.finalRun.seconds;
    char t[32];
    std::snprintf(t, sizeof t, "%.3g s", s.finalRun.seconds);
    print("  accuracy level " + std::to_string(rec.level) + " again, into the result file (" + t + ")");
  }
  return s;
}

}  // namespace sinew::accuracy
