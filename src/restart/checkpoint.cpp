// Checkpoint group of the result file (checkpoint.hpp). The writer goes through the result file's
// state datasets (ResultFile::writeStateTable: fixed size, overwritten in place, published by the
// same commit() as the step rows); a reader (any rank count) opens the file on every rank and picks
// the rows of its own nodes and elements.
#ifndef OMPI_SKIP_MPICXX
#define OMPI_SKIP_MPICXX 1
#endif
#include "restart/checkpoint.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "output/hdf5_util.hpp"
#include "scene/value_bounds.hpp"

namespace sinew {

namespace {

const char* const kScalarNames =
    "phase rows step step_value loadsteps lambda dl_prev dl_adapt fint_converged time substep successes dt "
    "spectral_radius energy0 max_drift formfinding load_ramp external_work external_power adapt_scale";

// "_U_dU": the vectors of a table, in column order (the tables of each phase have their own names,
// since a fixed-size dataset keeps its shape)
std::string tableSuffix(const std::vector<std::pair<std::string, Vec>>& vectors) {
  std::string s;
  for (const auto& [name, v] : vectors) s += "_" + name;
  return s;
}

long globalFeElements(const DistributedMesh& m) {
  long mx = -1;
  for (const LocalElement& el : m.elements) mx = std::max(mx, el.feIndex);
  MPI_Allreduce(MPI_IN_PLACE, &mx, 1, MPI_LONG, MPI_MAX, m.comm);
  return mx + 1;
}

/// A variable-length string attribute of obj (as h5::writeAttribute writes it).
std::string readTextAttribute(hid_t obj, const char* name, const std::string& what) {
  h5::Handle attr(H5Aopen(obj, name, H5P_DEFAULT), H5Aclose, what);
  char* s = nullptr;
  h5::Handle mtype(H5Tcopy(H5T_C_S1), H5Tclose, "string type");
  h5::check(H5Tset_size(mtype, H5T_VARIABLE), "string size");
  h5::check(H5Tset_cset(mtype, H5T_CSET_UTF8), "string charset");
  h5::check(H5Aread(attr, mtype, &s), what + " read");
  const std::string text = s ? s : "";
  h5::Handle space(H5Aget_space(attr), H5Sclose, what + " space");
  H5Dvlen_reclaim(mtype, space, H5P_DEFAULT, &s);
  return text;
}

bool linkExists(hid_t f, const std::string& name) {
  return h5::check(H5Lexists(f, name.c_str(), H5P_DEFAULT), "checkpoint: lookup of /" + name) > 0;
}

std::vector<hsize_t> datasetDims(hid_t dset, const std::string& what, std::vector<hsize_t>* maxdims = nullptr) {
  h5::Handle space(H5Dget_space(dset), H5Sclose, what + ": dataspace");
  const int r = h5::check(H5Sget_simple_extent_ndims(space), what + ": rank");
  std::vector<hsize_t> dims(static_cast<size_t>(r)), mx(static_cast<size_t>(r));
  h5::check(H5Sget_simple_extent_dims(space, dims.data(), mx.data()), what + ": dims");
  if (maxdims) *maxdims = mx;
  return dims;
}

// Reads the points `coords` (rank r each) of dataset `dset` in order.
std::vector<double> readPoints(hid_t dset, const std::vector<hsize_t>& coords, int r, const std::string& what) {
  const size_t npts = coords.size() / static_cast<size_t>(r);
  std::vector<double> out(npts);
  if (npts == 0) return out;
  h5::Handle fspace(H5Dget_space(dset), H5Sclose, what + ": dataspace");
  h5::check(H5Sselect_elements(fspace, H5S_SELECT_SET, npts, coords.data()), what + ": select");
  h5::Handle mspace = h5::dataspace({hsize_t(npts)}, what);
  h5::check(H5Dread(dset, H5T_NATIVE_DOUBLE, mspace, fspace, H5P_DEFAULT, out.data()), what + ": read");
  return out;
}

#if H5_VERSION_GE(1, 12, 0)
using ObjectInfo = H5O_info2_t;
#else
using ObjectInfo = H5O_info_t;
#endif
herr_t collectDatasets(hid_t, const char* name, const ObjectInfo* info, void* data) {
  if (info->type == H5O_TYPE_DATASET) static_cast<std::vector<std::string>*>(data)->push_back(name);
  return 0;
}

}  // namespace

const char* phaseName(CheckpointPhase p) {
  switch (p) {
    case CheckpointPhase::FormFinding: return "form finding";
    case CheckpointPhase::Statics: return "statics";
    case CheckpointPhase::Dynamics: return "dynamics";
    case CheckpointPhase::Continuation: return "path following";
  }
  return "unknown";
}

// ---------------------------------------------------------------- writer

CheckpointWriter::CheckpointWriter(Assembler& assembler, std::string fingerprint)
    : asm_(assembler), fingerprint_(std::move(fingerprint)) {
  const DistributedMesh& m = asm_.mesh();
  numFeElements_ = globalFeElements(m);
  int k = 0;
  for (const LocalElement& el : m.elements) k = std::max(k, el.kernel->checkpointSize());
  MPI_Allreduce(&k, &kernelColumns_, 1, MPI_INT, MPI_MAX, m.comm);
}

void CheckpointWriter::write(ResultFile& file, const CheckpointData& d, const std::string& group) {
  const DistributedMesh& m = asm_.mesh();
  if (!groups_.count(group)) {  // once per group and file
    file.writeStateAttribute(group, "fingerprint", fingerprint_);
    file.writeStateAttribute(group, "scalar_names", std::string(kScalarNames));
    groups_.insert(group);
  }
  const long nfe = m.numFeNodes;
  std::vector<long> nodeRows;
  for (int i = 0; i < m.numOwnedNodes; ++i) nodeRows.push_back(m.nodes[i].gid);
  std::vector<long> elemRows;
  for (const LocalElement& el : m.elements) elemRows.push_back(el.feIndex);

  // one node table (X0, R_ref, then 6 columns per vector) and one element table (6 multiplier
  // columns per vector, then the kernel states): few collective writes per checkpoint
  const int nv = static_cast<int>(d.vectors.size());
  const int nodeCols = 12 + 6 * nv, elemCols = 6 * nv + kernelColumns_;
  std::vector<double> nt(nodeRows.size() * nodeCols, 0.0), et(elemRows.size() * elemCols, 0.0);
  const std::vector<Mat3> R = asm_.referenceRotations();
  for (int i = 0; i < m.numOwnedNodes; ++i) {
    double* row = &nt[static_cast<size_t>(i) * nodeCols];
    std::copy(m.nodes[i].X0.begin(), m.nodes[i].X0.end(), row);
    const Mat3 Ri = i < static_cast<int>(R.size()) ? R[i] : identity3();
    std::copy(Ri.begin(), Ri.end(), row + 3);
  }
  for (int j = 0; j < nv; ++j) {
    const auto& [name, v] = d.vectors[static_cast<size_t>(j)];
    const PetscScalar* a = nullptr;
    if (VecGetArrayRead(v, &a)) throw std::runtime_error("checkpoint vector " + name + ": PETSc error");
    for (int i = 0; i < m.numOwnedNodes; ++i) {
      const LocalNode& n = m.nodes[i];
      double* row = &nt[static_cast<size_t>(i) * nodeCols + 12 + 6 * j];
      for (int k = 0; k < n.ndof; ++k)
        if (n.dof[k] >= 0 && n.dof[k] < m.numOwnedUnknowns) row[k] = a[n.dof[k]];
    }
    for (size_t e = 0; e < m.elements.size(); ++e) {
      const LocalElement& el = m.elements[e];
      if (el.firstMultiplier < 0) continue;
      const int nc = std::min(el.kernel->numConstraints(), 6);
      for (int c = 0; c < nc; ++c) et[e * elemCols + 6 * j + c] = a[el.firstMultiplier + c];
    }
    if (VecRestoreArrayRead(v, &a)) throw std::runtime_error("checkpoint vector " + name + ": PETSc error");
  }
  if (kernelColumns_ > 0)
    for (size_t e = 0; e < m.elements.size(); ++e) m.elements[e].kernel->saveCheckpoint(&et[e * elemCols + 6 * nv]);
  const std::string suffix = tableSuffix(d.vectors);
  file.writeStateTable(group + "/node" + suffix, nfe, nodeCols, nodeRows, nt);
  file.writeStateTable(group + "/element" + suffix, numFeElements_, elemCols, elemRows, et);
  if (d.formfindingRows > 0) {
    std::vector<double> ff(static_cast<size_t>(d.formfindingRows) * kFormFindingColumns, 0.0);
    std::copy_n(d.formfinding.begin(), std::min(d.formfinding.size(), ff.size()), ff.begin());
    file.writeStateArray(group + "/formfinding", ff, {d.formfindingRows, kFormFindingColumns});
  }
  if (d.pathSize > 0) {
    std::vector<double> pv(static_cast<size_t>(d.pathSize), 0.0);
    std::copy_n(d.path.begin(), std::min(d.path.size(), pv.size()), pv.begin());
    file.writeStateArray(group + "/path", pv, {d.pathSize});
  }
  file.writeStateArray(group + "/scalars", d.scalars, {kNumScalars});
}

// ---------------------------------------------------------------- reader

CheckpointReader::CheckpointReader(MPI_Comm comm, const std::string& path, const std::string& group)
    : comm_(comm), path_(path), group_(group) {
  // every rank opens the file on its own (read-only, default driver): reads are independent
  int ok = 1;
  std::string error;
  hid_t f = -1;
  H5E_BEGIN_TRY { f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT); }
  H5E_END_TRY;
  ok = f >= 0;
  MPI_Allreduce(MPI_IN_PLACE, &ok, 1, MPI_INT, MPI_LAND, comm);
  if (!ok) {
    if (f >= 0) H5Fclose(f);
    throw std::runtime_error("cannot open " + path + " as an HDF5 result file");
  }
  file_ = f;
  if (!linkExists(f, group_) || !linkExists(f, group_ + "/scalars"))
    throw std::runtime_error(path + " has no checkpoint (/" + group_ + "): it was not written by a run that can be continued "
                                    "(no step was written, or -showinputonly)");
  h5::Handle g(H5Gopen2(f, group_.c_str(), H5P_DEFAULT), H5Gclose, path + ": group /" + group_);
  fingerprint_ = readTextAttribute(g, "fingerprint", path + ": /checkpoint fingerprint");
  h5::Handle ds(H5Dopen2(f, (group_ + "/scalars").c_str(), H5P_DEFAULT), H5Dclose, path + ": /" + group_ + "/scalars");
  const auto dims = datasetDims(ds, "/" + group_ + "/scalars");
  if (dims.size() != 1 || dims[0] != hsize_t(kNumScalars))
    throw std::runtime_error(path + ": /" + group_ + "/scalars has another layout (written by another Sinew version)");
  h5::check(H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, scalars_.data()), path + ": scalars");
  try {
    checkScalars();
  } catch (...) {  // the destructor of a throwing constructor does not run
    H5Fclose(f);
    file_ = -1;
    throw;
  }
  if (checkpointVectors(phase()).empty()) throw std::runtime_error(path + ": /" + group_ + ": unknown phase");
  const std::string nt = table("node"), et = table("element");
  h5::Handle dn(H5Dopen2(f, nt.c_str(), H5P_DEFAULT), H5Dclose, path + ": /" + nt);
  feNodes_ = static_cast<long>(datasetDims(dn, "/" + nt)[0]);
  h5::Handle de(H5Dopen2(f, et.c_str(), H5P_DEFAULT), H5Dclose, path + ": /" + et);
  feElements_ = static_cast<long>(datasetDims(de, "/" + et)[0]);
}

