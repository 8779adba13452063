// Member functions of Hdf5ResultFile::Impl (result_file_impl.hpp): creating the two files and their
// step-indexed and state datasets, the writes of table rows (each rank its own box), NaN filling of rows never
// written, the /mesh cell tables and reference geometry, and publishing the lead under the final
// name with its XDMF.
// Open MPI's deprecated C++ bindings warn under -Wcast-function-type when mpi.h is not a system
// header (plain -I from pkg-config); Sinew uses the C API only.
#ifndef OMPI_SKIP_MPICXX
#define OMPI_SKIP_MPICXX 1
#endif
#include "output/result_file_impl.hpp"

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <utility>

#include "output/collective_agreement.hpp"
#include "output/io_diagnosis.hpp"

namespace sinew {

using namespace result_io;
using collective::agree;
using collective::agreeStatus;
using collective::broadcastString;
using collective::product;
using collective::signatureOf;

void Hdf5ResultFile::Impl::apply(Op op) {
  try {
    op(leadSink());
  } catch (...) {
    failed = true;
    throw;
  }
  log.push_back(std::move(op));
}

void Hdf5ResultFile::Impl::writeBox(Sink& s, hid_t dset, hid_t memType, const std::vector<hsize_t>& start,
                                const std::vector<hsize_t>& count, const void* data, const std::string& what) {
  agreeStatus(comm, h5::writeBox(dset, memType, start, count, data, s.dxpl, what), what + ": write", s.name);
}

void Hdf5ResultFile::Impl::createFile(Sink& s, const std::string& name) {
  const std::string what = "file " + name;
  h5::Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, what + ": access list");
  h5::check(H5Pset_fapl_mpio(fapl, comm, MPI_INFO_NULL), what + ": MPI-IO driver");
  h5::check(H5Pset_all_coll_metadata_ops(fapl, 1), what + ": collective metadata reads");
  h5::check(H5Pset_coll_metadata_write(fapl, 1), what + ": collective metadata writes");
  const hid_t id = H5Fcreate(name.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
  agreeStatus(comm, id, "create", name);
  s.name = name;
  s.file = h5::Handle(id, H5Fclose, what + ": create");
  s.dxpl = h5::independentDxpl();
}

StepDataset& Hdf5ResultFile::Impl::createStepDataset(Sink& s, const std::string& name, Kind kind, std::vector<long> inner,
                                                  long rowLength, bool analysisAxis) {
  const std::string what = "dataset /" + name;
  const int rows = analysisAxis ? s.numAnalysisRows() : s.numSteps();
  std::vector<hsize_t> dims{hsize_t(rows)}, maxdims{H5S_UNLIMITED}, chunk;
  for (long d : inner) {
    dims.push_back(hsize_t(d));
    maxdims.push_back(d > 0 ? hsize_t(d) : H5S_UNLIMITED);
  }
  // Table datasets: one step per chunk, rows split to about kChunkBytes. Step rows: many steps
  // per chunk, since each row is small.
  std::size_t rowBytes = sizeof(double);
  for (std::size_t i = (kind == Kind::Row ? 0 : 1); i < inner.size(); ++i) rowBytes *= std::max(inner[i], 1L);
  if (kind == Kind::Row) {
    chunk.push_back(std::clamp<hsize_t>(kChunkBytes / rowBytes, 1, 256));
    for (long d : inner) chunk.push_back(hsize_t(std::max(d, 1L)));
  } else {
    chunk.push_back(1);
    chunk.push_back(std::clamp<hsize_t>(kChunkBytes / rowBytes, 1, hsize_t(std::max(inner[0], 1L))));
    for (std::size_t i = 1; i < inner.size(); ++i) chunk.push_back(hsize_t(inner[i]));
  }
  h5::Handle space = h5::dataspace(dims, maxdims, what);
  h5::Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, what + ": creation list");
  h5::check(H5Pset_chunk(dcpl, static_cast<int>(chunk.size()), chunk.data()), what + ": chunk");
  h5::check(H5Pset_fill_value(dcpl, H5T_NATIVE_DOUBLE, &kNaN), what + ": fill value");
  // Rows never written are set to NaN explicitly at each commit; skip filling every new chunk first.
  h5::check(H5Pset_fill_time(dcpl, H5D_FILL_TIME_NEVER), what + ": fill time");
  h5::Handle lcpl = h5::intermediateGroupLcpl(what);
  const hid_t id = H5Dcreate2(s.file, name.c_str(), H5T_IEEE_F64LE, space, lcpl, dcpl, H5P_DEFAULT);
  agreeStatus(comm, id, what + ": create", s.name);
  StepDataset sd;
  sd.kind = kind;
  sd.dset = h5::Handle(id, H5Dclose, what + ": create");
  sd.inner = std::move(inner);
  sd.written.assign(rows, 0);
  sd.filled.assign(rows, 0);
  sd.rowLength = rowLength;
  sd.analysisAxis = analysisAxis;
  if (analysisAxis) h5::writeAttribute(sd.dset, "rows", std::string(kAnalysisRowsName));  // readers: row j is step row step_analysis_rows[j]
  return s.steps.emplace(name, std::move(sd)).first->second;
}

