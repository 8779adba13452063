// Parallel HDF5 result file (design.md section 3).
//
// Crash safety (docs/results.md, "Crash safety"): the file under the final name `path` is, from
// the first commit() on, always a complete HDF5 file holding every committed step, so a run killed
// at any moment (even by SIGKILL) leaves a file that h5py opens. HDF5 1.10 has no SWMR for
// parallel files, and a file being written is not consistent on disk between two H5Fflush calls,
// so the scheme keeps two copies and never writes into the one under the final name:
// - two HDF5 files are open, the "lead" (named `path.part`) and the "published" one (`path`);
// - every write goes to the lead at once (errors surface where they happen) and is recorded;
// - commit() flushes the lead (H5Fflush: metadata, superblock end-of-address), then rank 0 makes
//   it the published file by renames: link(path, path.part2), rename(path.part, path),
//   rename(path.part2, path.part). rename(2) is atomic, so `path` names one complete file at every
//   instant; the former published file replays the recorded writes since the last commit and
//   becomes the lead.
// Cost per commit: the step's writes a second time, one flush and three renames, independent of
// how many steps the file already holds; the disk holds two copies until close() deletes one.
// close() sets `converged`, closes the lead and publishes it the same way.
//
// Layout decisions that readers may rely on:
// - Step-indexed datasets are chunked, unlimited along the step axis, created at their first write
//   and extended at every beginStep, so each has exactly stepsWritten() rows. A row that was never
//   written (the field was created later, or skipped at a step) holds NaN, also the fill value.
// - writeStepRow: one value at the first write makes a [ns] dataset (unless asked for a table: /freq
//   and /buck are [ns, k] also for k = 1), several a [ns, k] one. k is
//   fixed at the first write; a later row with fewer values is padded with 0, one with more values
//   is an error.
// - Distributed rows (node, element, mesh fields) are written in two phases: an all-to-all moves
//   every owned row to the rank holding the contiguous block [n r / P, n (r + 1) / P) of that
//   table, which then writes one hyperslab. The exchange plan is built once per table.
// - /mesh/p0 (the reference geometry, layout.meshReference) is written at creation, so that every
//   published file has the geometry its XDMF names. Cell fields (/cell/<kind>/<quantity>) are
//   tables over the cells of one kind, rows in /mesh/<kind> order.
// - The XDMF (xdmf_writer.hpp: reference geometry + "displacement" /mesh/u, distinct times) is
//   written from the file just published, and only names datasets and rows that file holds; a later
//   file only adds rows and datasets, so an XDMF that was not rewritten stays valid.
// - Errors in arguments are detected on all ranks together (one allreduce per call) so that every
//   rank throws and none is left waiting in a collective HDF5 call. HDF5 failures of collective
//   calls (a full disk, a file-size limit) are agreed the same way and thrown as ResultFileError
//   naming the file, the dataset and the cause.
// This file holds the public ResultFile methods: each checks its arguments on all ranks together,
// then hands the write to the store of the two copies (Hdf5ResultFile::Impl, result_file_impl.hpp),
// which moves distributed rows with row plans (row_plan.hpp); the agreement helpers are in
// collective_agreement.hpp.
// Open MPI's deprecated C++ bindings warn under -Wcast-function-type when mpi.h is not a system
// header (plain -I from pkg-config); Sinew uses the C API only.
#ifndef OMPI_SKIP_MPICXX
#define OMPI_SKIP_MPICXX 1
#endif
#include "sinew/result_file.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <utility>

#include "output/collective_agreement.hpp"
#include "output/file_sync.hpp"
#include "output/result_file_impl.hpp"

namespace sinew {

using namespace result_io;
using collective::agree;
using collective::agreeStatus;
using collective::broadcastShape;
using collective::broadcastString;
using collective::product;
using collective::signatureOf;

ResultFileError::ResultFileError(const std::string& what) : std::runtime_error(what) {}

Hdf5ResultFile::Hdf5ResultFile(MPI_Comm comm, const std::string& path, const ResultLayout& layout)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // failures become ResultFileError, not stack dumps
  MPI_Comm_dup(comm, &m.comm);
  MPI_Comm_rank(m.comm, &m.rank);
  MPI_Comm_size(m.comm, &m.size);
  m.path = path;
  m.partPath = path + ".part";
  m.sparePath = path + ".part2";
  m.layout = layout;
  m.validateLayout();
  m.nodePlan = RowPlan::build(m.comm, layout.numNodes, layout.ownedNodes, "result file: owned nodes");
  m.elementPlan = RowPlan::build(m.comm, layout.numElements, layout.ownedElements, "result file: owned elements");
  m.meshPlan = RowPlan::build(m.comm, layout.numMeshNodes, layout.ownedMeshNodes, "result file: owned mesh nodes");
  m.computeCellOffsets();
  int withReference = !layout.meshReference.empty() || layout.ownedMeshNodes.empty();
  MPI_Allreduce(MPI_IN_PLACE, &withReference, 1, MPI_INT, MPI_LAND, m.comm);
  m.hasReference = withReference && layout.numMeshNodes > 0;
  const std::vector<double> reference =
      m.hasReference ? m.meshPlan.exchange(m.comm, layout.meshReference, 3) : std::vector<double>();

