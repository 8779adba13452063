// Parallel HDF5 result file (design.md section 3) and the XDMF beside it.
// Every method is collective over the communicator unless it says otherwise.
#pragma once
#include <mpi.h>

#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace sinew {

/// Which rows of the distributed tables this rank writes, and the visualization mesh.
struct ResultLayout {
  long numNodes = 0;      ///< nn: scene nodes (rows of /node/*)
  long numElements = 0;   ///< ne: scene elements (rows of /element/*)
  long numMeshNodes = 0;  ///< FE nodes of the visualization mesh (rows of /mesh/*)
  std::vector<long> ownedNodes;      ///< 0-based scene node rows this rank writes (each row by one rank)
  std::vector<long> ownedElements;   ///< 0-based scene element rows this rank writes
  std::vector<long> ownedMeshNodes;  ///< 0-based FE node rows this rank writes
  /// Reference position (x, y, z) of each owned FE node, in the order of ownedMeshNodes: /mesh/p0,
  /// the geometry of the XDMF (written at creation; empty on every rank: no /mesh/p0, no grids).
  std::vector<double> meshReference;
  /// This rank's visualization cells, as global 0-based FE node ids. Cells of every rank are
  /// concatenated in rank order into /mesh/lines [*,2], /mesh/triangles [*,3], /mesh/quads [*,4],
  /// with /mesh/<kind>_element holding the 1-based scene element of each cell.
  std::vector<long> lines, triangles, quads;
  std::vector<long> lineElement, triangleElement, quadElement;
  /// SPACAR Light's element look (eprops color, opacity, hide), when the scene sets any (the same on
  /// every rank): per cell of this rank, in the order of lines / triangles / quads, 5 values r, g, b
  /// (0..1), opacity, visible (0 for hide) -> /mesh/<kind>_color [*, 3], _opacity, _visible [*] and
  /// the XDMF cell attributes of the same names.
  bool look = false;
  std::vector<double> lineLook, triangleLook, quadLook;
  int dimension = 3;
  // root attributes
  std::string version, scene;
  long ndof = 0;           ///< SPACAR Light's ndof: kinematic DOFs = free node coordinates - rigid-mode constraints
  long nunknowns = 0;      ///< equations solved: free node coordinates + constraint multipliers
  long nnodedofs = 0;      ///< free node coordinates (supports and prescribed motions eliminated)
  long nconstraints = 0;   ///< rigid deformation modes held exactly (Lagrange multipliers)
  int nranks = 1;
  bool inputOnly = false;  ///< opt.showinputonly: root attribute showinputonly = 1
  std::string stepName = "load_factor";  ///< "load_factor" or "time"
};

/// A result file could not be created or written (full disk, file-size limit, unwritable path);
/// the message names the file, the dataset and the cause. Thrown on every rank together.
class ResultFileError : public std::runtime_error {
 public:
  explicit ResultFileError(const std::string& what);
};

/// Where a run's results go: the datasets and root attributes of design.md section 3, written by
/// the procedures and step analyses through these calls. Two stores: Hdf5ResultFile (the parallel
/// HDF5 file and the XDMF beside it) and ResultStore (the same datasets in memory,
/// sinew/result_store.hpp). Every method is collective over the communicator unless it says otherwise.
class ResultFile {
 public:
  virtual ~ResultFile() = default;

