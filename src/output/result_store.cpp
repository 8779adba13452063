// The in-memory result store (sinew/result_store.hpp). It follows the HDF5 file's layout decisions
// (result_file.cpp's file comment) so that every dataset equals the file's bit for bit:
// - step-indexed datasets have one row per step (or per step-analysis row), created at their first
//   write; rows never written are NaN; a step row of fewer values than the first is padded with 0;
// - distributed tables (node, element, mesh, cell fields): each rank keeps the rows it owns, per
//   step; close() gathers them (MPI_Allgatherv, values copied, no arithmetic) into the global arrays
//   on every rank, rows placed by the owners' row lists (layout.owned*, cells in rank order);
// - step rows, arrays and state arrays are rank 0's values, broadcast at close;
// - /step_analysis_rows exists once a commit saw step-analysis rows that are not every step row.
#ifndef OMPI_SKIP_MPICXX
#define OMPI_SKIP_MPICXX 1
#endif
#include "sinew/result_store.hpp"

#include "output/collective_agreement.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <stdexcept>
#include <utility>

namespace sinew {

long ResultArray::size() const {
  long n = 1;
  for (long d : shape) n *= d;
  return n;
}

const ResultArray* RunResults::find(const std::string& name) const {
  auto it = datasets.find(name);
  return it == datasets.end() ? nullptr : &it->second;
}

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr const char* kAnalysisRows = "step_analysis_rows";  // as in the HDF5 file

std::string normalized(std::string n) {
  while (!n.empty() && n.front() == '/') n.erase(n.begin());
  return n;
}

template <class T>
MPI_Datatype mpiType();
template <>
MPI_Datatype mpiType<double>() { return MPI_DOUBLE; }
template <>
MPI_Datatype mpiType<long>() { return MPI_LONG; }

/// Every rank's `mine`, concatenated in rank order; counts[r]: how many came from rank r.
template <class T>
std::vector<T> allGather(MPI_Comm comm, const std::vector<T>& mine, std::vector<int>* counts = nullptr) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  std::vector<int> n(static_cast<std::size_t>(size)), offsets(static_cast<std::size_t>(size), 0);
  const int local = static_cast<int>(mine.size());
  MPI_Allgather(&local, 1, MPI_INT, n.data(), 1, MPI_INT, comm);
  for (int r = 1; r < size; ++r) offsets[r] = offsets[r - 1] + n[r - 1];
  std::vector<T> all(static_cast<std::size_t>(offsets.back() + n.back()));
  MPI_Allgatherv(mine.data(), local, mpiType<T>(), all.data(), n.data(), offsets.data(), mpiType<T>(), comm);
  if (counts) *counts = std::move(n);
  return all;
}

template <class T>
void broadcast(MPI_Comm comm, std::vector<T>& v) {
  long n = static_cast<long>(v.size());
  MPI_Bcast(&n, 1, MPI_LONG, 0, comm);
  v.resize(static_cast<std::size_t>(n));
  MPI_Bcast(v.data(), static_cast<int>(n), mpiType<T>(), 0, comm);
}

long product(const std::vector<long>& dims) {
  long n = 1;
  for (long d : dims) n *= d;
  return n;
}

}  // namespace

struct ResultStore::Impl {
  // the tables whose rows are distributed; Row: rank 0's step rows
  enum Kind { Node, Element, Mesh, Lines, Triangles, Quads, Row };
  struct StepTable {
    Kind kind = Row;
    std::vector<long> inner;  // dims after the row axis and the table rows ({} or {k} for Row)
    long m = 1;               // values per table row (Row: k)
    bool analysisAxis = false;
    std::vector<std::vector<double>> rows;  // per step (or step-analysis) row: this rank's values
    std::vector<char> written;
  };
  struct StateTable {
    long numRows = 0, m = 1;
    std::vector<long> rows;
    std::vector<double> values;
  };