  m.createFile(m.sinks[0], m.partPath);
  m.createFile(m.sinks[1], m.sparePath);
  // Attributes are collective: every rank writes rank 0's values.
  long numbers[6] = {layout.ndof, layout.nranks, layout.nunknowns, layout.nnodedofs, layout.nconstraints, layout.inputOnly};
  MPI_Bcast(numbers, 6, MPI_LONG, 0, m.comm);
  const std::string version = broadcastString(m.comm, layout.version), scene = broadcastString(m.comm, layout.scene);
  m.apply([&m, numbers, version, scene, reference](Sink& s) {
    h5::writeAttribute(s.file, "version", version);
    h5::writeAttribute(s.file, "ndof", numbers[0]);
    h5::writeAttribute(s.file, "nranks", static_cast<int>(numbers[1]));
    h5::writeAttribute(s.file, "nunknowns", numbers[2]);
    h5::writeAttribute(s.file, "nnodedofs", numbers[3]);
    h5::writeAttribute(s.file, "nconstraints", numbers[4]);
    if (numbers[5]) h5::writeAttribute(s.file, "showinputonly", 1);
    h5::writeAttribute(s.file, "scene", scene);
    h5::writeAttribute(s.file, "converged", 0);
    m.writeCells(s);
    if (m.hasReference) m.writeReference(s, reference);
  });
  commit();
}

Hdf5ResultFile::~Hdf5ResultFile() {
  if (!impl_ || impl_->closed) return;
  try {
    close(false);
  } catch (const std::exception& e) {
    std::cerr << "sinew: closing result file " << impl_->path << " failed: " << e.what() << "\n";
  }
}

void Hdf5ResultFile::beginStep(int step, double stepValue) {
  Impl& m = *impl_;
  const std::string what = "dataset /" + m.layout.stepName;
  std::string error = m.stateError(false);
  if (error.empty() && step != m.numSteps())
    error = "step " + std::to_string(step) + " does not follow step " + std::to_string(m.numSteps() - 1);
  agree(m.comm, error, signatureOf(m.layout.stepName, {step}, 10), what);
  m.analysisOpen = false;
  m.apply([&m, step, stepValue](Sink& s) { m.beginStepIn(s, step, stepValue); });
}

void Hdf5ResultFile::beginAnalysisRow() {
  Impl& m = *impl_;
  const std::string what = std::string("dataset /") + kAnalysisRowsName;
  std::string error = m.stateError(true);
  const std::vector<long>& rows = m.leadSink().analysisRows;
  if (error.empty() && m.analysisOpen) error = "a step-analysis row is already open";
  if (error.empty() && !rows.empty() && rows.back() >= m.numSteps() - 1)
    error = "step " + std::to_string(m.numSteps() - 1) + " already has a step-analysis row";
  agree(m.comm, error, signatureOf(kAnalysisRowsName, {m.numSteps()}, 15), what);
  m.analysisOpen = true;
  m.apply([&m](Sink& s) { m.beginAnalysisRowIn(s); });
}

void Hdf5ResultFile::endAnalysisRow() { impl_->analysisOpen = false; }

const std::vector<long>& Hdf5ResultFile::analysisRows() const { return impl_->leadSink().analysisRows; }

void Hdf5ResultFile::writeNodeField(const std::string& name, std::span<const double> values, std::vector<long> inner) {
  impl_->writeTable(Kind::Node, name, values, std::move(inner));
}

void Hdf5ResultFile::writeElementField(const std::string& name, std::span<const double> values, std::vector<long> inner) {
  impl_->writeTable(Kind::Element, name, values, std::move(inner));
}

void Hdf5ResultFile::writeMeshField(const std::string& name, std::span<const double> values, std::vector<long> inner) {
  impl_->writeTable(Kind::Mesh, name, values, std::move(inner));
}