  /// Starts step `step` (0-based, consecutive) with its load factor or time. Every step-indexed
  /// dataset written afterwards for this step goes to row `step`.
  virtual void beginStep(int step, double stepValue) = 0;
  /// Step-analysis rows (frequencies, buckling, compliance: the analyses opt.step_analyses runs at
  /// some rows only): between beginAnalysisRow() and endAnalysisRow() every step-indexed write goes
  /// to a dataset with one row per step-analysis row ([m, ...] instead of [ns, ...], HDF5 attribute
  /// rows = "step_analysis_rows"); the new row belongs to the current step. /step_analysis_rows [m]
  /// (int64, 0-based step rows) says which step each row belongs to; it is written only while those
  /// rows are not every step row (0, 1, ..., ns - 1), so a run that analyses every step keeps the
  /// [ns, ...] datasets of earlier versions. A dataset stays on the rows it was created on.
  virtual void beginAnalysisRow() = 0;
  virtual void endAnalysisRow() = 0;
  /// Step row of each step-analysis row so far (the same on every rank).
  virtual const std::vector<long>& analysisRows() const = 0;
  /// [ns, nn, inner...] dataset ("node/p", "node/CMglob" with inner {6,6}): this rank's rows, in
  /// the order of layout.ownedNodes, each of prod(inner) values. A row never written holds NaN.
  virtual void writeNodeField(const std::string& name, std::span<const double> values, std::vector<long> inner) = 0;
  /// [ns, ne, inner...] dataset ("element/stressmax" with inner {}): rows of layout.ownedElements.
  virtual void writeElementField(const std::string& name, std::span<const double> values, std::vector<long> inner) = 0;
  /// [ns, nmesh, inner...] dataset ("mesh/p", "mesh/u", "mesh/mode_freq_1"): rows of ownedMeshNodes.
  /// Fields named mesh/* other than mesh/p appear as point attributes in the XDMF (mesh/u as
  /// "displacement"); the XDMF geometry is mesh/p0 (docs/results.md, "Opening the XDMF in ParaView").
  virtual void writeMeshField(const std::string& name, std::span<const double> values, std::vector<long> inner) = 0;
  /// [ns, ncells, inner...] dataset "cell/<cells>/<quantity>" ("cell/lines/axial_force") over the
  /// cells of one kind (`cells`: "lines", "triangles" or "quads"): this rank's cells of that kind in
  /// the order of layout.lines (triangles, quads), so that row c belongs to /mesh/<cells>[c]. Shown
  /// as a cell attribute in the XDMF.
  virtual void writeCellField(const std::string& cells, const std::string& quantity, std::span<const double> values,
                              std::vector<long> inner) = 0;
  /// Global rows of this rank's cells of one kind ("lines", "triangles", "quads") in /cell/<cells>/*.
  virtual const std::vector<long>& ownedCellRows(const std::string& cells) const = 0;
  /// [ns] or [ns, k] dataset ("stressmax", "freq", "buck", "sensors/tip"): rank 0's values are written.
  /// One value makes a [ns] dataset unless `table` ([ns, k] also for k = 1: /freq, /buck). k is fixed
  /// at the first write; a later row with fewer values is padded with 0.
  virtual void writeStepRow(const std::string& name, std::span<const double> values, bool table = false) = 0;
  /// A dataset written once (statespace/A, formfinding/residual): rank 0's values, given shape.
  virtual void writeArray(const std::string& name, std::span<const double> values, std::vector<long> shape) = 0;
  /// Restart state (src/restart/checkpoint.*): fixed-size datasets without a step axis, created at
  /// their first write and overwritten in place by every later one. They are recorded like every
  /// other write, so commit() publishes them together with the step rows they belong to (no flush
  /// of their own). [numRows, m] table from this rank's rows `rows` (global 0-based ids, each row
  /// on one rank; rows no rank holds are NaN), m values per row. A name's rows are fixed at its
  /// first write.
  virtual void writeStateTable(const std::string& name, long numRows, long m, std::span<const long> rows,
                               std::span<const double> values) = 0;
  /// [shape] state array of rank 0's values, overwritten in place.
  virtual void writeStateArray(const std::string& name, std::span<const double> values, std::vector<long> shape) = 0;
  /// String attribute `attr` of the group `group` (created when missing; also a group of step
  /// datasets, /path): rank 0's text.
  virtual void writeStateAttribute(const std::string& group, const std::string& attr, const std::string& text) = 0;
  /// Makes everything written so far the committed content (the file: under its final name,
  /// atomically, with the XDMF). Call after every step.
  virtual void commit() = 0;
  /// Sets root attribute `converged` and ends the writing. Idempotent. After a failed write
  /// (failed()), the file under the final name keeps the last committed state.
  virtual void close(bool converged) = 0;
  virtual int stepsWritten() const = 0;
  /// A write or commit threw ResultFileError; later writes throw too.
  virtual bool failed() const = 0;
};

/// The HDF5 result file. Crash-safe: from construction on, `path` always names a complete HDF5 file
/// holding every committed step (converged = 0 until close), so a run killed at any moment leaves a
/// file that h5py opens. Writes go to `path.part` (a second copy) and become visible at commit()
/// (src/output/result_file.cpp explains the scheme and its cost); commit() also rewrites the XDMF
/// (rank 0) for the committed steps, and close() publishes the file with the XDMF listing every step.
class Hdf5ResultFile final : public ResultFile {
 public:
  /// Creates the file (with /mesh connectivity and the root attributes) and publishes it under
  /// `path` with no steps yet.
  Hdf5ResultFile(MPI_Comm comm, const std::string& path, const ResultLayout& layout);
  ~Hdf5ResultFile() override;
  Hdf5ResultFile(const Hdf5ResultFile&) = delete;
  Hdf5ResultFile& operator=(const Hdf5ResultFile&) = delete;

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
  void close(bool converged) override;
  int stepsWritten() const override;
  bool failed() const override;

  /// On one process, a commit forces the file to the disk (fsync) only when `seconds` have passed
  /// since the last one that did (0: every commit); the published file survives a killed run either
  /// way (src/output/file_sync.hpp). Default 10 s. With several processes every commit syncs.
  void setSyncInterval(double seconds);
  /// Commits so far, and how many of them were forced to the disk.
  long commits() const;
  long syncedCommits() const;
  const std::string& path() const;
  std::string xdmfPath() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sinew