std::string Hdf5ResultFile::Impl::axisError(const StepDataset& sd) const {
  if (sd.analysisAxis == analysisOpen) return "";
  return sd.analysisAxis ? "has one row per step-analysis row, written outside a step-analysis row"
                         : "has one row per step, written inside a step-analysis row";
}

std::string Hdf5ResultFile::Impl::stateError(bool needsStep) const {
  if (closed) return "file already closed";
  if (failed) return "an earlier write failed";
  if (needsStep && numSteps() == 0) return "written before the first beginStep";
  return "";
}

std::string Hdf5ResultFile::Impl::nameError(const std::string& name) const {
  if (name.empty()) return "empty dataset name";
  if (name == layout.stepName) return "name reserved for the step values";
  if (name == kAnalysisRowsName) return "name reserved for the rows of the step analyses";
  for (std::size_t pos = 0;;) {
    pos = name.find('/', pos + 1);
    const std::string prefix = name.substr(0, pos);
    if (h5::check(H5Lexists(leadSink().file, prefix.c_str(), H5P_DEFAULT), "dataset /" + name + ": lookup") <= 0)
      return "";
    if (pos == std::string::npos) return "dataset /" + name + " already exists";
  }
}

void Hdf5ResultFile::Impl::beginStepIn(Sink& s, int step, double stepValue) {
  const std::string what = "dataset /" + layout.stepName;
  if (step == 0) createStepDataset(s, layout.stepName, Kind::Row, {}, 1);
  s.stepValues.push_back(stepValue);
  for (auto& [name, sd] : s.steps) {
    if (sd.analysisAxis) continue;  // extended by beginAnalysisRowIn
    std::vector<hsize_t> dims{hsize_t(s.numSteps())};
    for (long d : sd.inner) dims.push_back(hsize_t(d));
    agreeStatus(comm, H5Dset_extent(sd.dset, dims.data()), "dataset /" + name + ": extend to step " + std::to_string(step),
                s.name);
    sd.written.push_back(0);
    sd.filled.push_back(0);
  }
  StepDataset& sv = s.steps.at(layout.stepName);
  writeBox(s, sv.dset, H5T_NATIVE_DOUBLE, {hsize_t(step)}, {1}, rank == 0 ? &stepValue : nullptr, what);
  sv.written[step] = 1;
}

void Hdf5ResultFile::Impl::beginAnalysisRowIn(Sink& s) {
  s.analysisRows.push_back(s.numSteps() - 1);
  const int row = s.numAnalysisRows() - 1;
  for (auto& [name, sd] : s.steps) {
    if (!sd.analysisAxis) continue;
    std::vector<hsize_t> dims{hsize_t(s.numAnalysisRows())};
    for (long d : sd.inner) dims.push_back(hsize_t(d));
    agreeStatus(comm, H5Dset_extent(sd.dset, dims.data()),
                "dataset /" + name + ": extend to step-analysis row " + std::to_string(row), s.name);
    sd.written.push_back(0);
    sd.filled.push_back(0);
  }
}

