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
// - writeStepRow: one value at the first write makes a [ns] dataset, several a [ns, k] one. k is
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
// Open MPI's deprecated C++ bindings warn under -Wcast-function-type when mpi.h is not a system
// header (plain -I from pkg-config); Sinew uses the C API only.
#ifndef OMPI_SKIP_MPICXX
#define OMPI_SKIP_MPICXX 1
#endif
#include "sinew/result_file.hpp"

#include <algorithm>
#include <array>
#include <climits>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <utility>
#include <stdexcept>

#include "output/hdf5_util.hpp"
#include "output/file_sync.hpp"
#include "output/io_diagnosis.hpp"
#include "output/xdmf_writer.hpp"

namespace sinew {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t kChunkBytes = std::size_t(1) << 20;  // target chunk size

long product(const std::vector<long>& v) {
  long p = 1;
  for (long x : v) p *= x;
  return p;
}

// writeArray/writeStateArray: rank 0's shape and number of values reach every rank (the others'
// arguments are ignored); "" or what is wrong with them (a dimension below minDim, a count that is
// not the shape's product).
std::string broadcastShape(MPI_Comm comm, std::size_t numValues, std::vector<long>& shape, long minDim) {
  long header[2] = {static_cast<long>(shape.size()), static_cast<long>(numValues)};
  MPI_Bcast(header, 2, MPI_LONG, 0, comm);
  shape.resize(static_cast<std::size_t>(header[0]));
  MPI_Bcast(shape.data(), static_cast<int>(shape.size()), MPI_LONG, 0, comm);
  for (long d : shape)
    if (d < minDim) return minDim == 0 ? "negative dimension" : "dimension < " + std::to_string(minDim);
  if (product(shape) != header[1]) return std::to_string(header[1]) + " values on rank 0 for " + std::to_string(product(shape));
  return "";
}

std::string normalized(const std::string& name) {
  std::string n = name;
  while (!n.empty() && n.front() == '/') n.erase(n.begin());
  return n;
}

std::string broadcastString(MPI_Comm comm, const std::string& s) {
  long n = static_cast<long>(s.size());
  MPI_Bcast(&n, 1, MPI_LONG, 0, comm);
  std::string out = s;
  out.resize(static_cast<std::size_t>(n));
  MPI_Bcast(out.data(), static_cast<int>(n), MPI_CHAR, 0, comm);
  return out;
}

// Every rank learns whether any rank failed a check, so all of them throw together. `signature`
// must be equal on all ranks (name and shape of a collective call); a mismatch is an error too.
void agree(MPI_Comm comm, const std::string& localError, std::size_t signature, const std::string& what) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const long sig = static_cast<long>(signature & 0x3fffffffffffffffULL);
  long buf[3] = {localError.empty() ? LONG_MIN : -static_cast<long>(rank), sig, -sig};
  MPI_Allreduce(MPI_IN_PLACE, buf, 3, MPI_LONG, MPI_MAX, comm);
  if (!localError.empty()) throw std::runtime_error(what + ": " + localError);
  if (buf[0] != LONG_MIN) throw std::runtime_error(what + ": invalid arguments on rank " + std::to_string(-buf[0]));
  if (buf[1] != -buf[2]) throw std::runtime_error(what + ": ranks disagree on the name or shape of a collective write");
}

std::size_t signatureOf(const std::string& name, const std::vector<long>& dims, int kind) {
  std::size_t h = std::hash<std::string>{}(name) ^ (std::size_t(kind) * 0x9e3779b97f4a7c15ULL);
  for (long d : dims) h = h * 1000003ULL ^ std::hash<long>{}(d);
  return h;
}

// Moves rows owned in arbitrary order to contiguous blocks, one block per rank.
struct RowPlan {
  long begin = 0, count = 0;          // this rank's block of the table
  std::vector<int> sendCounts, sendDispls, recvCounts, recvDispls;  // in rows
  std::vector<long> sendOrder;        // positions in the owned list, grouped by destination
  std::vector<long> recvSlot;         // block-local row of each received row
  bool complete = true;               // every row of every block is owned by some rank