  MPI_Comm comm = MPI_COMM_NULL;
  int rank = 0;
  std::string stepName;
  std::array<std::vector<long>, 6> owned;              // this rank's rows per distributed kind
  std::array<std::vector<std::vector<long>>, 6> rowsOf;  // every rank's rows per kind (filled at close)
  std::array<long, 6> tableRows{};                      // global rows per kind
  std::map<std::string, StepTable> steps;  // std::map: every rank iterates in the same order
  std::vector<double> stepValues;
  std::vector<long> analysisRows;
  bool analysisOpen = false, analysisRowsKept = false, closed = false;
  std::map<std::string, ResultArray> arrays;  // writeArray, writeStateArray: rank 0's values
  std::map<std::string, StateTable> stateTables;
  RunResults out;

  ~Impl() {
    if (comm != MPI_COMM_NULL) MPI_Comm_free(&comm);
  }

  int numRows(const StepTable& t) const {
    return static_cast<int>(t.analysisAxis ? analysisRows.size() : stepValues.size());
  }

  void requireStep(const std::string& name) const {
    if (closed) throw std::logic_error("result store: " + name + " written after close");
    if (stepValues.empty()) throw std::logic_error("result store: " + name + " written before the first beginStep");
  }

  StepTable& table(const std::string& name, Kind kind, std::vector<long> inner, long m) {
    auto it = steps.find(name);
    if (it != steps.end()) {
      if (it->second.kind != kind || it->second.analysisAxis != analysisOpen)
        throw std::logic_error("result store: dataset /" + name + " written as another kind or on other rows");
      return it->second;
    }
    StepTable t;
    t.kind = kind;
    t.inner = std::move(inner);
    t.m = m;
    t.analysisAxis = analysisOpen;
    t.rows.resize(static_cast<std::size_t>(numRows(t)));
    t.written.assign(t.rows.size(), 0);
    return steps.emplace(name, std::move(t)).first->second;
  }

  void writeTable(Kind kind, const std::string& rawName, std::span<const double> values, std::vector<long> inner) {
    const std::string name = normalized(rawName);
    requireStep(name);
    const long m = product(inner);
    if (values.size() != owned[kind].size() * static_cast<std::size_t>(m))
      throw std::logic_error("result store: dataset /" + name + ": " + std::to_string(values.size()) + " values for " +
                             std::to_string(owned[kind].size()) + " rows of " + std::to_string(m));
    StepTable& t = table(name, kind, std::move(inner), m);
    const std::size_t row = static_cast<std::size_t>(numRows(t) - 1);
    t.rows[row].assign(values.begin(), values.end());
    t.written[row] = 1;
  }

  void extend(bool analysisAxis) {
    for (auto& [name, t] : steps)
      if (t.analysisAxis == analysisAxis) {
        t.rows.emplace_back();
        t.written.push_back(0);
      }
  }

  void noteAnalysisRows() {
    analysisRowsKept = analysisRowsKept || (!analysisRows.empty() && analysisRows.size() != stepValues.size());
  }

  // Global [rows, N, inner...] array of a distributed table: rank r's rows of each written step
  // land at rowsOf[kind][r]. `rows`: of t (-1: its step or step-analysis rows so far).
  ResultArray gatherTable(const StepTable& t, long rows = -1) {
    const long N = tableRows[t.kind], nrows = rows >= 0 ? rows : numRows(t);
    ResultArray a;
    a.shape = {nrows, N};
    a.shape.insert(a.shape.end(), t.inner.begin(), t.inner.end());
    a.values.assign(static_cast<std::size_t>(nrows * N * t.m), kNaN);
    std::vector<double> mine;
    for (long s = 0; s < nrows; ++s)
      if (t.written[s]) mine.insert(mine.end(), t.rows[s].begin(), t.rows[s].end());
    std::vector<int> counts;
    const std::vector<double> all = allGather(comm, mine, &counts);
    std::size_t at = 0;
    for (std::size_t r = 0; r < counts.size(); ++r)
      for (long s = 0; s < nrows; ++s) {
        if (!t.written[s]) continue;
        for (long row : rowsOf[t.kind][r]) {
          std::copy_n(all.begin() + static_cast<long>(at), t.m, a.values.begin() + (s * N + row) * t.m);
          at += static_cast<std::size_t>(t.m);
        }
      }
    return a;
  }

