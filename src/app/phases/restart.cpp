#include "app/phases/restart.hpp"

#include <slepcsys.h>
#include <yaml-cpp/yaml.h>

#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "app/phases/scene_changes.hpp"
#include "output/output_target.hpp"

namespace sinew {

namespace {

/// FNV-1a, 64 bit, as 16 hex digits.
struct Hash {
  std::uint64_t h = 1469598103934665603ULL;
  void add(const void* data, size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < n; ++i) {
      h ^= p[i];
      h *= 1099511628211ULL;
    }
  }
  void add(const std::string& s) { add(s.data(), s.size() + 1); }
  std::string hex() const {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016" PRIx64, h);
    return buf;
  }
};

bool isLoadKey(const std::string& k) {
  for (const char* prefix : {"force", "moment", "displ", "rot", "pressure", "massProportionalLoad"})
    if (k.rfind(prefix, 0) == 0) return true;
  return false;
}

std::string dump(const YAML::Node& n) {
  YAML::Emitter e;
  e << YAML::Flow << n;
  return e.c_str();
}

std::vector<std::pair<std::string, std::string>> parseLines(const std::string& text) {
  std::vector<std::pair<std::string, std::string>> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    const size_t c = line.find(": ");
    if (c != std::string::npos) out.emplace_back(line.substr(0, c), line.substr(c + 2));
  }
  return out;
}

bool fileExists(MPI_Comm comm, const std::string& path) {
  int rank = 0, e = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank == 0) e = std::filesystem::exists(path) ? 1 : 0;
  MPI_Bcast(&e, 1, MPI_INT, 0, comm);
  return e != 0;
}

bool sameFile(const std::string& a, const std::string& b) {
  std::error_code ec;
  if (std::filesystem::exists(a, ec) && std::filesystem::exists(b, ec)) return std::filesystem::equivalent(a, b, ec);
  return std::filesystem::weakly_canonical(a, ec) == std::filesystem::weakly_canonical(b, ec);
}

enum class TableKind { Node, Element, Mesh, Cell, Row };
TableKind tableKind(const std::string& name, size_t rank) {
  if (rank >= 2 && name.rfind("cell/", 0) == 0) return TableKind::Cell;
  if (rank >= 2 && name.rfind("node/", 0) == 0) return TableKind::Node;
  if (rank >= 2 && name.rfind("element/", 0) == 0) return TableKind::Element;
  if (rank >= 2 && name.rfind("mesh/", 0) == 0) return TableKind::Mesh;
  return TableKind::Row;
}

}  // namespace

std::string sceneFingerprint(const Model& model, long feNodes, long feElements) {
  std::ostringstream s;
  s << "nodes: " << model.nodes.size() << "\n";
  Hash coords;
  for (const Vec3& x : model.nodes) coords.add(x.data(), sizeof(double) * 3);
  s << "node coordinates: " << coords.hex() << "\n";
  s << "elements: " << model.elements.size() << "\n";
  Hash conn;
  for (const auto& e : model.elements) {
    const long n = static_cast<long>(e.size());
    conn.add(&n, sizeof n);
    conn.add(e.data(), sizeof(int) * e.size());
  }
  s << "element connectivity: " << conn.hex() << "\n";
  s << "FE nodes: " << feNodes << "\n";
  s << "FE elements: " << feElements << "\n";
  const YAML::Node root = YAML::Load(model.sceneText);
  Hash eprops, nprops, loads, ff;
  // (a key missing from the scene gives an undefined node, which must not be asked for its type)
  if (const YAML::Node ep = root["eprops"]; ep.IsDefined() && ep.IsSequence()) {
    for (size_t i = 0; i < ep.size(); ++i)
      for (auto it = ep[i].begin(); ep[i].IsMap() && it != ep[i].end(); ++it) {
        const std::string k = it->first.as<std::string>();
        (isLoadKey(k) ? loads : eprops).add(std::to_string(i) + "." + k + "=" + dump(it->second));
      }
  }
  for (const auto& [e, modes] : model.opt.rls) {
    eprops.add("rls " + std::to_string(e));
    eprops.add(modes.data(), sizeof(int) * modes.size());
  }
  if (const YAML::Node np = root["nprops"]; np.IsDefined() && np.IsMap()) {
    for (auto it = np.begin(); it != np.end(); ++it) {
      const std::string node = it->first.as<std::string>();
      if (!it->second.IsDefined() || !it->second.IsMap()) continue;
      for (auto jt = it->second.begin(); jt != it->second.end(); ++jt) {
        const std::string k = jt->first.as<std::string>();
        (isLoadKey(k) ? loads : nprops).add(node + "." + k + "=" + dump(jt->second));
      }
    }
  }
  if (model.opt.gravity) loads.add(model.opt.gravity->data(), sizeof(double) * 3);
  if (root["mesh"].IsDefined()) eprops.add("mesh=" + dump(root["mesh"]));
  s << "eprops: " << eprops.hex() << "\n";
  s << "nprops (supports, masses): " << nprops.hex() << "\n";
  s << "loads (nprops force/moment/displ/rot, eprops pressure/massProportionalLoad, gravity): " << loads.hex() << "\n";
  if (root["formfinding"].IsDefined()) ff.add(dump(root["formfinding"]));
  s << "formfinding block: " << (root["formfinding"].IsDefined() ? ff.hex() : std::string("none")) << "\n";
  return s.str();
}

