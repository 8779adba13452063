// A run's results in memory (the library entry point, sinew/simulation.hpp): the datasets and
// attributes the HDF5 result file would hold (design.md section 3), written through the same calls
// (ResultFile) and gathered on every rank when the run ends.
#pragma once
#include <mpi.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "sinew/result_file.hpp"

namespace sinew {

/// One dataset as the result file holds it: row-major values of `shape`. Float datasets fill
/// `values`; the int64 ones (/mesh/lines, /mesh/<kind>_element, /step_analysis_rows) `integers`.
struct ResultArray {
  std::vector<long> shape;
  std::vector<double> values;
  std::vector<long> integers;
  bool integer = false;
  std::string rows;  ///< HDF5 attribute "rows": "step_analysis_rows" on datasets of the step-analysis rows
  long size() const;  ///< product of shape
};

/// Every dataset and attribute of a run's result file, in memory. The restart checkpoint
/// (/checkpoint) is not kept: an in-memory run writes none.
struct RunResults {
  std::map<std::string, ResultArray> datasets;  ///< by path without the leading '/': "node/p", "freq", "mesh/p0"
  std::map<std::string, long> numbers;          ///< root attributes converged, ndof, nranks, nunknowns, nnodedofs, nconstraints, showinputonly
  std::map<std::string, std::string> texts;     ///< root attributes version, scene
  std::map<std::string, std::map<std::string, std::string>> groupTexts;  ///< group -> attribute -> text (/path stop_reason)
  /// The dataset `name`, or nullptr.
  const ResultArray* find(const std::string& name) const;
};

/// The in-memory store: each rank keeps the rows it writes during the run (no global arrays while
/// the analyses run); close() gathers every dataset on every rank of the communicator, row for
/// row the values the HDF5 file would hold (rows never written are NaN, shorter step rows padded
/// with 0, /step_analysis_rows only while those rows are not every step row).
class ResultStore final : public ResultFile {
 public:
  ResultStore(MPI_Comm comm, const ResultLayout& layout);
  ~ResultStore() override;
  ResultStore(const ResultStore&) = delete;
  ResultStore& operator=(const ResultStore&) = delete;

  void beginStep(int step, double stepValue) override;
  void beginAnalysisRow() override;
  void endAnalysisRow() override;
  const std::vector<long>& analysisRows() const override;
  void writeNodeField(const std::string& name, std::span<const double> values, std::vector<long> inner) override;
  void writeElementField(const std::string& name, std::span<const double> values, std::vector<long> inner) override;
  void writeMeshField(const std::string& name, std::span<const double> values, std::vector<long> inner) override;
  void writeCellField(const std::string& cells, const std::string& quantity, std::span<const double> values,
                      std::vector<long> inner) override;
  const std::vector<long>& ownedCellRows(const std::string& cells) const override;
  void writeStepRow(const std::string& name, std::span<const double> values, bool table = false) override;
  void writeArray(const std::string& name, std::span<const double> values, std::vector<long> shape) override;
  void writeStateTable(const std::string& name, long numRows, long m, std::span<const long> rows,
                       std::span<const double> values) override;
  void writeStateArray(const std::string& name, std::span<const double> values, std::vector<long> shape) override;
  void writeStateAttribute(const std::string& group, const std::string& attr, const std::string& text) override;
  void commit() override;
  /// Gathers every dataset on every rank (collective) and sets the attribute converged.
  void close(bool converged) override;
  int stepsWritten() const override;
  bool failed() const override { return false; }

  /// The gathered results (after close(); moved out by the caller).
  RunResults& results();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sinew