  static RowPlan build(MPI_Comm comm, long n, const std::vector<long>& owned, const std::string& what) {
    int rank = 0, size = 1;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
    RowPlan p;
    std::string error;
    for (long g : owned)
      if (g < 0 || g >= n) {
        error = "row " + std::to_string(g) + " outside [0, " + std::to_string(n) + ")";
        break;
      }
    agree(comm, error, signatureOf(what, {n}, 0), what);

    std::vector<long> begins(size + 1);
    for (int r = 0; r <= size; ++r) begins[r] = n * r / size;
    p.begin = begins[rank];
    p.count = begins[rank + 1] - begins[rank];
    std::vector<int> dest(owned.size());
    p.sendCounts.assign(size, 0);
    for (std::size_t i = 0; i < owned.size(); ++i) {
      dest[i] = static_cast<int>(std::upper_bound(begins.begin(), begins.end(), owned[i]) - begins.begin()) - 1;
      ++p.sendCounts[dest[i]];
    }
    p.recvCounts.assign(size, 0);
    MPI_Alltoall(p.sendCounts.data(), 1, MPI_INT, p.recvCounts.data(), 1, MPI_INT, comm);
    p.sendDispls.assign(size, 0);
    p.recvDispls.assign(size, 0);
    for (int r = 1; r < size; ++r) {
      p.sendDispls[r] = p.sendDispls[r - 1] + p.sendCounts[r - 1];
      p.recvDispls[r] = p.recvDispls[r - 1] + p.recvCounts[r - 1];
    }
    const long received = size ? p.recvDispls[size - 1] + p.recvCounts[size - 1] : 0;
    p.sendOrder.resize(owned.size());
    std::vector<long> sendRows(owned.size());
    std::vector<int> fill = p.sendDispls;
    for (std::size_t i = 0; i < owned.size(); ++i) {
      const int slot = fill[dest[i]]++;
      p.sendOrder[slot] = static_cast<long>(i);
      sendRows[slot] = owned[i];
    }
    p.recvSlot.resize(received);
    MPI_Alltoallv(sendRows.data(), p.sendCounts.data(), p.sendDispls.data(), MPI_LONG, p.recvSlot.data(),
                  p.recvCounts.data(), p.recvDispls.data(), MPI_LONG, comm);
    std::vector<char> seen(p.count, 0);
    for (long& r : p.recvSlot) {
      r -= p.begin;
      if (seen[r]++ && error.empty()) error = "row " + std::to_string(r + p.begin) + " is owned by two ranks";
    }
    int complete = std::all_of(seen.begin(), seen.end(), [](char c) { return c != 0; });
    MPI_Allreduce(MPI_IN_PLACE, &complete, 1, MPI_INT, MPI_LAND, comm);
    p.complete = complete != 0;
    agree(comm, error, signatureOf(what, {n}, 1), what);
    return p;
  }

  // This rank's block, `m` values per row, from its owned rows (in owned order). Rows that no rank
  // owns are NaN.
  std::vector<double> exchange(MPI_Comm comm, std::span<const double> values, long m) const {
    std::vector<double> send(values.size()), recv(recvSlot.size() * m), block(count * m, kNaN);
    for (std::size_t i = 0; i < sendOrder.size(); ++i)
      std::copy_n(values.begin() + sendOrder[i] * m, m, send.begin() + static_cast<long>(i) * m);
    MPI_Datatype row;
    MPI_Type_contiguous(static_cast<int>(m), MPI_DOUBLE, &row);
    MPI_Type_commit(&row);
    MPI_Alltoallv(send.data(), sendCounts.data(), sendDispls.data(), row, recv.data(), recvCounts.data(),
                  recvDispls.data(), row, comm);
    MPI_Type_free(&row);
    for (std::size_t i = 0; i < recvSlot.size(); ++i)
      std::copy_n(recv.begin() + static_cast<long>(i) * m, m, block.begin() + recvSlot[i] * m);
    return block;
  }
};

// Lines, Triangles, Quads: tables over the cells of one kind (cell fields), in /mesh/<kind> order.
enum class Kind { Node = 0, Element = 1, Mesh = 2, Row = 3, Lines = 4, Triangles = 5, Quads = 6 };

const char* kindName(Kind k) {
  switch (k) {
    case Kind::Node: return "node field";
    case Kind::Element: return "element field";
    case Kind::Mesh: return "mesh field";
    case Kind::Row: return "step row";
    default: return "cell field";
  }
}

bool isCellKind(Kind k) { return k == Kind::Lines || k == Kind::Triangles || k == Kind::Quads; }
int cellIndex(Kind k) { return static_cast<int>(k) - static_cast<int>(Kind::Lines); }

struct StepDataset {
  Kind kind = Kind::Row;
  h5::Handle dset;
  std::vector<long> inner;    // dims after the step axis (rows of a table, then field shape)
  std::vector<char> written;  // per step
  std::vector<char> filled;   // per step: NaN written into a row never written
  long rowLength = 1;         // Kind::Row: k
};