int lastLoadStepOf(const Restart* restart, const Model& model, const Settings& settings) {
  return restart ? restart->lastLoadStep(model.opt.loadsteps, settings.sceneOpt.count("loadsteps") > 0)
                 : model.opt.loadsteps;
}

std::vector<double> formfindingRows(const std::vector<FormFindingStepReport>& reports) {
  std::vector<double> rows;
  for (const auto& r : reports) {
    const double row[kFormFindingColumns] = {static_cast<double>(r.step), r.lambda, r.xurs ? 1.0 : 0.0,
                                             static_cast<double>(r.newtonIterations), r.residualNorm,
                                             r.equilibrium ? 1.0 : 0.0, r.shapeChange, r.shapeChangeNormal,
                                             r.meshQuality};
    rows.insert(rows.end(), row, row + kFormFindingColumns);
  }
  return rows;
}

std::vector<FormFindingStepReport> formfindingReports(const std::vector<double>& rows) {
  std::vector<FormFindingStepReport> out;
  for (size_t i = 0; i + kFormFindingColumns <= rows.size(); i += kFormFindingColumns) {
    const double* r = &rows[i];
    if (!(r[0] >= 1)) break;  // unused rows of the fixed-size table
    FormFindingStepReport rep;
    rep.step = static_cast<int>(r[0]);
    rep.lambda = r[1];
    rep.xurs = r[2] != 0.0;
    rep.newtonIterations = static_cast<int>(r[3]);
    rep.residualNorm = r[4];
    rep.equilibrium = r[5] != 0.0;
    rep.shapeChange = r[6];
    rep.shapeChangeNormal = r[7];
    rep.meshQuality = r[8];
    out.push_back(rep);
  }
  return out;
}

Restart::Restart(MPI_Comm comm, const std::string& path, const std::string& output, const std::string& fingerprint,
                 const Model& model, const Plan& plan, DynamicsScheme scheme)
    : comm_(comm) {
  // (a killed run leaves its last committed state under its final name; `path`.part is the copy
  // being written, inconsistent between two commits, and never read)
  std::string src = path;
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  // the new result file replaces its own source at its first commit: read from a copy
  int same = rank == 0 && (sameFile(src, output) || sameFile(src, output + ".part") || sameFile(src, output + ".part2"));
  MPI_Bcast(&same, 1, MPI_INT, 0, comm);
  // a file another run is writing changes under the reader (between its commits, or renamed by
  // them): refused, whatever state it is in (this run holds the lock of its own output)
  std::string busy = rank == 0 && !same ? otherWriter(path) : std::string();
  long nb = static_cast<long>(busy.size());
  MPI_Bcast(&nb, 1, MPI_LONG, 0, comm);
  busy.resize(static_cast<size_t>(nb));
  MPI_Bcast(busy.data(), static_cast<int>(nb), MPI_CHAR, 0, comm);
  if (!busy.empty())
    throw SceneError("-restart", busy + "; restart from it once that run has ended (or was stopped)");
  if (!fileExists(comm, src)) throw SceneError("-restart", "no result file " + path);
  if (same) {
    copy_ = output + ".restart-source";
    int ok = 1;
    if (rank == 0) {
      std::error_code ec;
      std::filesystem::copy_file(src, copy_, std::filesystem::copy_options::overwrite_existing, ec);
      ok = !ec;
    }
    MPI_Bcast(&ok, 1, MPI_INT, 0, comm);
    if (!ok) throw SceneError("-restart", "cannot copy " + src + " to " + copy_ + " (the output file is the restart source)");
    src = copy_;
  }
  try {
    check(comm, src, path, fingerprint, model, plan, scheme);
  } catch (...) {
    removeCopy();
    throw;
  }
}

