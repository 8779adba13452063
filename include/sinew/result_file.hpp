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

/// Crash-safe: from construction on, `path` always names a complete HDF5 file holding every
/// committed step (converged = 0 until close), so a run killed at any moment leaves a file that
/// h5py opens. Writes go to `path.part` (a second copy) and become visible at commit()
/// (src/output/result_file.cpp explains the scheme and its cost).
class ResultFile {
 public:
  /// Creates the file (with /mesh connectivity and the root attributes) and publishes it under
  /// `path` with no steps yet.
  ResultFile(MPI_Comm comm, const std::string& path, const ResultLayout& layout);
  ~ResultFile();
  ResultFile(const ResultFile&) = delete;
  ResultFile& operator=(const ResultFile&) = delete;

  /// Starts step `step` (0-based, consecutive) with its load factor or time. Every step-indexed
  /// dataset written afterwards for this step goes to row `step`.
  void beginStep(int step, double stepValue);
  /// Step-analysis rows (frequencies, buckling, compliance: the analyses opt.step_analyses runs at
  /// some rows only): between beginAnalysisRow() and endAnalysisRow() every step-indexed write goes
  /// to a dataset with one row per step-analysis row ([m, ...] instead of [ns, ...], HDF5 attribute
  /// rows = "step_analysis_rows"); the new row belongs to the current step. /step_analysis_rows [m]
  /// (int64, 0-based step rows) says which step each row belongs to; it is written only while those
  /// rows are not every step row (0, 1, ..., ns - 1), so a run that analyses every step keeps the
  /// [ns, ...] datasets of earlier versions. A dataset stays on the rows it was created on.
  void beginAnalysisRow();
  void endAnalysisRow();
  /// Step row of each step-analysis row so far (the same on every rank).
  const std::vector<long>& analysisRows() const;
  /// [ns, nn, inner...] dataset ("node/p", "node/CMglob" with inner {6,6}): this rank's rows, in
  /// the order of layout.ownedNodes, each of prod(inner) values.
  void writeNodeField(const std::string& name, std::span<const double> values, std::vector<long> inner);
  /// [ns, ne, inner...] dataset ("element/stressmax" with inner {}): rows of layout.ownedElements.
  void writeElementField(const std::string& name, std::span<const double> values, std::vector<long> inner);
  /// [ns, nmesh, inner...] dataset ("mesh/p", "mesh/u", "mesh/mode_freq_1"): rows of ownedMeshNodes.
  /// Fields named mesh/* other than mesh/p appear as point attributes in the XDMF (mesh/u as
  /// "displacement"); the XDMF geometry is mesh/p0 (docs/results.md, "Opening the XDMF in ParaView").
  void writeMeshField(const std::string& name, std::span<const double> values, std::vector<long> inner);
  /// [ns, ncells, inner...] dataset "cell/<cells>/<quantity>" ("cell/lines/axial_force") over the
  /// cells of one kind (`cells`: "lines", "triangles" or "quads"): this rank's cells of that kind in
  /// the order of layout.lines (triangles, quads), so that row c belongs to /mesh/<cells>[c]. Shown
  /// as a cell attribute in the XDMF.
  void writeCellField(const std::string& cells, const std::string& quantity, std::span<const double> values,
                      std::vector<long> inner);
  /// Global rows of this rank's cells of one kind ("lines", "triangles", "quads") in /cell/<cells>/*.
  const std::vector<long>& ownedCellRows(const std::string& cells) const;
  /// [ns] or [ns, k] dataset ("stressmax", "freq", "buck", "sensors/tip"): rank 0's values are written.
  /// One value makes a [ns] dataset unless `table` ([ns, k] also for k = 1: /freq, /buck).
  void writeStepRow(const std::string& name, std::span<const double> values, bool table = false);
  /// A dataset written once (statespace/A, formfinding/residual): rank 0's values, given shape.
  void writeArray(const std::string& name, std::span<const double> values, std::vector<long> shape);
  /// Restart state (src/output/checkpoint.*): fixed-size datasets without a step axis, created at
  /// their first write and overwritten in place by every later one. They are recorded like every
  /// other write, so commit() publishes them together with the step rows they belong to (no flush
  /// of their own). [numRows, m] table from this rank's rows `rows` (global 0-based ids, each row
  /// on one rank; rows no rank holds are NaN), m values per row. A name's rows are fixed at its
  /// first write.
  void writeStateTable(const std::string& name, long numRows, long m, std::span<const long> rows,
                       std::span<const double> values);
  /// [shape] state array of rank 0's values, overwritten in place.
  void writeStateArray(const std::string& name, std::span<const double> values, std::vector<long> shape);
  /// String attribute `attr` of the group `group` (created when missing; also a group of step
  /// datasets, /path): rank 0's text.
  void writeStateAttribute(const std::string& group, const std::string& attr, const std::string& text);
  /// Makes everything written so far the content of the file under the final name (atomically)
  /// and rewrites the XDMF (rank 0) for those steps. Call after every step.
  void commit();
  /// On one process, a commit forces the file to the disk (fsync) only when `seconds` have passed
  /// since the last one that did (0: every commit); the published file survives a killed run either
  /// way (src/output/file_sync.hpp). Default 10 s. With several processes every commit syncs.
  void setSyncInterval(double seconds);
  /// Commits so far, and how many of them were forced to the disk.
  long commits() const;
  long syncedCommits() const;
  /// Sets root attribute `converged`, closes the file, publishes it under its final name and writes
  /// the XDMF (rank 0) listing the steps written. Idempotent. After a failed write (failed()), the
  /// file under the final name keeps the last committed state.
  void close(bool converged);

  const std::string& path() const;
  std::string xdmfPath() const;
  int stepsWritten() const;
  /// A write or commit threw ResultFileError; later writes throw too.
  bool failed() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sinew