void Hdf5ResultFile::Impl::writeAnalysisRows(Sink& s) {
  const bool everyStep = s.numAnalysisRows() == s.numSteps();  // rows are increasing: then they are 0 .. ns - 1
  if (s.analysisRows.empty() || (everyStep && !s.analysisRowsDset.valid())) return;
  const std::string what = std::string("dataset /") + kAnalysisRowsName;
  const std::vector<hsize_t> dims{hsize_t(s.numAnalysisRows())};
  if (!s.analysisRowsDset.valid()) {
    const std::vector<hsize_t> maxdims{H5S_UNLIMITED}, chunk{256};
    h5::Handle space = h5::dataspace(std::vector<hsize_t>{0}, maxdims, what);
    h5::Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, what + ": creation list");
    h5::check(H5Pset_chunk(dcpl, 1, chunk.data()), what + ": chunk");
    const hid_t id = H5Dcreate2(s.file, kAnalysisRowsName, H5T_STD_I64LE, space, H5P_DEFAULT, dcpl, H5P_DEFAULT);
    agreeStatus(comm, id, what + ": create", s.name);
    s.analysisRowsDset = h5::Handle(id, H5Dclose, what + ": create");
  }
  agreeStatus(comm, H5Dset_extent(s.analysisRowsDset, dims.data()), what + ": extend", s.name);
  writeBox(s, s.analysisRowsDset, H5T_NATIVE_LONG, {0}, dims, rank == 0 ? s.analysisRows.data() : nullptr, what);
}

void Hdf5ResultFile::Impl::writeTable(Kind kind, const std::string& rawName, std::span<const double> values,
                                  std::vector<long> inner) {
  const std::string name = normalized(rawName);
  const std::string what = "dataset /" + name;
  std::string error = stateError(true);
  for (long d : inner)
    if (d < 1 && error.empty()) error = "inner dimension " + std::to_string(d) + " < 1";
  const long m = product(inner);
  if (error.empty() && values.size() != owned(kind).size() * std::size_t(m))
    error = std::to_string(values.size()) + " values for " + std::to_string(owned(kind).size()) + " rows of " +
            std::to_string(m);
  if (error.empty() && kind == Kind::Mesh && name == "mesh/p" && inner != std::vector<long>{3})
    error = "mesh/p must have inner shape {3}";
  std::vector<long> dims{tableRows(kind)};
  dims.insert(dims.end(), inner.begin(), inner.end());
  const auto& steps = leadSink().steps;
  auto it = steps.find(name);
  if (it == steps.end() && !closed && !failed) {
    const std::string e = nameError(name);  // on every rank: collective lookup
    if (error.empty()) error = e;
  } else if (error.empty() && it != steps.end() && (it->second.kind != kind || it->second.inner != dims)) {
    error = std::string("exists as a ") + kindName(it->second.kind) + " of another shape";
  } else if (error.empty() && it != steps.end()) {
    error = axisError(it->second);
  }
  agree(comm, error, signatureOf(name, dims, static_cast<int>(kind)), what);

  const RowPlan& p = plan(kind);
  apply([this, kind, name, dims, inner, axis = analysisOpen, block = p.exchange(comm, values, m)](Sink& s) {
    auto found = s.steps.find(name);
    StepDataset& sd = found != s.steps.end() ? found->second : createStepDataset(s, name, kind, dims, 1, axis);
    const RowPlan& pl = plan(kind);
    const int step = s.numRows(sd) - 1;
    std::vector<hsize_t> start{hsize_t(step), hsize_t(pl.begin)}, count{1, hsize_t(pl.count)};
    for (long d : inner) {
      start.push_back(0);
      count.push_back(hsize_t(d));
    }
    writeBox(s, sd.dset, H5T_NATIVE_DOUBLE, start, count, block.data(), "dataset /" + name);
    sd.written[step] = 1;
  });
}

void Hdf5ResultFile::Impl::fillUnwritten(Sink& s, const std::string& name, StepDataset& sd) {
  const std::string what = "dataset /" + name + ": NaN rows";
  const int rows = s.numRows(sd);
  for (int st = 0; st < rows;) {
    if (sd.written[st] || sd.filled[st]) {
      ++st;
      continue;
    }
    int e = st;
    while (e < rows && !sd.written[e] && !sd.filled[e]) ++e;
    std::vector<hsize_t> start{hsize_t(st)}, count{hsize_t(e - st)};
    bool mine = rank == 0;
    if (sd.kind != Kind::Row) {
      const RowPlan& p = plan(sd.kind);
      start.push_back(hsize_t(p.begin));
      count.push_back(hsize_t(p.count));
      mine = true;
    }
    for (std::size_t i = (sd.kind == Kind::Row ? 0 : 1); i < sd.inner.size(); ++i) {
      start.push_back(0);
      count.push_back(hsize_t(sd.inner[i]));
    }
    hsize_t n = 1;
    for (hsize_t c : count) n *= c;
    const std::vector<double> nan(mine ? n : 0, kNaN);
    writeBox(s, sd.dset, H5T_NATIVE_DOUBLE, start, count, mine ? nan.data() : nullptr, what);
    std::fill(sd.filled.begin() + st, sd.filled.begin() + e, 1);
    st = e;
  }
}