void Restart::check(MPI_Comm comm, const std::string& src, const std::string& path, const std::string& fingerprint,
                    const Model& model, const Plan& plan, DynamicsScheme scheme) {
  try {
    reader_ = std::make_unique<CheckpointReader>(comm, src);
  } catch (const std::exception& e) {
    throw SceneError("-restart", e.what());
  }
  // what differs between the scenes
  const auto now = parseLines(fingerprint), then = parseLines(reader_->fingerprint());
  std::map<std::string, std::string> old(then.begin(), then.end());
  std::string diff;
  bool loadsDiffer = false, loadsRefused = false;
  for (const auto& [what, value] : now) {
    auto it = old.find(what);
    const std::string before = it == old.end() ? "?" : it->second;
    if (before == value) continue;
    if (what.rfind("loads", 0) == 0) {
      loadsDiffer = true;
      continue;
    }
    const bool count = what == "nodes" || what == "elements" || what == "FE nodes" || what == "FE elements";
    diff += (diff.empty() ? "" : "; ") + what + (count ? " (" + value + " here, " + before + " in " + path + ")" : " changed");
  }
  if (diff.empty() && loadsDiffer && reader_->phase() != CheckpointPhase::FormFinding) {
    // other loads after form finding: the load analysis restarts from the found shape
    bool found = false;
    try {
      auto ff = std::make_unique<CheckpointReader>(comm, src, "checkpoint_formfinding");
      reader_ = std::move(ff);
      found = true;
    } catch (const std::exception&) {
    }
    if (!found) {
      diff = "loads (nprops force/moment/displ/rot, eprops pressure/massProportionalLoad, gravity) changed";
      loadsRefused = true;
    }
  }
  if (!diff.empty()) {
    // the fields that changed, from the scene text the earlier run stored (every result file has it);
    // the fingerprint's categories where it has none or the change is not in the text (a mesh file)
    const auto fields = sceneFieldChanges(reader_->sceneText(), model.sceneText, [&](const std::string& key) {
      return (isLoadKey(key) || key == "gravity") == loadsRefused;
    });
    std::string named;
    for (size_t i = 0; i < fields.size() && i < 6; ++i) named += (i ? "; " : "") + fields[i];
    if (fields.size() > 6) named += "; and " + std::to_string(fields.size() - 6) + " more";
    throw SceneError("-restart", "the scene differs from the run that wrote " + path + ": " + (named.empty() ? diff : named) +
                                     ". A restart continues the same scene (other loads only after form finding).");
  }
  const CheckpointPhase ph = reader_->phase();
  const auto& sc = reader_->scalars();
  const bool hadFF = sc[kCkFormFinding] != 0.0;
  if (hadFF != plan.formfinding)
    throw SceneError("-restart", std::string("the run that wrote ") + path + (hadFF ? " had" : " had no") +
                                     " form finding, this scene has " + (plan.formfinding ? "a" : "no") + " formfinding block");
  if (ph == CheckpointPhase::Dynamics && !plan.dynamics)
    throw SceneError("-restart", path + " holds a dynamics checkpoint; this scene has no opt.dynamics");
  if (ph == CheckpointPhase::Statics && (!plan.statics || plan.continuation || (plan.dynamics && !plan.preload)))
    throw SceneError("-restart", path + " holds a statics checkpoint; this scene runs " +
                                     (plan.dynamics ? "dynamics (opt.dynamics) from rest" : "path following (opt.continuation)"));
  {
    // a run with opt.dynamics start: static has /time rows and, on its load steps, /load_factor;
    // its statics and dynamics checkpoints continue only such a run (and the reverse)
    const auto names = reader_->stepDatasets();
    const bool srcPreload = std::find(names.begin(), names.end(), "time") != names.end() &&
                            std::find(names.begin(), names.end(), "load_factor") != names.end();
    if ((ph == CheckpointPhase::Statics || ph == CheckpointPhase::Dynamics) && srcPreload != plan.preload)
      throw SceneError(plan.dynamics ? "opt.dynamics.start" : "-restart",
                       "the run that wrote " + path + (srcPreload ? " started its dynamics from the load steps (start: static)"
                                                                  : " had no load steps before its time loop") +
                           ", this scene " + (plan.preload ? "has opt.dynamics.start: static" : plan.dynamics ? "starts at rest" : "has no opt.dynamics") +
                           ": a restart continues the same analyses");
  }
  if (ph == CheckpointPhase::Statics) {
    const std::string ramp = sc[kCkLoadRamp] != 0.0 ? "uniform" : "spacar";
    if (ramp != model.opt.load_ramp)
      throw SceneError("opt.load_ramp", "the run that wrote " + path + " had opt.load_ramp " + ramp + ", this scene has " +
                                            model.opt.load_ramp + ": a restart continues the same load steps (give -load_ramp " +
                                            ramp + ")");
  }
  // the phase's own counts (the reader checked that every scalar is finite and within an int)
  const auto damaged = [&](const std::string& what, double v, double lo, double hi) {
    std::ostringstream m;
    m << path << ": /checkpoint: " << what << " = " << v << ", expected an integer in " << lo << ".." << hi
      << "; the checkpoint is damaged (not as a Sinew run wrote it)";
    throw SceneError("-restart", m.str());
  };
  if (ph == CheckpointPhase::Statics && sc[kCkStep] > 100000)
    damaged("scalars step (load steps done; scalar_names)", sc[kCkStep], 0, 100000);
  if (ph == CheckpointPhase::Statics && !(sc[kCkLoadsteps] >= 1 && sc[kCkLoadsteps] <= 100000))
    damaged("scalars loadsteps (scalar_names)", sc[kCkLoadsteps], 1, 100000);
  if (ph == CheckpointPhase::FormFinding && model.formfinding && sc[kCkStep] > model.formfinding->formfinding_step)
    damaged("scalars step (form-finding steps done; scalar_names)", sc[kCkStep], 0, model.formfinding->formfinding_step);
  if (ph == CheckpointPhase::Continuation && !plan.continuation)
    throw SceneError("-restart", path + " holds a path-following checkpoint; this scene has no opt.continuation");
  if (ph == CheckpointPhase::Continuation &&
      static_cast<long>(reader_->pathState().size()) != ContinuationAnalysis::checkpointSize(model.opt.continuation->max_steps) &&
      static_cast<long>(reader_->pathState().size()) != ContinuationAnalysis::legacyCheckpointSize(model.opt.continuation->max_steps))
    throw SceneError("-restart", path + ": the path checkpoint was written with another opt.continuation.max_steps; a restart "
                                        "continues with the same max_steps");
  if (ph == CheckpointPhase::Continuation && plan.continuation) {
    const int ms = model.opt.continuation->max_steps;
    const std::vector<double> v = ContinuationAnalysis::currentCheckpointLayout(reader_->pathState(), ms);
    const auto integer = [](double x, double lo, double hi) { return x >= lo && x <= hi && x == std::floor(x); };
    using CA = ContinuationAnalysis;
    if (!integer(v[0], 1, ms)) damaged("path[0] (path points)", v[0], 1, ms);
    if (!integer(v[7], 0, ms)) damaged("path[7] (critical points)", v[7], 0, ms);
    for (size_t i = 0; i < static_cast<size_t>(v[0]); ++i) {
      const double step = v[CA::kCkHeader + i * CA::kCkPointCols];
      if (!integer(step, 1, ms)) damaged("path point " + std::to_string(i + 1) + " step", step, 1, ms);
    }
  }
  if (ph == CheckpointPhase::Dynamics) {
    const DynamicsOptions& d = *model.opt.dynamics;
    if (d.dt != sc[kCkDt] || d.spectral_radius != sc[kCkSpectralRadius]) {
      std::ostringstream m;
      m << "opt.dynamics of the run that wrote " << path << " had dt = " << sc[kCkDt] << ", spectral_radius = "
        << sc[kCkSpectralRadius] << "; this scene has dt = " << d.dt << ", spectral_radius = " << d.spectral_radius
        << ": a restart continues with the same time step and scheme (a later tend is fine)";
      throw SceneError("-restart", m.str());
    }
    if (scheme == DynamicsScheme::TSAlpha2)
      throw SceneError("-restart", "-dynamics_scheme tsalpha2 keeps its state inside PETSc TS and cannot continue from a "
                                   "checkpoint; restart with the default scheme arnold_bruls");
  }
  if (reader_->feNodes() <= 0) throw SceneError("-restart", path + ": empty checkpoint");
}