  // [rows] or [rows, k] step-row dataset: rank 0's rows, NaN where never written.
  ResultArray gatherRows(const StepTable& t) {
    const long nrows = numRows(t);
    ResultArray a;
    a.shape = {nrows};
    a.shape.insert(a.shape.end(), t.inner.begin(), t.inner.end());
    a.values.assign(static_cast<std::size_t>(nrows * t.m), kNaN);
    if (rank == 0)
      for (long s = 0; s < nrows; ++s)
        if (t.written[s]) std::copy(t.rows[s].begin(), t.rows[s].end(), a.values.begin() + s * t.m);
    MPI_Bcast(a.values.data(), static_cast<int>(a.values.size()), MPI_DOUBLE, 0, comm);
    return a;
  }

  ResultArray gatherState(const StateTable& st) {
    ResultArray a;
    a.shape = {st.numRows, st.m};
    a.values.assign(static_cast<std::size_t>(st.numRows * st.m), kNaN);
    const std::vector<long> rows = allGather(comm, st.rows);
    const std::vector<double> values = allGather(comm, st.values);
    for (std::size_t i = 0; i < rows.size(); ++i)
      std::copy_n(values.begin() + static_cast<long>(i) * st.m, st.m, a.values.begin() + rows[i] * st.m);
    return a;
  }

  // /mesh/<kind> connectivity and element numbers (int64), the element look, /mesh/p0.
  void gatherMesh(const ResultLayout& layout, bool hasReference) {
    struct Cells {
      const char* name;
      int nodes;
      const std::vector<long>& conn;
      const std::vector<long>& element;
      const std::vector<double>& look;
    };
    const std::array<Cells, 3> kinds = {{{"lines", 2, layout.lines, layout.lineElement, layout.lineLook},
                                         {"triangles", 3, layout.triangles, layout.triangleElement, layout.triangleLook},
                                         {"quads", 4, layout.quads, layout.quadElement, layout.quadLook}}};
    for (int k = 0; k < 3; ++k) {
      const Cells& c = kinds[k];
      const long total = tableRows[Lines + k];
      if (total == 0) continue;
      const std::string base = std::string("mesh/") + c.name;
      ResultArray conn, element;
      conn.integer = element.integer = true;
      conn.shape = {total, c.nodes};
      conn.integers = allGather(comm, c.conn);
      element.shape = {total};
      element.integers = allGather(comm, c.element);
      out.datasets[base] = std::move(conn);
      out.datasets[base + "_element"] = std::move(element);
      if (!layout.look) continue;
      // SPACAR Light's element look: r, g, b, opacity, visible per cell -> _color [*, 3], _opacity, _visible
      const std::vector<double> look = allGather(comm, c.look);
      const std::array<std::pair<const char*, std::pair<int, int>>, 3> parts = {
          {{"_color", {0, 3}}, {"_opacity", {3, 1}}, {"_visible", {4, 1}}}};
      for (const auto& [suffix, range] : parts) {
        ResultArray a;
        a.shape = range.second > 1 ? std::vector<long>{total, range.second} : std::vector<long>{total};
        for (long cell = 0; cell < total; ++cell)
          for (int j = 0; j < range.second; ++j) a.values.push_back(look[static_cast<std::size_t>(5 * cell + range.first + j)]);
        out.datasets[base + suffix] = std::move(a);
      }
    }
    if (hasReference) {
      StepTable ref;
      ref.kind = Mesh;
      ref.m = 3;
      ref.inner = {3};
      ref.rows = {layout.meshReference};
      ref.written = {1};
      ResultArray a = gatherTable(ref, 1);
      a.shape.erase(a.shape.begin());  // [nmesh, 3], no step axis
      out.datasets["mesh/p0"] = std::move(a);
    }
  }
};