// A damaged or hand-edited checkpoint must not reach the step loops: a count beyond an int wraps
// (steps done 1e15 became -2147483647, and the run wrote rows for ever). Every scalar is finite and
// every count an integer in its range; rows at most the step rows the file holds.
void CheckpointReader::checkScalars() const {
  std::istringstream words(kScalarNames);
  const std::vector<std::string> names{std::istream_iterator<std::string>(words), std::istream_iterator<std::string>()};
  const auto bad = [&](int i, const std::string& expected) {
    std::ostringstream m;
    m << path_ << ": /" << group_ << "/scalars: " << (static_cast<size_t>(i) < names.size() ? names[static_cast<size_t>(i)] : "scalar")
      << " (entry " << i << " of attribute scalar_names) = " << scalars_[static_cast<size_t>(i)] << ", expected " << expected
      << "; the checkpoint is damaged (not as a Sinew run wrote it)";
    throw std::runtime_error(m.str());
  };
  for (int i = 0; i < kNumScalars; ++i)
    if (!std::isfinite(scalars_[static_cast<size_t>(i)])) bad(i, "a finite number");
  const auto count = [&](int i, double lo, double hi) {
    const double v = scalars_[static_cast<size_t>(i)];
    if (!(v >= lo && v <= hi && v == std::floor(v))) {
      std::ostringstream e;
      e << "an integer in " << lo << ".." << hi;
      bad(i, e.str());
    }
  };
  count(kCkPhase, 1, 4);
  count(kCkStep, 0, scene::kMaxTimeSteps);  // the largest count of any phase
  count(kCkLoadsteps, 0, scene::kMaxTimeSteps);
  count(kCkSuccesses, 0, scene::kMaxTimeSteps);
  count(kCkFormFinding, 0, 1);
  count(kCkLoadRamp, 0, 1);
  long rows = 0;  // step rows the file holds: its /load_factor or /time
  for (const char* name : {"load_factor", "time"})
    if (linkExists(static_cast<hid_t>(file_), name)) {
      h5::Handle d(H5Dopen2(static_cast<hid_t>(file_), name, H5P_DEFAULT), H5Dclose, path_ + ": /" + name);
      rows = std::max(rows, static_cast<long>(datasetDims(d, name)[0]));
    }
  count(kCkRows, 0, static_cast<double>(rows));
}

