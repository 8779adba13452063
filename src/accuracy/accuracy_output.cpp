#include "accuracy/accuracy_output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>

#include "accuracy/time_refinement.hpp"
#include "output/hdf5_util.hpp"

namespace sinew::accuracy {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// A float64 dataset `name` of `dims` under `group` from row-major `values`.
void writeDataset(hid_t group, const std::string& name, const std::vector<hsize_t>& dims, const std::vector<double>& values) {
  const std::string what = "/accuracy/" + name;
  h5::Handle space = h5::dataspace(dims, what + ": dataspace");
  h5::Handle d(H5Dcreate2(group, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose,
               what + ": create");
  if (!values.empty()) h5::check(H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), what + ": write");
}

void writeDoubleAttribute(hid_t obj, const std::string& name, double value) {
  h5::Handle space(H5Screate(H5S_SCALAR), H5Sclose, "attribute " + name + ": dataspace");
  h5::Handle a(H5Acreate2(obj, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
               "attribute " + name + ": create");
  h5::check(H5Awrite(a, H5T_NATIVE_DOUBLE, &value), "attribute " + name + ": write");
}

int statusCode(const Estimate& e) {
  switch (e.status) {
    case EstimateStatus::Converging: return 0;
    case EstimateStatus::Resolved: return 1;
    case EstimateStatus::Erratic: return 2;
  }
  return 2;
}

std::string sci(double v) {
  if (!std::isfinite(v)) return "-";
  char b[32];
  std::snprintf(b, sizeof b, "%.2e", v);
  return b;
}

std::string number(double v) {
  if (!std::isfinite(v)) return "-";
  char b[32];
  std::snprintf(b, sizeof b, "%.10g", v);
  return b;
}

/// A quantity's value as printed: the number, or [a, b, c] for a vector (a longer one, the found
/// shape, by its size: /accuracy/value holds it).
std::string valueText(const std::vector<double>& v) {
  if (v.empty()) return "-";
  if (v.size() == 1) return number(v[0]);
  if (v.size() > 9) {
    char b[64];
    std::snprintf(b, sizeof b, "[%zu values in /accuracy/value]", v.size());
    return b;
  }
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) {
    char b[32];
    std::snprintf(b, sizeof b, "%.6g", v[i]);
    s += (i ? ", " : "") + std::string(b);
  }
  return s + "]";
}

}  // namespace

RunResults readResultDatasets(const std::string& path, const std::set<std::string>& names) {
  RunResults r;
  h5::Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, path + ": open");
  for (const std::string& name : names) {
    htri_t exists = 0;
    H5E_BEGIN_TRY { exists = H5Lexists(file, name.c_str(), H5P_DEFAULT); }
    H5E_END_TRY;
    if (exists <= 0) continue;  // a dataset the level did not write (fewer analyses): the quantity is missing
    const std::string what = path + ": /" + name;
    h5::Handle d(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose, what + ": open");
    h5::Handle space(H5Dget_space(d), H5Sclose, what + ": dataspace");
    const int rank = h5::check(H5Sget_simple_extent_ndims(space), what + ": rank");
    std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
    h5::check(H5Sget_simple_extent_dims(space, dims.data(), nullptr), what + ": dims");
    ResultArray a;
    for (hsize_t n : dims) a.shape.push_back(static_cast<long>(n));
    a.values.resize(static_cast<std::size_t>(a.size()));
    if (!a.values.empty())
      h5::check(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, a.values.data()), what + ": read");
    r.datasets[name] = std::move(a);
  }
  h5::Handle attr(H5Aopen(file, "nunknowns", H5P_DEFAULT), H5Aclose, path + ": attribute nunknowns");
  long long n = 0;
  h5::check(H5Aread(attr, H5T_NATIVE_LLONG, &n), path + ": attribute nunknowns");
  r.numbers["nunknowns"] = static_cast<long>(n);
  return r;
}