struct CellKind {
  const char* name;        // dataset name under /mesh
  const char* topology;    // XDMF TopologyType
  int nodes;
  const std::vector<long>* conn;     // global FE node ids, `nodes` per cell
  const std::vector<long>* element;  // 1-based scene element per cell
  const std::vector<double>* look;   // r, g, b, opacity, visible per cell (layout.look)
};

/// The element-look datasets of a cell kind: name suffix, first of the 5 look values, how many.
struct LookPart {
  const char* suffix;
  int first, count;
};
constexpr std::array<LookPart, 3> kLookParts = {{{"_color", 0, 3}, {"_opacity", 3, 1}, {"_visible", 4, 1}}};

// Every rank learns whether an HDF5 call failed on any rank (a full disk may fail the write of
// one aggregator only); all throw the message of the first failing rank, so none is left waiting
// in the next collective call.
void agreeStatus(MPI_Comm comm, long status, const std::string& what, const std::string& file) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  std::string msg;
  if (status < 0) {
    msg = h5::failureText(what);
    const std::string cause = ioFailureCause(file);
    if (!cause.empty()) msg += ": " + cause;
  }
  int first = status < 0 ? rank : INT_MAX;
  MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, comm);
  if (first == INT_MAX) return;
  long n = static_cast<long>(msg.size());
  MPI_Bcast(&n, 1, MPI_LONG, first, comm);
  msg.resize(static_cast<std::size_t>(n));
  MPI_Bcast(msg.data(), static_cast<int>(n), MPI_CHAR, first, comm);
  throw ResultFileError("file " + file + ": " + msg);
}

// One of the two HDF5 files of the crash-safe scheme (file comment) and what it holds.
struct Sink {
  std::string name;  // current name on disk (rank 0 keeps it; every rank knows it)
  h5::Handle file, dxpl;
  std::map<std::string, StepDataset> steps;  // std::map: every rank iterates in the same order
  std::vector<double> stepValues;
  std::map<std::string, h5::Handle> state;  // fixed-size restart state datasets, kept open
  std::set<std::string> stateGroups;
  int numSteps() const { return static_cast<int>(stepValues.size()); }
  void closeHandles() noexcept {
    for (auto& [name, sd] : steps) sd.dset.reset();
    for (auto& [name, d] : state) d.reset();
    dxpl.reset();
    file.reset();
  }
};

}  // namespace

ResultFileError::ResultFileError(const std::string& what) : std::runtime_error(what) {}

struct ResultFile::Impl {
  using Op = std::function<void(Sink&)>;
  MPI_Comm comm = MPI_COMM_NULL;
  int rank = 0, size = 1;
  std::string path, partPath, sparePath;
  ResultLayout layout;
  RowPlan nodePlan, elementPlan, meshPlan;
  RowPlan cellPlans[3];             // lines, triangles, quads
  std::vector<long> ownedCells[3];  // global rows of this rank's cells of each kind (contiguous)
  bool hasReference = false;        // /mesh/p0 written (layout.meshReference given)
  std::map<std::string, RowPlan> statePlans;  // per state table, built at its first write
  Sink sinks[2];
  int lead = 0;              // index of the sink receiving writes (named partPath)
  bool published = false;    // the other sink is under the final name (after the first commit)
  std::vector<Op> log;       // writes since the last commit, replayed into the other sink
  long cellTotals[3] = {0, 0, 0}, cellOffsets[3] = {0, 0, 0};
  bool closed = false, failed = false;
  double syncInterval = 10, lastSync = 0;  // seconds between commits forced to the disk (file_sync.hpp)
  long commits = 0, syncedCommits = 0;
  std::uintmax_t leadBytes = 0, stepBytes = 0;  // rank 0: lead file size after the last flush, largest growth per commit
  double xdmfWritten = 0, xdmfSeconds = 0;  // rank 0: when the XDMF was last written, and how long it took

  ~Impl() {
    sinks[0].closeHandles();
    sinks[1].closeHandles();
    if (comm != MPI_COMM_NULL) MPI_Comm_free(&comm);
  }

  Sink& leadSink() { return sinks[lead]; }
  const Sink& leadSink() const { return sinks[lead]; }
  int numSteps() const { return leadSink().numSteps(); }