Restart::~Restart() { removeCopy(); }

void Restart::removeCopy() {
  reader_.reset();
  int rank = 0;
  MPI_Comm_rank(comm_, &rank);
  if (!copy_.empty() && rank == 0) {
    std::error_code ec;
    std::filesystem::remove(copy_, ec);
  }
}

void Restart::restore(RunContext& ctx, const ResultLayout& layout) {
  const CheckpointReader& r = *reader_;
  const int rows = r.rows();
  ResultFile& file = ctx.file;
  // ---- step rows: every dataset with an unlimited step axis, row by row; a row that the earlier
  // run never wrote (all NaN on every rank) stays unwritten. The datasets of the step analyses have
  // one row per analysed step (/step_analysis_rows; absent: every step): those rows are copied as
  // step-analysis rows of their steps, so that the resumed run appends its own after them.
  std::vector<long> inner;
  std::vector<std::string> names, analysisNames;
  for (const std::string& name : r.stepDatasets()) {
    if (name == "step_analysis_rows") continue;
    (r.onAnalysisRows(name) ? analysisNames : names).push_back(name);
  }
  std::vector<long> analysed;  // step row of each step-analysis row of the earlier run
  if (r.exists("step_analysis_rows")) {
    std::vector<long> shape;
    for (double v : r.readArray("step_analysis_rows", &shape)) analysed.push_back(static_cast<long>(v));
  } else if (!analysisNames.empty()) {
    for (long j = 0; j < r.datasetShape(analysisNames.front()).at(0); ++j) analysed.push_back(j);
  }
  std::size_t nextAnalysed = 0;
  // the earlier run's step values (its form-finding rows are 0 in either layout; a statics or
  // dynamics checkpoint comes from a run of this layout, Restart::check); with opt.dynamics start:
  // static, /load_factor is copied as any other row dataset
  const std::string stepName = std::find(names.begin(), names.end(), "time") != names.end() ? "time" : "load_factor";
  // row s of dataset `name` into the current row of the new file
  auto copyRow = [&](const std::string& name, int s) {
    const std::vector<long> shape = r.datasetShape(name);
    const TableKind kind = tableKind(name, shape.size());
    // cell/<cells>/<quantity>: the rows of this rank's cells of that kind
    const std::string cells = kind == TableKind::Cell ? name.substr(5, name.find('/', 5) - 5) : "";
    const std::vector<long>* sel = kind == TableKind::Node      ? &layout.ownedNodes
                                   : kind == TableKind::Element ? &layout.ownedElements
                                   : kind == TableKind::Mesh    ? &layout.ownedMeshNodes
                                   : kind == TableKind::Cell    ? &file.ownedCellRows(cells)
                                                                : nullptr;
    std::vector<long> in;
    const std::vector<double> row = r.readStepRow(name, s, sel, &in);
    int unwritten = std::all_of(row.begin(), row.end(), [](double x) { return std::isnan(x); });
    MPI_Allreduce(MPI_IN_PLACE, &unwritten, 1, MPI_INT, MPI_LAND, ctx.comm);
    if (unwritten) return;
    if (kind == TableKind::Row) {
      file.writeStepRow(name, row, shape.size() >= 2);  // [ns, 1] stays a table (/freq with nfreq 1)
      return;
    }
    const std::vector<long> cellInner(shape.begin() + 2, shape.end());
    if (kind == TableKind::Cell) file.writeCellField(cells, name.substr(name.find('/', 5) + 1), row, cellInner);
    else if (kind == TableKind::Node) file.writeNodeField(name, row, cellInner);
    else if (kind == TableKind::Element) file.writeElementField(name, row, cellInner);
    else file.writeMeshField(name, row, cellInner);
  };
  for (int s = 0; s < rows; ++s) {
    const std::vector<double> v = r.readStepRow(stepName, s, nullptr, &inner);
    file.beginStep(ctx.nextStep++, v.at(0));
    for (const std::string& name : names)
      if (name != stepName && name != layout.stepName) copyRow(name, s);
    while (nextAnalysed < analysed.size() && analysed[nextAnalysed] < s) ++nextAnalysed;
    if (nextAnalysed < analysed.size() && analysed[nextAnalysed] == s) {
      file.beginAnalysisRow();
      for (const std::string& name : analysisNames) copyRow(name, static_cast<int>(nextAnalysed));
      file.endAnalysisRow();
      ++nextAnalysed;
    }
  }
  // form-finding arrays, written when form finding ended (a form-finding checkpoint writes them anew)
  if (phase() != CheckpointPhase::FormFinding)
    for (const char* a : {"formfinding/residual", "formfinding/shape_change", "formfinding/shape_change_normal"})
      if (r.exists(a)) {
        std::vector<long> shape;
        const std::vector<double> v = r.readArray(a, &shape);
        file.writeArray(a, v, shape);
      }
  // ---- state
  Assembler& as = ctx.assembler;
  r.loadNodes(as);
  r.loadKernels(as);
  if (r.loadVector("U", as, ctx.U)) throw std::runtime_error(source() + ": /checkpoint/node_U: cannot be read");
}