void Hdf5ResultFile::Impl::fillAll(Sink& s) {
  for (auto& [name, sd] : s.steps) fillUnwritten(s, name, sd);
  writeAnalysisRows(s);
}

void Hdf5ResultFile::Impl::computeCellOffsets() {
  const std::array<CellKind, 3> kinds = cellKinds();
  long local[3];
  for (int k = 0; k < 3; ++k) local[k] = static_cast<long>(kinds[k].conn->size()) / kinds[k].nodes;
  MPI_Allreduce(local, cellTotals, 3, MPI_LONG, MPI_SUM, comm);
  MPI_Exscan(local, cellOffsets, 3, MPI_LONG, MPI_SUM, comm);
  if (rank == 0) std::fill(cellOffsets, cellOffsets + 3, 0L);
  for (int k = 0; k < 3; ++k) {
    ownedCells[k].resize(static_cast<std::size_t>(local[k]));
    for (long c = 0; c < local[k]; ++c) ownedCells[k][c] = cellOffsets[k] + c;
    cellPlans[k] = RowPlan::build(comm, cellTotals[k], ownedCells[k], std::string("result file: ") + kinds[k].name);
  }
}

void Hdf5ResultFile::Impl::writeReference(Sink& s, const std::vector<double>& block) {
  const std::string what = "dataset /mesh/p0";
  std::vector<hsize_t> dims{hsize_t(layout.numMeshNodes), 3}, start{hsize_t(meshPlan.begin), 0},
      count{hsize_t(meshPlan.count), 3};
  h5::Handle space = h5::dataspace(dims, what);
  h5::Handle lcpl = h5::intermediateGroupLcpl(what);
  const hid_t id = H5Dcreate2(s.file, "mesh/p0", H5T_IEEE_F64LE, space, lcpl, H5P_DEFAULT, H5P_DEFAULT);
  agreeStatus(comm, id, what + ": create", s.name);
  h5::Handle dset(id, H5Dclose, what + ": create");
  writeBox(s, dset, H5T_NATIVE_DOUBLE, start, count, block.data(), what);
  h5::check(dset.reset(), what + ": close");
}

void Hdf5ResultFile::Impl::writeCells(Sink& s) {
  const std::array<CellKind, 3> kinds = cellKinds();
  h5::Handle lcpl = h5::intermediateGroupLcpl("/mesh");
  for (int k = 0; k < 3; ++k) {
    if (cellTotals[k] == 0) continue;
    const long local = static_cast<long>(kinds[k].conn->size()) / kinds[k].nodes;
    for (int part = 0; part < 2; ++part) {
      const std::string name = std::string("mesh/") + kinds[k].name + (part ? "_element" : "");
      const std::string what = "dataset /" + name;
      std::vector<hsize_t> dims{hsize_t(cellTotals[k])}, start{hsize_t(cellOffsets[k])}, count{hsize_t(local)};
      if (!part) {
        dims.push_back(hsize_t(kinds[k].nodes));
        start.push_back(0);
        count.push_back(hsize_t(kinds[k].nodes));
      }
      h5::Handle space = h5::dataspace(dims, what);
      const hid_t id = H5Dcreate2(s.file, name.c_str(), H5T_STD_I64LE, space, lcpl, H5P_DEFAULT, H5P_DEFAULT);
      agreeStatus(comm, id, what + ": create", s.name);
      h5::Handle dset(id, H5Dclose, what + ": create");
      const std::vector<long>& data = part ? *kinds[k].element : *kinds[k].conn;
      writeBox(s, dset, H5T_NATIVE_LONG, start, count, data.data(), what);
      h5::check(dset.reset(), what + ": close");
    }
    if (!layout.look) continue;
    // SPACAR Light's element look: /mesh/<kind>_color [*, 3], _opacity [*], _visible [*]
    for (const LookPart& lp : kLookParts) {
      const std::string name = std::string("mesh/") + kinds[k].name + lp.suffix;
      const std::string what = "dataset /" + name;
      std::vector<hsize_t> dims{hsize_t(cellTotals[k])}, start{hsize_t(cellOffsets[k])}, count{hsize_t(local)};
      if (lp.count > 1) {
        dims.push_back(hsize_t(lp.count));
        start.push_back(0);
        count.push_back(hsize_t(lp.count));
      }
      std::vector<double> data;
      for (long c = 0; c < local; ++c)
        for (int j = 0; j < lp.count; ++j) data.push_back((*kinds[k].look)[5 * static_cast<std::size_t>(c) + lp.first + j]);
      h5::Handle space = h5::dataspace(dims, what);
      const hid_t id = H5Dcreate2(s.file, name.c_str(), H5T_IEEE_F64LE, space, lcpl, H5P_DEFAULT, H5P_DEFAULT);
      agreeStatus(comm, id, what + ": create", s.name);
      h5::Handle dset(id, H5Dclose, what + ": create");
      writeBox(s, dset, H5T_NATIVE_DOUBLE, start, count, data.data(), what);
      h5::check(dset.reset(), what + ": close");
    }
  }
}