RunResults accuracyResults(const StudyResult& study) {
  RunResults r;
  const std::size_t nl = study.levels.size(), nq = study.quantities.size();
  std::size_t m = 1;
  for (const LevelRecord& l : study.levels)
    for (const auto& v : l.values) m = std::max(m, v.size());
  std::vector<double> level, factor, unknowns, seconds, newton, reused, worst, limiting, error, order, status, value;
  std::vector<double> steps, rejected, planned;  // paths only
  bool path = false;
  for (const LevelRecord& l : study.levels) {
    level.push_back(l.level);
    factor.push_back(static_cast<double>(l.factor));
    unknowns.push_back(static_cast<double>(l.unknowns));
    seconds.push_back(l.seconds);
    newton.push_back(l.newtonIterations >= 0 ? static_cast<double>(l.newtonIterations) : kNaN);
    reused.push_back(l.guessesUsed);
    path = path || l.pathSteps >= 0;
    steps.push_back(l.pathSteps >= 0 ? static_cast<double>(l.pathSteps) : kNaN);
    rejected.push_back(l.rejectedSteps >= 0 ? static_cast<double>(l.rejectedSteps) : kNaN);
    planned.push_back(l.plannedSteps);
    worst.push_back(l.worst >= 0 ? l.worst : kNaN);
    limiting.push_back(l.limiting);
    for (std::size_t q = 0; q < nq; ++q) {
      const bool has = q < l.estimates.size();
      error.push_back(has ? l.estimates[q].error : kNaN);
      order.push_back(has ? l.estimates[q].order : kNaN);
      status.push_back(has ? statusCode(l.estimates[q]) : -1);
      for (std::size_t k = 0; k < m; ++k) value.push_back(k < l.values[q].size() ? l.values[q][k] : kNaN);
    }
  }
  std::vector<double> extrapolated(nq * m, kNaN);
  if (nl)
    for (std::size_t q = 0; q < nq && q < study.levels.back().estimates.size(); ++q) {
      const std::vector<double>& x = study.levels.back().estimates[q].extrapolated;
      for (std::size_t k = 0; k < x.size() && k < m; ++k) extrapolated[q * m + k] = x[k];
    }
  const long L = static_cast<long>(nl), Q = static_cast<long>(nq), M = static_cast<long>(m);
  auto add = [&](const std::string& name, std::vector<long> shape, std::vector<double> values) {
    ResultArray& a = r.datasets["accuracy/" + name];
    a.shape = std::move(shape);
    a.values = std::move(values);
  };
  add("level", {L}, level);
  add("nbeams_factor", {L}, factor);  // with time refinement: the divisor of dt
  add("unknowns", {L}, unknowns);
  add("wall_time", {L}, seconds);
  add("newton_iterations", {L}, newton);  // NaN: the level's summary reports none (opt.silent, no solver phase)
  add("reused_starts", {L}, reused);      // load increments started from the coarser level's state
  if (path) {
    add("path_steps", {L}, steps);        // a path's accepted steps (its points)
    add("rejected_steps", {L}, rejected);  // its steps cut or repeated shorter
    add("planned_steps", {L}, planned);    // its steps that followed the coarser level's steps
  }
  add("worst_error", {L}, worst);
  add("limiting", {L}, limiting);
  add("error", {L, Q}, error);
  add("order", {L, Q}, order);
  add("status", {L, Q}, status);
  add("value", {L, Q, M}, value);
  add("extrapolated", {Q, M}, extrapolated);
  std::string names;
  for (const QuantityDef& q : study.quantities) names += q.name + "\n";
  std::map<std::string, std::string>& t = r.groupTexts["accuracy"];
  t["quantities"] = names;
  t["target"] = number(study.target);
  t["met"] = study.met ? "1" : "0";
  t["level"] = std::to_string(nl ? study.levels.back().level : -1);
  t["stop_reason"] = study.stopReason;
  t["refinement"] = !study.time ? "elements / 2^level" : study.space ? "elements and dt / 2^level" : "dt / 2^level";
  return r;
}

void writeAccuracyGroup(const std::string& path, const StudyResult& study) {
  h5::Handle file(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose, path + ": open for /accuracy");
  H5E_BEGIN_TRY { H5Ldelete(file, "accuracy", H5P_DEFAULT); }  // a group of an earlier run of the same file
  H5E_END_TRY;
  h5::Handle g(H5Gcreate2(file, "accuracy", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "/accuracy: create");
  const RunResults r = accuracyResults(study);
  for (const auto& [name, a] : r.datasets)
    writeDataset(g, name.substr(std::string("accuracy/").size()), std::vector<hsize_t>(a.shape.begin(), a.shape.end()), a.values);
  const std::map<std::string, std::string>& t = r.groupTexts.at("accuracy");
  h5::writeAttribute(g, "quantities", t.at("quantities"));
  writeDoubleAttribute(g, "target", study.target);
  h5::writeAttribute(g, "met", study.met ? 1 : 0);
  h5::writeAttribute(g, "level", study.levels.empty() ? -1 : study.levels.back().level);
  h5::writeAttribute(g, "stop_reason", study.stopReason);
  h5::writeAttribute(g, "refinement", t.at("refinement"));
}

std::string accuracyTable(const StudyResult& study) {
  std::string s = "accuracy (-target_error " + sci(study.target) + ", relative): ";
  if (study.levels.empty()) return s + study.stopReason + "\n";
  const LevelRecord& last = study.levels.back();
  s += study.met ? "met at level " + std::to_string(last.level) + " (" + levelName(last.level, study.time, study.space) + ")"
                 : "not met; " + study.stopReason;
  char b[256];
  std::snprintf(b, sizeof b, "; %.3g s for all levels\n  %5s %10s %10s %7s %15s  %s\n", study.totalSeconds, "level",
                "unknowns", "time [s]", "Newton", "worst estimate", "limiting quantity");
  s += b;
  for (const LevelRecord& l : study.levels) {
    std::string limit = "-";
    if (l.limiting >= 0) {
      const Estimate& e = l.estimates[static_cast<std::size_t>(l.limiting)];
      char o[64];
      std::snprintf(o, sizeof o, " (%s, order %.2f)", statusName(e.status), e.order);
      limit = study.quantities[static_cast<std::size_t>(l.limiting)].name + o;
    }
    const std::string its = l.newtonIterations >= 0 ? std::to_string(l.newtonIterations) : "-";
    std::snprintf(b, sizeof b, "  %5d %10ld %10.3g %7s %15s  %s\n", l.level, l.unknowns, l.seconds, its.c_str(),
                  l.worst >= 0 ? sci(l.worst).c_str() : "-", limit.c_str());
    s += b;
  }
  s += "  quantity: value at level " + std::to_string(last.level) + ", estimated relative error, observed order, status"
       ", extrapolated value\n";
  for (std::size_t q = 0; q < study.quantities.size(); ++q) {
    const bool has = q < last.estimates.size();
    const Estimate* e = has ? &last.estimates[q] : nullptr;
    char o[32] = "-";
    if (e && std::isfinite(e->order)) std::snprintf(o, sizeof o, "%.2f", e->order);
    const auto text = study.quantities[q].kind == QuantityDef::Kind::DisplacementHistory ? historyText : valueText;
    s += "    " + study.quantities[q].name + ": " + text(last.values[q]) + ", " + (e ? sci(e->error) : "-") + ", " + o + ", " +
         (e ? statusName(e->status) : "-") + ", " + (e && !e->extrapolated.empty() ? text(e->extrapolated) : "-") + "\n";
  }
  return s;
}

}  // namespace sinew::accuracy