PetscErrorCode Restart::restoredState(RunContext& ctx, CheckpointData& d, std::vector<Vec>* work) const {
  PetscFunctionBeginUser;
  const CheckpointReader& r = *reader_;
  d.scalars = r.scalars();
  d.vectors.emplace_back("U", ctx.U);
  for (const char* v : {"dU", "V", "A", "Qdd"}) {
    const bool wanted = ((phase() == CheckpointPhase::Statics || phase() == CheckpointPhase::Continuation) && std::string(v) == "dU") ||
                        (phase() == CheckpointPhase::Dynamics && std::string(v) != "dU");
    if (!wanted || !r.hasVector(v)) continue;
    Vec w;
    PetscCall(loadedVector(ctx, v, &w));
    work->push_back(w);
    d.vectors.emplace_back(v, w);
  }
  if (phase() == CheckpointPhase::Continuation) {
    d.path = ContinuationAnalysis::currentCheckpointLayout(r.pathState(), ctx.model.opt.continuation->max_steps);
    d.pathSize = static_cast<long>(d.path.size());
  }
  if (ctx.model.formfinding) {
    d.formfinding = r.formfinding();
    d.formfindingRows = ctx.model.formfinding->formfinding_step;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

void Restart::resumeFormFinding(RunContext& ctx, FormFindingAnalysis& analysis) const {
  reader_->loadKernels(ctx.assembler);  // after the analysis' set-up (distortion control touches the prestress)
  analysis.resume(formfindingReports(reader_->formfinding()));
}

PetscErrorCode Restart::loadedVector(RunContext& ctx, const char* name, Vec* v) const {
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(ctx.U, v));
  PetscCall(reader_->loadVector(name, ctx.assembler, *v));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Restart::resumeStatics(RunContext& ctx, StaticAnalysis& statics) const {
  PetscFunctionBeginUser;
  const auto& sc = reader_->scalars();
  StaticsProgress p;
  p.step = static_cast<int>(sc[kCkStep]);
  p.lambda = sc[kCkLambda];
  p.dlPrev = sc[kCkDlPrev];
  p.dlAdapt = sc[kCkDlAdapt];
  p.fintConverged = sc[kCkFintConverged];
  Vec dU;
  PetscCall(loadedVector(ctx, "dU", &dU));
  PetscCall(statics.resume(p, dU));
  PetscCall(VecDestroy(&dU));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Restart::resumeContinuation(RunContext& ctx, ContinuationAnalysis& path) const {
  PetscFunctionBeginUser;
  Vec dU;
  PetscCall(loadedVector(ctx, "dU", &dU));
  PetscCall(path.resume(ContinuationAnalysis::currentCheckpointLayout(reader_->pathState(), ctx.model.opt.continuation->max_steps), dU));
  PetscCall(VecDestroy(&dU));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Restart::resumeDamping(RunContext& ctx, DynamicAnalysis& dyn, Vec V, Vec A, Vec Q) const {
  PetscFunctionBeginUser;
  const std::string group = kDynamicsStartGroup;
  if (!reader_->exists(group + "/scalars")) {
    PetscCall(PetscPrintf(ctx.comm,
                          "  warning: %s has no /%s (written before Sinew stored the start state of damped runs): the "
                          "damping is rebuilt from the resumed state, so the continued run differs from an uninterrupted one "
                          "(docs/dynamics.md, Damping)\n",
                          source().c_str(), kDynamicsStartGroup));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  // the damping of the uninterrupted run: built at its start state (U0 and, for rotation nodes, the
  // start reference rotations; element states), then the resumed state is put back
  const CheckpointReader start(ctx.comm, reader_->path(), group);
  Vec U0;
  PetscCall(VecDuplicate(ctx.U, &U0));
  PetscCall(start.loadVector("U", ctx.assembler, U0));
  PetscCall(start.loadVector("V", ctx.assembler, V));
  PetscCall(start.loadVector("A", ctx.assembler, A));
  PetscCall(start.loadVector("Qdd", ctx.assembler, Q));
  start.loadNodes(ctx.assembler);
  start.loadKernels(ctx.assembler);
  PetscCall(dyn.setupResumedDamping(U0));
  if (ctx.checkpoint) {  // the new file keeps the start state: it can be continued in turn
    CheckpointData d;
    d.scalars = start.scalars();
    d.vectors = {{"U", U0}, {"V", V}, {"A", A}, {"Qdd", Q}};
    ctx.guardedWrite([&] {
      ctx.checkpoint->write(ctx.file, d, group);
      ctx.file.commit();
    });
  }
  PetscCall(VecDestroy(&U0));
  reader_->loadNodes(ctx.assembler);
  reader_->loadKernels(ctx.assembler);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Restart::resumeDynamics(RunContext& ctx, DynamicAnalysis& dyn, double* energy0, double* maxDrift, double* work,
                                      double* power) const {
  PetscFunctionBeginUser;
  const auto& sc = reader_->scalars();
  DynamicsProgress p;
  p.step = static_cast<int>(sc[kCkStep]);
  p.time = sc[kCkTime];
  p.h = sc[kCkSubstep];
  p.successes = static_cast<int>(sc[kCkSuccesses]);
  p.scale = sc[kCkAdaptScale];
  Vec V, A, Q;
  PetscCall(loadedVector(ctx, "V", &V));
  PetscCall(loadedVector(ctx, "A", &A));
  PetscCall(loadedVector(ctx, "Qdd", &Q));
  PetscCall(dyn.resume(p, ctx.U, V, A, Q));
  if (dyn.damped()) PetscCall(resumeDamping(ctx, dyn, V, A, Q));
  PetscCall(VecDestroy(&V));
  PetscCall(VecDestroy(&A));
  PetscCall(VecDestroy(&Q));
  *energy0 = sc[kCkEnergy0];
  *maxDrift = sc[kCkMaxDrift];
  *work = sc[kCkExternalWork];
  *power = sc[kCkExternalPower];
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