hid_t Hdf5ResultFile::Impl::stateDataset(Sink& s, const std::string& name, const std::vector<hsize_t>& dims) {
  auto it = s.state.find(name);
  if (it != s.state.end()) return it->second;
  const std::string what = "dataset /" + name;
  h5::Handle space = h5::dataspace(dims, what);
  h5::Handle lcpl = h5::intermediateGroupLcpl(what);
  const hid_t id = H5Dcreate2(s.file, name.c_str(), H5T_IEEE_F64LE, space, lcpl, H5P_DEFAULT, H5P_DEFAULT);
  agreeStatus(comm, id, what + ": create", s.name);
  return s.state.emplace(name, h5::Handle(id, H5Dclose, what + ": create")).first->second;
}

void Hdf5ResultFile::Impl::validateLayout() const {
  std::string error;
  auto fail = [&](const std::string& e) {
    if (error.empty()) error = e;
  };
  if (layout.stepName != "load_factor" && layout.stepName != "time")
    fail("stepName must be load_factor or time, not " + layout.stepName);
  if (layout.numNodes < 0 || layout.numElements < 0 || layout.numMeshNodes < 0) fail("negative table size");
  for (const CellKind& c : cellKinds()) {
    const std::size_t npe = std::size_t(c.nodes);
    if (c.conn->size() % npe || c.element->size() != c.conn->size() / npe)
      fail(std::string(c.name) + ": connectivity and element lists do not match");
    for (long id : *c.conn)
      if (id < 0 || id >= layout.numMeshNodes) fail(std::string(c.name) + ": node " + std::to_string(id) + " outside the mesh");
    if (layout.look && c.look->size() != 5 * c.element->size())
      fail(std::string(c.name) + ": look values do not match the cells");
  }
  if (!layout.meshReference.empty() && layout.meshReference.size() != 3 * layout.ownedMeshNodes.size())
    fail("meshReference: " + std::to_string(layout.meshReference.size()) + " values for " +
         std::to_string(layout.ownedMeshNodes.size()) + " owned mesh nodes");
  agree(comm, error, signatureOf(layout.stepName, {layout.numNodes, layout.numElements, layout.numMeshNodes}, 9),
        "result file " + path + ": layout");
}