void Hdf5ResultFile::writeCellField(const std::string& cells, const std::string& quantity, std::span<const double> values,
                                std::vector<long> inner) {
  Kind kind = Kind::Lines;
  if (cells == "triangles") kind = Kind::Triangles;
  else if (cells == "quads") kind = Kind::Quads;
  else if (cells != "lines") throw std::invalid_argument("cell field " + quantity + ": unknown cell kind " + cells);
  impl_->writeTable(kind, "cell/" + cells + "/" + quantity, values, std::move(inner));
}

const std::vector<long>& Hdf5ResultFile::ownedCellRows(const std::string& cells) const {
  const int k = cells == "lines" ? 0 : (cells == "triangles" ? 1 : 2);
  return impl_->ownedCells[k];
}

void Hdf5ResultFile::writeStepRow(const std::string& rawName, std::span<const double> values, bool table) {
  Impl& m = *impl_;
  const std::string name = normalized(rawName);
  const std::string what = "dataset /" + name;
  long k = static_cast<long>(values.size());
  MPI_Bcast(&k, 1, MPI_LONG, 0, m.comm);
  std::string error = m.stateError(true);
  const auto& steps = m.leadSink().steps;
  auto it = steps.find(name);
  if (error.empty()) {
    if (it != steps.end()) {
      if (it->second.kind != Kind::Row || name == m.layout.stepName)
        error = std::string("exists as a ") + kindName(it->second.kind);
      else if (k > it->second.rowLength)
        error = std::to_string(k) + " values, more than the " + std::to_string(it->second.rowLength) +
                " of its first row";
      else
        error = m.axisError(it->second);
    } else {
      error = m.nameError(name);
    }
  }
  agree(m.comm, error, signatureOf(name, {}, 3), what);
  if (it == steps.end() && k == 0) return;  // nothing fixes the row length yet; rows stay NaN

  std::vector<double> row(m.rank == 0 ? values.begin() : values.end(), values.end());
  m.apply([&m, name, k, table, axis = m.analysisOpen, row = std::move(row)](Sink& s) {
    auto found = s.steps.find(name);
    StepDataset& sd = found != s.steps.end()
                          ? found->second
                          : m.createStepDataset(s, name, Kind::Row, k == 1 && !table ? std::vector<long>{} : std::vector<long>{k}, k, axis);
    const int step = s.numRows(sd) - 1;
    std::vector<double> padded(sd.rowLength, 0.0);  // shorter rows are padded with 0
    std::copy(row.begin(), row.end(), padded.begin());
    std::vector<hsize_t> start{hsize_t(step)}, count{1};
    if (!sd.inner.empty()) {
      start.push_back(0);
      count.push_back(hsize_t(sd.rowLength));
    }
    m.writeBox(s, sd.dset, H5T_NATIVE_DOUBLE, start, count, m.rank == 0 ? padded.data() : nullptr, "dataset /" + name);
    sd.written[step] = 1;
  });
}

void Hdf5ResultFile::writeArray(const std::string& rawName, std::span<const double> values, std::vector<long> shape) {
  Impl& m = *impl_;
  const std::string name = normalized(rawName);
  const std::string what = "dataset /" + name;
  const std::string shapeError = broadcastShape(m.comm, values.size(), shape, 0);
  std::string error = m.stateError(false);
  if (!shapeError.empty()) error = shapeError;
  if (error.empty()) error = m.nameError(name);
  agree(m.comm, error, signatureOf(name, shape, 4), what);

  std::vector<double> data(m.rank == 0 ? values.begin() : values.end(), values.end());
  m.apply([&m, name, shape, data = std::move(data)](Sink& s) {
    const std::string w = "dataset /" + name;
    std::vector<hsize_t> dims(shape.begin(), shape.end()), start(dims.size(), 0);
    h5::Handle space = h5::dataspace(dims, w);
    h5::Handle lcpl = h5::intermediateGroupLcpl(w);
    const hid_t id = H5Dcreate2(s.file, name.c_str(), H5T_IEEE_F64LE, space, lcpl, H5P_DEFAULT, H5P_DEFAULT);
    agreeStatus(m.comm, id, w + ": create", s.name);
    h5::Handle dset(id, H5Dclose, w + ": create");
    // an empty array (no form-finding step converged) has no storage to write
    if (product(shape) > 0) m.writeBox(s, dset, H5T_NATIVE_DOUBLE, start, dims, m.rank == 0 ? data.data() : nullptr, w);
    h5::check(dset.reset(), w + ": close");
  });
}