ResultStore::ResultStore(MPI_Comm comm, const ResultLayout& layout) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  MPI_Comm_dup(comm, &m.comm);
  MPI_Comm_rank(m.comm, &m.rank);
  m.stepName = layout.stepName;
  m.owned[Impl::Node] = layout.ownedNodes;
  m.owned[Impl::Element] = layout.ownedElements;
  m.owned[Impl::Mesh] = layout.ownedMeshNodes;
  m.tableRows[Impl::Node] = layout.numNodes;
  m.tableRows[Impl::Element] = layout.numElements;
  m.tableRows[Impl::Mesh] = layout.numMeshNodes;
  // cells are numbered in rank order: this rank's cells of each kind are a contiguous block
  const std::array<std::pair<const std::vector<long>*, int>, 3> cells = {
      {{&layout.lines, 2}, {&layout.triangles, 3}, {&layout.quads, 4}}};
  long local[3], first[3] = {0, 0, 0};
  for (int k = 0; k < 3; ++k) local[k] = static_cast<long>(cells[k].first->size()) / cells[k].second;
  MPI_Allreduce(local, &m.tableRows[Impl::Lines], 3, MPI_LONG, MPI_SUM, m.comm);
  MPI_Exscan(local, first, 3, MPI_LONG, MPI_SUM, m.comm);
  if (m.rank == 0) std::fill(first, first + 3, 0L);
  for (int k = 0; k < 3; ++k)
    for (long c = 0; c < local[k]; ++c) m.owned[Impl::Lines + k].push_back(first[k] + c);
  for (int k = 0; k < 6; ++k) {  // every rank's rows of each kind, for the gathers at close
    std::vector<int> counts;
    const std::vector<long> all = allGather(m.comm, m.owned[k], &counts);
    auto it = all.begin();
    for (int n : counts) {
      m.rowsOf[k].emplace_back(it, it + n);
      it += n;
    }
  }
  int withReference = !layout.meshReference.empty() || layout.ownedMeshNodes.empty();
  MPI_Allreduce(MPI_IN_PLACE, &withReference, 1, MPI_INT, MPI_LAND, m.comm);
  m.gatherMesh(layout, withReference && layout.numMeshNodes > 0);
  // root attributes: rank 0's values
  long numbers[6] = {layout.ndof, layout.nranks, layout.nunknowns, layout.nnodedofs, layout.nconstraints, layout.inputOnly};
  MPI_Bcast(numbers, 6, MPI_LONG, 0, m.comm);
  m.out.numbers = {{"ndof", numbers[0]},      {"nranks", numbers[1]},       {"nunknowns", numbers[2]},
                   {"nnodedofs", numbers[3]}, {"nconstraints", numbers[4]}, {"converged", 0}};
  if (numbers[5]) m.out.numbers["showinputonly"] = 1;
  m.out.texts = {{"version", collective::broadcastString(m.comm, layout.version)}, {"scene", collective::broadcastString(m.comm, layout.scene)}};
}

ResultStore::~ResultStore() = default;

void ResultStore::beginStep(int step, double stepValue) {
  Impl& m = *impl_;
  if (m.closed || step != static_cast<int>(m.stepValues.size()))
    throw std::logic_error("result store: step " + std::to_string(step) + " out of order");
  m.analysisOpen = false;
  m.stepValues.push_back(stepValue);
  m.extend(false);
  Impl::StepTable& t = m.table(m.stepName, Impl::Row, {}, 1);
  t.rows.back() = {stepValue};
  t.written.back() = 1;
}

void ResultStore::beginAnalysisRow() {
  Impl& m = *impl_;
  m.requireStep(kAnalysisRows);
  m.analysisOpen = true;
  m.analysisRows.push_back(static_cast<long>(m.stepValues.size()) - 1);
  m.extend(true);
}

void ResultStore::endAnalysisRow() { impl_->analysisOpen = false; }

const std::vector<long>& ResultStore::analysisRows() const { return impl_->analysisRows; }

void ResultStore::writeNodeField(const std::string& name, std::span<const double> values, std::vector<long> inner) {
  impl_->writeTable(Impl::Node, name, values, std::move(inner));
}

void ResultStore::writeElementField(const std::string& name, std::span<const double> values, std::vector<long> inner) {
  impl_->writeTable(Impl::Element, name, values, std::move(inner));
}

void ResultStore::writeMeshField(const std::string& name, std::span<const double> values, std::vector<long> inner) {
  impl_->writeTable(Impl::Mesh, name, values, std::move(inner));
}