XdmfDescription Hdf5ResultFile::Impl::xdmfDescription(const Sink& s) const {
  XdmfDescription d;
  d.h5Name = std::filesystem::path(path).filename().string();
  d.numMeshNodes = layout.numMeshNodes;
  d.stepValues = s.stepValues;
  d.stepName = layout.stepName;
  d.inputOnly = layout.inputOnly;
  if (hasReference) d.geometryDataset = "/mesh/p0";
  if (auto it = s.steps.find("formfinding/step"); it != s.steps.end()) d.formFindingRows = it->second.written;
  // a time integration from the end of the load steps (opt.dynamics start: static): the load-step
  // rows (/load_factor written, /time 0) come before the time rows, numbered as form-finding rows
  if (auto it = s.steps.find("load_factor"); layout.stepName == "time" && it != s.steps.end()) {
    const std::vector<char>& w = it->second.written;
    if (d.formFindingRows.size() < w.size()) d.formFindingRows.resize(w.size(), 0);
    for (std::size_t i = 0; i < w.size(); ++i) d.formFindingRows[i] = d.formFindingRows[i] || w[i];
  }
  const std::array<CellKind, 3> kinds = cellKinds();
  for (int k = 0; k < 3; ++k)
    if (cellTotals[k] > 0) {
      d.cells.push_back({kinds[k].name, kinds[k].topology, kinds[k].nodes, cellTotals[k],
                         std::string("/mesh/") + kinds[k].name, {}, {}});
      if (layout.look)  // static cell attributes: color (RGB, "Map Scalars" off), opacity, visible
        for (const LookPart& lp : kLookParts)
          d.cells.back().staticFields.push_back(
              {std::string(lp.suffix + 1), std::string("/mesh/") + kinds[k].name + lp.suffix,
               lp.count > 1 ? std::vector<long>{lp.count} : std::vector<long>{}, {}, {}, -1});
    }
  auto field = [](const std::string& name, const std::string& dataset, const StepDataset& sd) {
    XdmfField f;
    f.name = name;
    f.dataset = "/" + dataset;
    f.inner.assign(sd.inner.begin() + 1, sd.inner.end());
    f.written = sd.written;
    return f;
  };
  // the step row of each step-analysis row -> per step, the row of an analysis-axis dataset (or -1)
  std::vector<long> analysisRowOfStep(s.stepValues.size(), -1);
  for (std::size_t j = 0; j < s.analysisRows.size(); ++j)
    if (s.analysisRows[j] >= 0 && s.analysisRows[j] < static_cast<long>(analysisRowOfStep.size()))
      analysisRowOfStep[static_cast<std::size_t>(s.analysisRows[j])] = static_cast<long>(j);
  auto onRows = [&](XdmfField f, const StepDataset& sd) {
    if (sd.analysisAxis) {
      f.rowOfStep = analysisRowOfStep;
      f.numRows = s.numAnalysisRows();
    }
    return f;
  };
  for (const auto& [name, sd] : s.steps) {
    if (sd.kind == Kind::Mesh && name != "mesh/p") {
      // /mesh/u is the displacement from the reference geometry /mesh/p0
      d.pointFields.push_back(onRows(field(name == "mesh/u" ? "displacement" : name.substr(5), name, sd), sd));
    } else if (isCellKind(sd.kind)) {
      const std::string kind = kinds[cellIndex(sd.kind)].name;
      for (XdmfCellBlock& c : d.cells)
        if (c.name == kind) c.fields.push_back(onRows(field(name.substr(name.rfind('/') + 1), name, sd), sd));
    }
  }
  return d;
}

void Hdf5ResultFile::Impl::publishLead(bool keepOther) {
  std::string error;
  if (rank == 0) {
    try {
      namespace fs = std::filesystem;
      std::error_code ec;
      if (keepOther && published) {
        fs::remove(sparePath, ec);
        fs::create_hard_link(path, sparePath, ec);
        if (ec) throw std::runtime_error("cannot link " + path + " as " + sparePath + ": " + ec.message());
      }
      fs::rename(partPath, path, ec);
      if (ec) throw std::runtime_error("cannot rename " + partPath + " to " + path + ": " + ec.message());
      if (keepOther) {
        fs::rename(sparePath, partPath, ec);
        if (ec) throw std::runtime_error("cannot rename " + sparePath + " to " + partPath + ": " + ec.message());
      } else {
        fs::remove(sparePath, ec);
      }
      // The XDMF text grows with the steps: rewriting it at every commit would cost O(steps^2)
      // over a long run. It is rewritten when at least 10 times its last write time has passed
      // (at most ~10 % of the run), and always at close; between two rewrites it lists a prefix
      // of the steps of the file, which stays valid.
      const double now = MPI_Wtime();
      if (!keepOther || now - xdmfWritten >= 10 * xdmfSeconds) {
        const std::string xdmf = std::filesystem::path(path).replace_extension(".xdmf").string();
        try {
          writeXdmfFile(xdmf, xdmfDescription(leadSink()));
        } catch (const std::exception& e) {
          fs::remove(xdmf + ".part", ec);
          const std::string cause = ioFailureCause(xdmf);
          throw std::runtime_error(std::string(e.what()) + (cause.empty() ? "" : ": " + cause));
        }
        xdmfWritten = MPI_Wtime();
        xdmfSeconds = xdmfWritten - now;
      }
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  error = broadcastString(comm, error);
  if (!error.empty()) {
    failed = true;
    throw ResultFileError("result file " + path + ": " + error);
  }
  Sink& other = sinks[1 - lead];
  leadSink().name = path;
  other.name = partPath;
  published = true;
}
}  // namespace sinew