CheckpointReader::~CheckpointReader() {
  if (file_ >= 0) H5Fclose(static_cast<hid_t>(file_));
}

bool CheckpointReader::exists(const std::string& name) const {
  const hid_t f = static_cast<hid_t>(file_);
  for (size_t pos = 0;;) {
    pos = name.find('/', pos + 1);
    if (!linkExists(f, name.substr(0, pos))) return false;
    if (pos == std::string::npos) return true;
  }
}

std::vector<std::string> checkpointVectors(CheckpointPhase p) {
  switch (p) {
    case CheckpointPhase::FormFinding: return {"U"};
    case CheckpointPhase::Statics: return {"U", "dU"};
    case CheckpointPhase::Dynamics: return {"U", "V", "A", "Qdd"};
    case CheckpointPhase::Continuation: return {"U", "dU"};
  }
  return {};
}

std::string CheckpointReader::sceneText() const {
  const hid_t f = static_cast<hid_t>(file_);
  if (H5Aexists(f, "scene") <= 0) return {};
  try {
    return readTextAttribute(f, "scene", path_ + ": scene attribute");
  } catch (const std::exception&) {
    return {};
  }
}

std::string CheckpointReader::table(const char* kind) const {
  std::string s = group_ + "/" + kind;
  for (const std::string& v : checkpointVectors(phase())) s += "_" + v;
  return s;
}