void ResultStore::writeCellField(const std::string& cells, const std::string& quantity, std::span<const double> values,
                                 std::vector<long> inner) {
  const Impl::Kind kind = cells == "lines" ? Impl::Lines : cells == "triangles" ? Impl::Triangles : Impl::Quads;
  if (cells != "lines" && cells != "triangles" && cells != "quads")
    throw std::invalid_argument("cell field " + quantity + ": unknown cell kind " + cells);
  impl_->writeTable(kind, "cell/" + cells + "/" + quantity, values, std::move(inner));
}

const std::vector<long>& ResultStore::ownedCellRows(const std::string& cells) const {
  return impl_->owned[cells == "lines" ? Impl::Lines : cells == "triangles" ? Impl::Triangles : Impl::Quads];
}

void ResultStore::writeStepRow(const std::string& rawName, std::span<const double> values, bool table) {
  Impl& m = *impl_;
  const std::string name = normalized(rawName);
  m.requireStep(name);
  long k = static_cast<long>(values.size());
  MPI_Bcast(&k, 1, MPI_LONG, 0, m.comm);
  auto it = m.steps.find(name);
  if (it == m.steps.end() && k == 0) return;  // nothing fixes the row length yet; rows stay NaN
  Impl::StepTable& t = it != m.steps.end() ? it->second : m.table(name, Impl::Row, k == 1 && !table ? std::vector<long>{} : std::vector<long>{k}, k);
  if (k > t.m) throw std::logic_error("result store: dataset /" + name + ": more values than its first row");
  const std::size_t row = static_cast<std::size_t>(m.numRows(t) - 1);
  t.rows[row].assign(static_cast<std::size_t>(t.m), 0.0);  // shorter rows are padded with 0
  if (m.rank == 0) std::copy(values.begin(), values.end(), t.rows[row].begin());
  t.written[row] = 1;
}

void ResultStore::writeArray(const std::string& rawName, std::span<const double> values, std::vector<long> shape) {
  ResultArray a;
  a.shape = std::move(shape);
  broadcast(impl_->comm, a.shape);  // rank 0's values and shape, as the file writes them (/node/p0: rank 0 holds it)
  if (impl_->rank == 0) a.values.assign(values.begin(), values.end());
  impl_->arrays[normalized(rawName)] = std::move(a);
}

void ResultStore::writeStateTable(const std::string& rawName, long numRows, long m, std::span<const long> rows,
                                  std::span<const double> values) {
  impl_->stateTables[normalized(rawName)] = {numRows, m, std::vector<long>(rows.begin(), rows.end()),
                                             std::vector<double>(values.begin(), values.end())};
}

void ResultStore::writeStateArray(const std::string& name, std::span<const double> values, std::vector<long> shape) {
  writeArray(name, values, std::move(shape));
}

void ResultStore::writeStateAttribute(const std::string& group, const std::string& attr, const std::string& text) {
  impl_->out.groupTexts[normalized(group)][attr] = collective::broadcastString(impl_->comm, text);
}

void ResultStore::commit() { impl_->noteAnalysisRows(); }

void ResultStore::close(bool converged) {
  Impl& m = *impl_;
  if (m.closed) return;
  m.closed = true;
  int ok = converged ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &ok, 1, MPI_INT, MPI_LAND, m.comm);
  m.out.numbers["converged"] = ok;
  m.noteAnalysisRows();
  for (const auto& [name, t] : m.steps) {
    ResultArray a = t.kind == Impl::Row ? m.gatherRows(t) : m.gatherTable(t);
    if (t.analysisAxis) a.rows = kAnalysisRows;
    m.out.datasets[name] = std::move(a);
  }
  if (m.analysisRowsKept) {
    ResultArray a;
    a.integer = true;
    a.shape = {static_cast<long>(m.analysisRows.size())};
    a.integers = m.analysisRows;
    m.out.datasets[kAnalysisRows] = std::move(a);
  }
  for (auto& [name, a] : m.arrays) {
    broadcast(m.comm, a.values);
    m.out.datasets[name] = std::move(a);
  }
  for (const auto& [name, st] : m.stateTables) m.out.datasets[name] = m.gatherState(st);
  m.steps.clear();
  m.arrays.clear();
  m.stateTables.clear();
}

int ResultStore::stepsWritten() const { return static_cast<int>(impl_->stepValues.size()); }

RunResults& ResultStore::results() { return impl_->out; }

}  // namespace sinew