  // Runs a write on the lead and records it for the other sink. A failure (agreed on all ranks)
  // stops every later write: the published file keeps the last committed state.
  void apply(Op op) {
    try {
      op(leadSink());
    } catch (...) {
      failed = true;
      throw;
    }
    log.push_back(std::move(op));
  }

  std::array<CellKind, 3> cellKinds() const {
    return {{{"lines", "Polyline", 2, &layout.lines, &layout.lineElement, &layout.lineLook},
             {"triangles", "Triangle", 3, &layout.triangles, &layout.triangleElement, &layout.triangleLook},
             {"quads", "Quadrilateral", 4, &layout.quads, &layout.quadElement, &layout.quadLook}}};
  }

  const RowPlan& plan(Kind k) const {
    if (isCellKind(k)) return cellPlans[cellIndex(k)];
    return k == Kind::Node ? nodePlan : k == Kind::Element ? elementPlan : meshPlan;
  }
  long tableRows(Kind k) const {
    if (isCellKind(k)) return cellTotals[cellIndex(k)];
    return k == Kind::Node ? layout.numNodes : k == Kind::Element ? layout.numElements : layout.numMeshNodes;
  }
  const std::vector<long>& owned(Kind k) const {
    if (isCellKind(k)) return ownedCells[cellIndex(k)];
    return k == Kind::Node ? layout.ownedNodes : k == Kind::Element ? layout.ownedElements : layout.ownedMeshNodes;
  }

  void writeBox(Sink& s, hid_t dset, hid_t memType, const std::vector<hsize_t>& start, const std::vector<hsize_t>& count,
                const void* data, const std::string& what) {
    agreeStatus(comm, h5::writeBox(dset, memType, start, count, data, s.dxpl, what), what + ": write", s.name);
  }

  void createFile(Sink& s, const std::string& name) {
    const std::string what = "file " + name;
    h5::Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, what + ": access list");
    h5::check(H5Pset_fapl_mpio(fapl, comm, MPI_INFO_NULL), what + ": MPI-IO driver");
    h5::check(H5Pset_all_coll_metadata_ops(fapl, 1), what + ": collective metadata reads");
    h5::check(H5Pset_coll_metadata_write(fapl, 1), what + ": collective metadata writes");
    const hid_t id = H5Fcreate(name.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
    agreeStatus(comm, id, "create", name);
    s.name = name;
    s.file = h5::Handle(id, H5Fclose, what + ": create");
    s.dxpl = h5::collectiveDxpl();
  }

  // [steps, inner...] dataset, chunked and unlimited along the step axis.
  StepDataset& createStepDataset(Sink& s, const std::string& name, Kind kind, std::vector<long> inner, long rowLength) {
    const std::string what = "dataset /" + name;
    std::vector<hsize_t> dims{hsize_t(s.numSteps())}, maxdims{H5S_UNLIMITED}, chunk;
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
    sd.written.assign(s.numSteps(), 0);
    sd.filled.assign(s.numSteps(), 0);
    sd.rowLength = rowLength;
    return s.steps.emplace(name, std::move(sd)).first->second;
  }

  // Why a write cannot go ahead now, or "".
  std::string stateError(bool needsStep) const {
    if (closed) return "file already closed";
    if (failed) return "an earlier write failed";
    if (needsStep && numSteps() == 0) return "written before the first beginStep";
    return "";
  }

  // Why `name` cannot be a new dataset, or "": it must be neither a dataset of this file nor the
  // step dataset. With collective metadata reads the H5Lexists calls are collective, so every rank
  // calls this whenever the name is missing from `steps` (which is the same on all ranks). The
  // walk goes one path component at a time, since H5Lexists fails when a parent group is missing.
  std::string nameError(const std::string& name) const {
    if (name.empty()) return "empty dataset name";
    if (name == layout.stepName) return "name reserved for the step values";
    for (std::size_t pos = 0;;) {
      pos = name.find('/', pos + 1);
      const std::string prefix = name.substr(0, pos);
      if (h5::check(H5Lexists(leadSink().file, prefix.c_str(), H5P_DEFAULT), "dataset /" + name + ": lookup") <= 0)
        return "";
      if (pos == std::string::npos) return "dataset /" + name + " already exists";
    }
  }