bool CheckpointReader::hasVector(const std::string& name) const {
  const auto names = checkpointVectors(phase());
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::vector<double> CheckpointReader::readRows(const std::string& name, const std::vector<long>& rows, int first,
                                               int m) const {
  const std::string what = path_ + ": /" + name;
  h5::Handle d(H5Dopen2(static_cast<hid_t>(file_), name.c_str(), H5P_DEFAULT), H5Dclose, what);
  const auto dims = datasetDims(d, what);
  if (dims.size() != 2 || dims[1] < hsize_t(first + m)) throw std::runtime_error(what + ": unexpected shape");
  std::vector<hsize_t> coords;
  coords.reserve(rows.size() * static_cast<size_t>(m) * 2);
  for (long r : rows) {
    if (r < 0 || hsize_t(r) >= dims[0]) throw std::runtime_error(what + ": row " + std::to_string(r) + " missing");
    for (int j = 0; j < m; ++j) {
      coords.push_back(hsize_t(r));
      coords.push_back(hsize_t(first + j));
    }
  }
  return readPoints(d, coords, 2, what);
}

std::vector<double> CheckpointReader::pathState() const {
  if (!exists(group_ + "/path")) return {};
  std::vector<long> shape;
  return readArray(group_ + "/path", &shape);
}

std::vector<double> CheckpointReader::formfinding() const {
  if (!exists(group_ + "/formfinding")) return {};
  std::vector<long> shape;
  return readArray(group_ + "/formfinding", &shape);
}

PetscErrorCode CheckpointReader::loadVector(const std::string& name, Assembler& assembler, Vec v) const {
  PetscFunctionBeginUser;
  const DistributedMesh& m = assembler.mesh();
  std::vector<long> nodeRows, elemRows;
  for (int i = 0; i < m.numOwnedNodes; ++i) nodeRows.push_back(m.nodes[i].gid);
  for (const LocalElement& el : m.elements) elemRows.push_back(el.feIndex);
  const auto names = checkpointVectors(phase());
  const int j = static_cast<int>(std::find(names.begin(), names.end(), name) - names.begin());
  if (j == static_cast<int>(names.size())) throw std::runtime_error(path_ + ": no vector " + name + " in the checkpoint");
  const std::vector<double> nv = readRows(table("node"), nodeRows, 12 + 6 * j, 6);
  const std::vector<double> ev = readRows(table("element"), elemRows, 6 * j, 6);
  PetscCall(VecSet(v, 0.0));
  PetscScalar* a = nullptr;
  PetscCall(VecGetArray(v, &a));
  for (int i = 0; i < m.numOwnedNodes; ++i) {
    const LocalNode& n = m.nodes[i];
    for (int k = 0; k < n.ndof; ++k)
      if (n.dof[k] >= 0 && n.dof[k] < m.numOwnedUnknowns) a[n.dof[k]] = nv[6 * i + k];
  }
  for (size_t e = 0; e < m.elements.size(); ++e) {
    const LocalElement& el = m.elements[e];
    if (el.firstMultiplier < 0) continue;
    const int nc = std::min(el.kernel->numConstraints(), 6);
    for (int c = 0; c < nc; ++c) a[el.firstMultiplier + c] = ev[6 * e + c];
  }
  PetscCall(VecRestoreArray(v, &a));
  PetscCall(VecGhostUpdateBegin(v, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGhostUpdateEnd(v, INSERT_VALUES, SCATTER_FORWARD));
  PetscFunctionReturn(PETSC_SUCCESS);
}

void CheckpointReader::loadNodes(Assembler& assembler) const {
  DistributedMesh& m = assembler.mesh();
  std::vector<long> rows;
  for (const LocalNode& n : m.nodes) rows.push_back(n.gid);
  const std::vector<double> x0 = readRows(table("node"), rows, 0, 3);
  const std::vector<double> rr = readRows(table("node"), rows, 3, 9);
  std::vector<Mat3> R = assembler.referenceRotations();
  for (size_t i = 0; i < m.nodes.size(); ++i) {
    for (int k = 0; k < 3; ++k) m.nodes[i].X0[k] = x0[3 * i + k];
    if (i < R.size()) std::copy_n(rr.begin() + static_cast<long>(9 * i), 9, R[i].begin());
  }
  assembler.setReferenceRotations(R);
}

void CheckpointReader::loadKernels(Assembler& assembler) const {
  DistributedMesh& m = assembler.mesh();
  int k = 0;
  for (const LocalElement& el : m.elements) k = std::max(k, el.kernel->checkpointSize());
  MPI_Allreduce(MPI_IN_PLACE, &k, 1, MPI_INT, MPI_MAX, m.comm);
  if (k == 0) return;
  std::vector<long> rows;
  for (const LocalElement& el : m.elements) rows.push_back(el.feIndex);
  const int first = 6 * static_cast<int>(checkpointVectors(phase()).size());
  const std::vector<double> kv = readRows(table("element"), rows, first, k);
  for (size_t e = 0; e < m.elements.size(); ++e)
    if (m.elements[e].kernel->checkpointSize() > 0) m.elements[e].kernel->loadCheckpoint(&kv[e * k]);
}

std::vector<std::string> CheckpointReader::stepDatasets() const {
  std::vector<std::string> all, steps;
#if H5_VERSION_GE(1, 12, 0)
  h5::check(H5Ovisit3(static_cast<hid_t>(file_), H5_INDEX_NAME, H5_ITER_INC, collectDatasets, &all, H5O_INFO_BASIC),
            path_ + ": list datasets");
#else
  h5::check(H5Ovisit2(static_cast<hid_t>(file_), H5_INDEX_NAME, H5_ITER_INC, collectDatasets, &all, H5O_INFO_BASIC),
            path_ + ": list datasets");
#endif
  for (const std::string& name : all) {
    if (name.rfind("checkpoint", 0) == 0) continue;
    h5::Handle d(H5Dopen2(static_cast<hid_t>(file_), name.c_str(), H5P_DEFAULT), H5Dclose, path_ + ": /" + name);
    std::vector<hsize_t> mx;
    const auto dims = datasetDims(d, name, &mx);
    if (!dims.empty() && mx[0] == H5S_UNLIMITED) steps.push_back(name);
  }
  return steps;
}

std::vector<double> CheckpointReader::readStepRow(const std::string& name, int step, const std::vector<long>* rows2,
                                                  std::vector<long>* inner) const {
  const std::string what = path_ + ": /" + name;
  h5::Handle d(H5Dopen2(static_cast<hid_t>(file_), name.c_str(), H5P_DEFAULT), H5Dclose, what);
  const auto dims = datasetDims(d, what);
  const int r = static_cast<int>(dims.size());
  inner->assign(dims.begin() + 1, dims.end());
  if (r == 1) {
    std::vector<hsize_t> c{hsize_t(step)};
    return readPoints(d, c, 1, what);
  }
  // rows2: rows of the second axis (a node/element/mesh table); nullptr: the whole step row
  std::vector<long> second;
  if (rows2) {
    second = *rows2;
  } else {
    second.resize(static_cast<size_t>(dims[1]));
    std::iota(second.begin(), second.end(), 0L);
  }
  hsize_t m = 1;
  for (int i = 2; i < r; ++i) m *= dims[static_cast<size_t>(i)];
  std::vector<hsize_t> coords;
  coords.reserve(second.size() * m * static_cast<size_t>(r));
  for (long row : second)
    for (hsize_t j = 0; j < m; ++j) {
      coords.push_back(hsize_t(step));
      coords.push_back(hsize_t(row));
      hsize_t rest = j;
      std::vector<hsize_t> idx(static_cast<size_t>(r - 2));
      for (int i = r - 1; i >= 2; --i) {
        idx[static_cast<size_t>(i - 2)] = rest % dims[static_cast<size_t>(i)];
        rest /= dims[static_cast<size_t>(i)];
      }
      coords.insert(coords.end(), idx.begin(), idx.end());
    }
  return readPoints(d, coords, r, what);
}

bool CheckpointReader::onAnalysisRows(const std::string& name) const {
  const std::string what = path_ + ": /" + name;
  h5::Handle d(H5Dopen2(static_cast<hid_t>(file_), name.c_str(), H5P_DEFAULT), H5Dclose, what);
  return h5::check(H5Aexists(d, "rows"), what + ": attribute rows") > 0;
}

std::vector<long> CheckpointReader::datasetShape(const std::string& name) const {
  const std::string what = path_ + ": /" + name;
  h5::Handle d(H5Dopen2(static_cast<hid_t>(file_), name.c_str(), H5P_DEFAULT), H5Dclose, what);
  const auto dims = datasetDims(d, what);
  return std::vector<long>(dims.begin(), dims.end());
}

std::vector<double> CheckpointReader::readArray(const std::string& name, std::vector<long>* shape) const {
  const std::string what = path_ + ": /" + name;
  h5::Handle d(H5Dopen2(static_cast<hid_t>(file_), name.c_str(), H5P_DEFAULT), H5Dclose, what);
  const auto dims = datasetDims(d, what);
  shape->assign(dims.begin(), dims.end());
  hsize_t n = 1;
  for (hsize_t x : dims) n *= x;
  std::vector<double> out(n);
  if (n > 0) h5::check(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), what + ": read");
  return out;
}

}  // namespace sinew