void Hdf5ResultFile::writeStateTable(const std::string& rawName, long numRows, long m, std::span<const long> rows,
                                 std::span<const double> values) {
  Impl& im = *impl_;
  const std::string name = normalized(rawName);
  const std::string what = "dataset /" + name;
  std::string error = im.stateError(false);
  if (error.empty() && (m < 1 || numRows < 0)) error = "shape [" + std::to_string(numRows) + ", " + std::to_string(m) + "]";
  if (error.empty() && values.size() != rows.size() * std::size_t(m))
    error = std::to_string(values.size()) + " values for " + std::to_string(rows.size()) + " rows of " + std::to_string(m);
  if (error.empty() && name.empty()) error = "empty dataset name";
  if (error.empty() && im.leadSink().steps.count(name)) error = "exists as a step dataset";
  agree(im.comm, error, signatureOf(name, {numRows, m}, 12), what);
  auto it = im.statePlans.find(name);
  if (it == im.statePlans.end())
    it = im.statePlans.emplace(name, RowPlan::build(im.comm, numRows, std::vector<long>(rows.begin(), rows.end()), what)).first;
  const RowPlan& p = it->second;
  im.apply([&im, name, numRows, m, begin = p.begin, count = p.count, block = p.exchange(im.comm, values, m)](Sink& s) {
    const hid_t d = im.stateDataset(s, name, {hsize_t(numRows), hsize_t(m)});
    im.writeBox(s, d, H5T_NATIVE_DOUBLE, {hsize_t(begin), 0}, {hsize_t(count), hsize_t(m)}, count > 0 ? block.data() : nullptr,
                "dataset /" + name);
  });
}

void Hdf5ResultFile::writeStateArray(const std::string& rawName, std::span<const double> values, std::vector<long> shape) {
  Impl& im = *impl_;
  const std::string name = normalized(rawName);
  const std::string what = "dataset /" + name;
  const std::string shapeError = broadcastShape(im.comm, values.size(), shape, 1);
  std::string error = im.stateError(false);
  if (!shapeError.empty()) error = shapeError;
  if (error.empty() && im.leadSink().steps.count(name)) error = "exists as a step dataset";
  agree(im.comm, error, signatureOf(name, shape, 13), what);
  std::vector<double> data(im.rank == 0 ? values.begin() : values.end(), values.end());
  im.apply([&im, name, shape, data = std::move(data)](Sink& s) {
    const std::vector<hsize_t> dims(shape.begin(), shape.end());
    const hid_t d = im.stateDataset(s, name, dims);
    im.writeBox(s, d, H5T_NATIVE_DOUBLE, std::vector<hsize_t>(dims.size(), 0), dims, im.rank == 0 ? data.data() : nullptr,
                "dataset /" + name);
  });
}

void Hdf5ResultFile::writeStateAttribute(const std::string& rawGroup, const std::string& attr, const std::string& text) {
  Impl& im = *impl_;
  const std::string group = normalized(rawGroup);
  agree(im.comm, im.stateError(false), signatureOf(group + "@" + attr, {}, 14), "group /" + group);
  const std::string value = broadcastString(im.comm, text);
  im.apply([&im, group, attr, value](Sink& s) {
    const std::string what = "group /" + group;
    h5::Handle g;
    htri_t exists = 0;  // a group of step datasets (/path) is opened too
    H5E_BEGIN_TRY { exists = H5Lexists(s.file, group.c_str(), H5P_DEFAULT); }
    H5E_END_TRY;
    if (s.stateGroups.count(group) || exists > 0) {
      g = h5::Handle(H5Gopen2(s.file, group.c_str(), H5P_DEFAULT), H5Gclose, what + ": open");
      s.stateGroups.insert(group);
    } else {
      h5::Handle lcpl = h5::intermediateGroupLcpl(what);
      const hid_t id = H5Gcreate2(s.file, group.c_str(), lcpl, H5P_DEFAULT, H5P_DEFAULT);
      agreeStatus(im.comm, id, what + ": create", s.name);
      g = h5::Handle(id, H5Gclose, what + ": create");
      s.stateGroups.insert(group);
    }
    h5::writeAttribute(g, attr, value);
  });
}