  void beginStepIn(Sink& s, int step, double stepValue) {
    const std::string what = "dataset /" + layout.stepName;
    if (step == 0) createStepDataset(s, layout.stepName, Kind::Row, {}, 1);
    s.stepValues.push_back(stepValue);
    for (auto& [name, sd] : s.steps) {
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

  void writeTable(Kind kind, const std::string& rawName, std::span<const double> values, std::vector<long> inner) {
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
    }
    agree(comm, error, signatureOf(name, dims, static_cast<int>(kind)), what);

    const RowPlan& p = plan(kind);
    apply([this, kind, name, dims, inner, block = p.exchange(comm, values, m)](Sink& s) {
      auto found = s.steps.find(name);
      StepDataset& sd = found != s.steps.end() ? found->second : createStepDataset(s, name, kind, dims, 1);
      const RowPlan& pl = plan(kind);
      const int step = s.numSteps() - 1;
      std::vector<hsize_t> start{hsize_t(step), hsize_t(pl.begin)}, count{1, hsize_t(pl.count)};
      for (long d : inner) {
        start.push_back(0);
        count.push_back(hsize_t(d));
      }
      writeBox(s, sd.dset, H5T_NATIVE_DOUBLE, start, count, block.data(), "dataset /" + name);
      sd.written[step] = 1;
    });
  }

  // Sets every row never written to NaN, one hyperslab per run of consecutive such steps.
  void fillUnwritten(Sink& s, const std::string& name, StepDataset& sd) {
    const std::string what = "dataset /" + name + ": NaN rows";
    for (int st = 0; st < s.numSteps();) {
      if (sd.written[st] || sd.filled[st]) {
        ++st;
        continue;
      }
      int e = st;
      while (e < s.numSteps() && !sd.written[e] && !sd.filled[e]) ++e;
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

  void fillAll(Sink& s) {
    for (auto& [name, sd] : s.steps) fillUnwritten(s, name, sd);
  }

  // Global cell counts, this rank's first row of each kind (cells are concatenated in rank order)
  // and the row plans of the cell fields.
  void computeCellOffsets() {
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

  // /mesh/p0 [nmesh, 3]: the reference geometry, written once at creation.
  void writeReference(Sink& s, const std::vector<double>& block) {
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

  void writeCells(Sink& s) {
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

  // The fixed-size state dataset `name` of sink s: created at the first write (shape dims).
  hid_t stateDataset(Sink& s, const std::string& name, const std::vector<hsize_t>& dims) {
    auto it = s.state.find(name);
    if (it != s.state.end()) return it->second;
    const std::string what = "dataset /" + name;
    h5::Handle space = h5::dataspace(dims, what);
    h5::Handle lcpl = h5::intermediateGroupLcpl(what);
    const hid_t id = H5Dcreate2(s.file, name.c_str(), H5T_IEEE_F64LE, space, lcpl, H5P_DEFAULT, H5P_DEFAULT);
    agreeStatus(comm, id, what + ": create", s.name);
    return s.state.emplace(name, h5::Handle(id, H5Dclose, what + ": create")).first->second;
  }

  void validateLayout() const {
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

  XdmfDescription xdmfDescription(const Sink& s) const {
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
                 lp.count > 1 ? std::vector<long>{lp.count} : std::vector<long>{}, {}});
      }
    auto field = [](const std::string& name, const std::string& dataset, const StepDataset& sd) {
      XdmfField f;
      f.name = name;
      f.dataset = "/" + dataset;
      f.inner.assign(sd.inner.begin() + 1, sd.inner.end());
      f.written = sd.written;
      return f;
    };
    for (const auto& [name, sd] : s.steps) {
      if (sd.kind == Kind::Mesh && name != "mesh/p") {
        // /mesh/u is the displacement from the reference geometry /mesh/p0
        d.pointFields.push_back(field(name == "mesh/u" ? "displacement" : name.substr(5), name, sd));
      } else if (isCellKind(sd.kind)) {
        const std::string kind = kinds[cellIndex(sd.kind)].name;
        for (XdmfCellBlock& c : d.cells)
          if (c.name == kind) c.fields.push_back(field(name.substr(name.rfind('/') + 1), name, sd));
      }
    }
    return d;
  }

  // Rank 0 puts the lead under the final name (atomically replacing the published file, which
  // stays reachable as partPath) and rewrites the XDMF for the steps it holds; every rank learns
  // the outcome. keepOther = false at close: the former published file is dropped.
  void publishLead(bool keepOther) {
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
};

ResultFile::ResultFile(MPI_Comm comm, const std::string& path, const ResultLayout& layout)
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

ResultFile::~ResultFile() {
  if (!impl_ || impl_->closed) return;
  try {
    close(false);
  } catch (const std::exception& e) {
    std::cerr << "sinew: closing result file " << impl_->path << " failed: " << e.what() << "\n";
  }
}

void ResultFile::beginStep(int step, double stepValue) {
  Impl& m = *impl_;
  const std::string what = "dataset /" + m.layout.stepName;
  std::string error = m.stateError(false);
  if (error.empty() && step != m.numSteps())
    error = "step " + std::to_string(step) + " does not follow step " + std::to_string(m.numSteps() - 1);
  agree(m.comm, error, signatureOf(m.layout.stepName, {step}, 10), what);
  m.apply([&m, step, stepValue](Sink& s) { m.beginStepIn(s, step, stepValue); });
}

void ResultFile::writeNodeField(const std::string& name, std::span<const double> values, std::vector<long> inner) {
  impl_->writeTable(Kind::Node, name, values, std::move(inner));
}

void ResultFile::writeElementField(const std::string& name, std::span<const double> values, std::vector<long> inner) {
  impl_->writeTable(Kind::Element, name, values, std::move(inner));
}

void ResultFile::writeMeshField(const std::string& name, std::span<const double> values, std::vector<long> inner) {
  impl_->writeTable(Kind::Mesh, name, values, std::move(inner));
}

void ResultFile::writeCellField(const std::string& cells, const std::string& quantity, std::span<const double> values,
                                std::vector<long> inner) {
  Kind kind = Kind::Lines;
  if (cells == "triangles") kind = Kind::Triangles;
  else if (cells == "quads") kind = Kind::Quads;
  else if (cells != "lines") throw std::invalid_argument("cell field " + quantity + ": unknown cell kind " + cells);
  impl_->writeTable(kind, "cell/" + cells + "/" + quantity, values, std::move(inner));
}

const std::vector<long>& ResultFile::ownedCellRows(const std::string& cells) const {
  const int k = cells == "lines" ? 0 : (cells == "triangles" ? 1 : 2);
  return impl_->ownedCells[k];
}

void ResultFile::writeStepRow(const std::string& rawName, std::span<const double> values) {
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
    } else {
      error = m.nameError(name);
    }
  }
  agree(m.comm, error, signatureOf(name, {}, 3), what);
  if (it == steps.end() && k == 0) return;  // nothing fixes the row length yet; rows stay NaN

  std::vector<double> row(m.rank == 0 ? values.begin() : values.end(), values.end());
  m.apply([&m, name, k, row = std::move(row)](Sink& s) {
    auto found = s.steps.find(name);
    StepDataset& sd = found != s.steps.end()
                          ? found->second
                          : m.createStepDataset(s, name, Kind::Row, k == 1 ? std::vector<long>{} : std::vector<long>{k}, k);
    const int step = s.numSteps() - 1;
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

void ResultFile::writeArray(const std::string& rawName, std::span<const double> values, std::vector<long> shape) {
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

void ResultFile::writeStateTable(const std::string& rawName, long numRows, long m, std::span<const long> rows,
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

void ResultFile::writeStateArray(const std::string& rawName, std::span<const double> values, std::vector<long> shape) {
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

void ResultFile::writeStateAttribute(const std::string& rawGroup, const std::string& attr, const std::string& text) {
  Impl& im = *impl_;
  const std::string group = normalized(rawGroup);
  agree(im.comm, im.stateError(false), signatureOf(group + "@" + attr, {}, 14), "group /" + group);
  const std::string value = broadcastString(im.comm, text);
  im.apply([&im, group, attr, value](Sink& s) {
    const std::string what = "group /" + group;
    h5::Handle g;
    if (s.stateGroups.count(group)) {
      g = h5::Handle(H5Gopen2(s.file, group.c_str(), H5P_DEFAULT), H5Gclose, what + ": open");
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

void ResultFile::commit() {
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

long ResultFile::commits() const { return impl_->commits; }
long ResultFile::syncedCommits() const { return impl_->syncedCommits; }

void ResultFile::setSyncInterval(double seconds) {
  impl_->syncInterval = seconds;
  impl_->lastSync = MPI_Wtime();
  impl_->commits = impl_->syncedCommits = 0;  // counted from here (the creation's commit is not)
}

void ResultFile::close(bool converged) {
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

const std::string& ResultFile::path() const { return impl_->path; }

std::string ResultFile::xdmfPath() const {
  return std::filesystem::path(impl_->path).replace_extension(".xdmf").string();
}

int ResultFile::stepsWritten() const { return impl_->numSteps(); }

bool ResultFile::failed() const { return impl_->failed; }

}  // namespace sinew
