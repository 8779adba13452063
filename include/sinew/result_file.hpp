// Parallel HDF5 result file (design.md section 3) and the XDMF beside it.
// Every method is collective over the communicator unless it says otherwise.
#pragma once
#include <mpi.h>

#include <memory>
#include <span>
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
  /// This rank's visualization cells, as global 0-based FE node ids. Cells of every rank are
  /// concatenated in rank order into /mesh/lines [*,2], /mesh/triangles [*,3], /mesh/quads [*,4],
  /// with /mesh/<kind>_element holding the 1-based scene element of each cell.
  std::vector<long> lines, triangles, quads;
  std::vector<long> lineElement, triangleElement, quadElement;
  int dimension = 3;
  // root attributes
  std::string version, scene;
  long ndof = 0;
  int nranks = 1;
  std::string stepName = "load_factor";  ///< "load_factor" or "time"
};

class ResultFile {
 public:
  /// Creates `path + ".part"`; renamed to `path` by close(). Also writes /mesh connectivity.
  ResultFile(MPI_Comm comm, const std::string& path, const ResultLayout& layout);
  ~ResultFile();
  ResultFile(const ResultFile&) = delete;
  ResultFile& operator=(const ResultFile&) = delete;

  /// Starts step `step` (0-based, consecutive) with its load factor or time. Every step-indexed
  /// dataset written afterwards for this step goes to row `step`.
  void beginStep(int step, double stepValue);
  /// [ns, nn, inner...] dataset ("node/p", "node/CMglob" with inner {6,6}): this rank's rows, in
  /// the order of layout.ownedNodes, each of prod(inner) values.
  void writeNodeField(const std::string& name, std::span<const double> values, std::vector<long> inner);
  /// [ns, ne, inner...] dataset ("element/stressmax" with inner {}): rows of layout.ownedElements.
  void writeElementField(const std::string& name, std::span<const double> values, std::vector<long> inner);
  /// [ns, nmesh, inner...] dataset ("mesh/p", "mesh/u", "mesh/mode_freq_1"): rows of ownedMeshNodes.
  /// Fields named mesh/* other than mesh/p appear as point attributes in the XDMF.
  void writeMeshField(const std::string& name, std::span<const double> values, std::vector<long> inner);
  /// [ns] or [ns, k] dataset ("stressmax", "freq", "buck", "sensors/tip"): rank 0's values are written.
  void writeStepRow(const std::string& name, std::span<const double> values);
  /// A dataset written once (statespace/A, formfinding/residual): rank 0's values, given shape.
  void writeArray(const std::string& name, std::span<const double> values, std::vector<long> shape);
  /// Sets root attribute `converged`, closes the file, renames it to its final name and writes
  /// the XDMF (rank 0) listing the steps written. Idempotent.
  void close(bool converged);

  const std::string& path() const;
  std::string xdmfPath() const;
  int stepsWritten() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sinew
