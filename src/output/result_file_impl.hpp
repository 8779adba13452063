// Internals of the result file (Hdf5ResultFile::Impl): the two-copy store of the crash-safe scheme
// (result_file.cpp's file comment explains it), i.e. the lead file receiving every write and the
// published one under the final name, each a Sink with its step-indexed datasets (StepDataset),
// restart state datasets and groups; the log of writes since the last commit replayed into the
// other copy; the row plans of the distributed tables; the /mesh cell tables and the XDMF
// description of a published file. Member definitions are in result_file_impl.cpp; the public
// methods (argument checks agreed on all ranks, then Impl::apply of a write) in result_file.cpp.
#pragma once
#include <hdf5.h>

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "output/hdf5_util.hpp"
#include "output/row_plan.hpp"
#include "output/xdmf_writer.hpp"
#include "sinew/result_file.hpp"

namespace sinew {

namespace result_io {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
inline constexpr std::size_t kChunkBytes = std::size_t(1) << 20;  // target chunk size

/// Dataset name without leading slashes ("/node/p" -> "node/p").
inline std::string normalized(const std::string& name) {
  std::string n = name;
  while (!n.empty() && n.front() == '/') n.erase(n.begin());
  return n;
}

// Lines, Triangles, Quads: tables over the cells of one kind (cell fields), in /mesh/<kind> order.
enum class Kind { Node = 0, Element = 1, Mesh = 2, Row = 3, Lines = 4, Triangles = 5, Quads = 6 };

inline const char* kindName(Kind k) {
  switch (k) {
    case Kind::Node: return "node field";
    case Kind::Element: return "element field";
    case Kind::Mesh: return "mesh field";
    case Kind::Row: return "step row";
    default: return "cell field";
  }
}

inline bool isCellKind(Kind k) { return k == Kind::Lines || k == Kind::Triangles || k == Kind::Quads; }
inline int cellIndex(Kind k) { return static_cast<int>(k) - static_cast<int>(Kind::Lines); }

struct StepDataset {
  Kind kind = Kind::Row;
  h5::Handle dset;
  std::vector<long> inner;    // dims after the step axis (rows of a table, then field shape)
  std::vector<char> written;  // per step
  std::vector<char> filled;   // per step: NaN written into a row never written
  long rowLength = 1;         // Kind::Row: k
  bool analysisAxis = false;  // rows are the step-analysis rows (ResultFile::beginAnalysisRow), not the steps
};

inline constexpr const char* kAnalysisRowsName = "step_analysis_rows";

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

// One of the two HDF5 files of the crash-safe scheme (file comment of result_file.cpp) and what it holds.
struct Sink {
  std::string name;  // current name on disk (rank 0 keeps it; every rank knows it)
  h5::Handle file, dxpl;
  std::map<std::string, StepDataset> steps;  // std::map: every rank iterates in the same order
  std::vector<double> stepValues;
  std::vector<long> analysisRows;  // step row of each step-analysis row
  h5::Handle analysisRowsDset;     // /step_analysis_rows, once the analysis rows are not every step row
  std::map<std::string, h5::Handle> state;  // fixed-size restart state datasets, kept open
  std::set<std::string> stateGroups;
  int numSteps() const { return static_cast<int>(stepValues.size()); }
  int numAnalysisRows() const { return static_cast<int>(analysisRows.size()); }
  int numRows(const StepDataset& sd) const { return sd.analysisAxis ? numAnalysisRows() : numSteps(); }
  void closeHandles() noexcept {
    analysisRowsDset.reset();
    for (auto& [name, sd] : steps) sd.dset.reset();
    for (auto& [name, d] : state) d.reset();
    dxpl.reset();
    file.reset();
  }
};

}  // namespace result_io

struct Hdf5ResultFile::Impl {
  using Sink = result_io::Sink;
  using StepDataset = result_io::StepDataset;
  using CellKind = result_io::CellKind;
  using Kind = result_io::Kind;
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
  bool analysisOpen = false;  // between beginAnalysisRow and endAnalysisRow (the same on every rank)
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
  void apply(Op op);

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
                const void* data, const std::string& what);

  void createFile(Sink& s, const std::string& name);

  // [steps, inner...] dataset, chunked and unlimited along the step axis (analysisAxis: along the
  // step-analysis rows).
  StepDataset& createStepDataset(Sink& s, const std::string& name, Kind kind, std::vector<long> inner, long rowLength,
                                 bool analysisAxis = false);

  // Why a write to the existing dataset `sd` cannot go to the rows now open (step rows or
  // step-analysis rows), or "".
  std::string axisError(const StepDataset& sd) const;

  // Why a write cannot go ahead now, or "".
  std::string stateError(bool needsStep) const;

  // Why `name` cannot be a new dataset, or "": it must be neither a dataset of this file nor the
  // step dataset. With collective metadata reads the H5Lexists calls are collective, so every rank
  // calls this whenever the name is missing from `steps` (which is the same on all ranks). The
  // walk goes one path component at a time, since H5Lexists fails when a parent group is missing.
  std::string nameError(const std::string& name) const;

  void beginStepIn(Sink& s, int step, double stepValue);
  void beginAnalysisRowIn(Sink& s);

  // /step_analysis_rows of sink s: written (whole) while its step-analysis rows are not every step
  // row; called before every flush (fillAll).
  void writeAnalysisRows(Sink& s);

  void writeTable(Kind kind, const std::string& rawName, std::span<const double> values, std::vector<long> inner);

  // Sets every row never written to NaN, one hyperslab per run of consecutive such steps.
  void fillUnwritten(Sink& s, const std::string& name, StepDataset& sd);

  void fillAll(Sink& s);

  // Global cell counts, this rank's first row of each kind (cells are concatenated in rank order)
  // and the row plans of the cell fields.
  void computeCellOffsets();

  // /mesh/p0 [nmesh, 3]: the reference geometry, written once at creation.
  void writeReference(Sink& s, const std::vector<double>& block);

  void writeCells(Sink& s);

  // The fixed-size state dataset `name` of sink s: created at the first write (shape dims).
  hid_t stateDataset(Sink& s, const std::string& name, const std::vector<hsize_t>& dims);

  void validateLayout() const;

  XdmfDescription xdmfDescription(const Sink& s) const;

  // Rank 0 puts the lead under the final name (atomically replacing the published file, which
  // stays reachable as partPath) and rewrites the XDMF for the steps it holds; every rank learns
  // the outcome. keepOther = false at close: the former published file is dropped.
  void publishLead(bool keepOther);
};

}  // namespace sinew