void Hdf5ResultFile::commit() {
  Impl& m = *impl_;
  agree(m.comm, m.stateError(false), signatureOf("commit", {}, 11), "result file " + m.path + ": commit");
  try {
    Sink& lead = m.leadSink();
    m.fillAll(lead);
    // A full disk inside H5Fflush can leave the ranks in different collective calls of HDF5's
    // metadata flush (one fails a write and leaves, the others wait in its barrier): rank 0 checks
    // the free space first and the commit fails on every rank with "no space left" while the last
    // published state stays the file's content.
    {
      std::string error;
      if (m.rank == 0) {
        namespace fs = std::filesystem;
        std::error_code ec;
        const fs::path dir = fs::absolute(fs::path(m.path), ec).parent_path();
        const fs::space_info space = fs::space(dir, ec);
        // a new chunk (up to kChunkBytes) per copy may be allocated by the next step's writes
        const std::uintmax_t reserve = kChunkBytes + 2 * m.stepBytes;
        if (!ec && space.available < reserve)
          error = "no space left on device (" + std::to_string(space.available) + " bytes free on the file system of " +
                  dir.string() + ", a commit needs about " + std::to_string(reserve) + ")";
      }
      error = broadcastString(m.comm, error);
      if (!error.empty()) {
        m.failed = true;
        throw ResultFileError("result file " + m.path + ": " + error);
      }
    }
    // fsync only every syncInterval seconds, and only on one process: with several, HDF5's flush
    // relies on the collective MPI_File_sync to bring every rank out of the flush together when one
    // of them fails (a full disk left the others waiting in the flush's barrier without it)
    const double now = MPI_Wtime();
    const int sync = m.size > 1 || m.syncInterval <= 0 || now - m.lastSync >= m.syncInterval;  // 1 on every rank when several
    {
      FileSyncSkip skip(!sync);
      agreeStatus(m.comm, H5Fflush(lead.file, H5F_SCOPE_GLOBAL), "flush", lead.name);
    }
    if (sync) m.lastSync = now;
    if (m.rank == 0) {
      std::error_code ec;
      const std::uintmax_t bytes = std::filesystem::file_size(lead.name, ec);
      if (!ec) {
        if (bytes > m.leadBytes && m.leadBytes > 0) m.stepBytes = std::max(m.stepBytes, bytes - m.leadBytes);
        m.leadBytes = bytes;
      }
    }
    ++m.commits;
    m.syncedCommits += sync;
    m.publishLead(true);
    // the former published file catches up and takes the next writes
    m.lead = 1 - m.lead;
    for (const Impl::Op& op : m.log) op(m.leadSink());
    m.log.clear();
  } catch (...) {
    m.failed = true;
    throw;
  }
}

long Hdf5ResultFile::commits() const { return impl_->commits; }
long Hdf5ResultFile::syncedCommits() const { return impl_->syncedCommits; }

void Hdf5ResultFile::setSyncInterval(double seconds) {
  impl_->syncInterval = seconds;
  impl_->lastSync = MPI_Wtime();
  impl_->commits = impl_->syncedCommits = 0;  // counted from here (the creation's commit is not)
}

void Hdf5ResultFile::close(bool converged) {
  Impl& m = *impl_;
  if (m.closed) return;
  m.closed = true;
  int ok = converged ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &ok, 1, MPI_INT, MPI_LAND, m.comm);
  if (m.failed) {  // the published file keeps the last committed state (converged = 0)
    m.sinks[0].closeHandles();
    m.sinks[1].closeHandles();
    if (m.rank == 0) {
      std::error_code ec;
      std::filesystem::remove(m.partPath, ec);
      std::filesystem::remove(m.sparePath, ec);
    }
    return;
  }
  try {
    Sink& lead = m.leadSink();
    m.fillAll(lead);
    h5::writeAttribute(lead.file, "converged", ok);
    agreeStatus(m.comm, lead.analysisRowsDset.reset(), std::string("dataset /") + kAnalysisRowsName + ": close", lead.name);
    for (auto& [name, sd] : lead.steps) agreeStatus(m.comm, sd.dset.reset(), "dataset /" + name + ": close", lead.name);
    for (auto& [name, d] : lead.state) agreeStatus(m.comm, d.reset(), "dataset /" + name + ": close", lead.name);
    h5::check(lead.dxpl.reset(), "file " + lead.name + ": transfer list");
    agreeStatus(m.comm, lead.file.reset(), "close", lead.name);
    m.publishLead(false);
  } catch (...) {
    m.failed = true;
    m.sinks[0].closeHandles();
    m.sinks[1].closeHandles();
    if (m.rank == 0) {
      std::error_code ec;
      std::filesystem::remove(m.partPath, ec);
      std::filesystem::remove(m.sparePath, ec);
    }
    throw;
  }
  m.sinks[1 - m.lead].closeHandles();  // no longer under any name
}

const std::string& Hdf5ResultFile::path() const { return impl_->path; }

std::string Hdf5ResultFile::xdmfPath() const {
  return std::filesystem::path(impl_->path).replace_extension(".xdmf").string();
}

int Hdf5ResultFile::stepsWritten() const { return impl_->numSteps(); }

bool Hdf5ResultFile::failed() const { return impl_->failed; }

}  // namespace sinew
