// ResultFile on several ranks (run with mpirun -n 2): writes steps from interleaved, unordered row
// ownership, then rank 0 reopens the file serially and checks every value, shape and attribute,
// the rename of the .part file and the XDMF. Exit status 0 only when every check passed.
//   test_result_file [out.h5]
#ifndef OMPI_SKIP_MPICXX
#define OMPI_SKIP_MPICXX 1
#endif
#include <hdf5.h>
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "output/xdmf_writer.hpp"
#include "sinew/result_file.hpp"

namespace {

int failures = 0;
int rank = 0, nproc = 1;

void expect(bool ok, const std::string& what) {
  if (!ok) {
    ++failures;
    std::cerr << "[rank " << rank << "] FAILED: " << what << "\n";
  }
}

constexpr long kNodes = 7, kElements = 5, kMesh = 9;
const double kStepValues[3] = {0.25, 0.5, 1.0};

// Value of component c of row i at step s in field `f`.
double val(int f, int s, long i, long c) { return 100000.0 * f + 1000.0 * s + 10.0 * i + 0.01 * c; }

std::vector<double> rowsOf(int f, int s, const std::vector<long>& rows, long m) {
  std::vector<double> v;
  for (long i : rows)
    for (long c = 0; c < m; ++c) v.push_back(val(f, s, i, c));
  return v;
}

std::vector<double> freqRow(int s) {
  if (s == 1) return {1.5, 2.5, 3.5};  // shorter: padded with 0
  return {1.0 + s, 2.0 + s, 3.0 + s, 4.0 + s};
}

sinew::ResultLayout makeLayout(const std::string& scene) {
  sinew::ResultLayout L;
  L.numNodes = kNodes;
  L.numElements = kElements;
  L.numMeshNodes = kMesh;
  // Nodes: round robin, listed in descending order (not contiguous, not sorted).
  for (long i = kNodes - 1; i >= 0; --i)
    if (i % nproc == rank) L.ownedNodes.push_back(i);
  // Elements: all on rank 0, in a shuffled order; the other ranks own none.
  if (rank == 0) L.ownedElements = {3, 0, 4, 1, 2};
  // Mesh nodes: pairs alternate between ranks, each pair listed backwards.
  for (long i = 0; i < kMesh; ++i)
    if ((i / 2) % nproc == rank) L.ownedMeshNodes.insert(L.ownedMeshNodes.begin(), i);
  // Cells: rank r adds r + 1 lines; rank 0 adds two triangles; no quads anywhere.
  for (long j = 0; j <= rank; ++j) {
    L.lines.push_back((rank + j) % kMesh);
    L.lines.push_back((rank + j + 1) % kMesh);
    L.lineElement.push_back(1 + (rank + j) % kElements);
  }
  if (rank == 0) {
    L.triangles = {0, 1, 2, 2, 3, 4};
    L.triangleElement = {4, 5};
  }
  L.meshReference = rowsOf(9, 0, L.ownedMeshNodes, 3);  // /mesh/p0
  L.dimension = 3;
  L.version = "sinew-test 1.0";
  L.scene = scene;
  L.ndof = 42;
  L.nranks = nproc;
  return L;
}

template <class F>
void expectThrowOnAllRanks(F f, const std::string& what) {
  bool threw = false;
  try {
    f();
  } catch (const std::runtime_error& e) {
    threw = true;
    if (rank == 0) std::cout << "  expected error: " << e.what() << "\n";
  }
  expect(threw, what + " throws on rank " + std::to_string(rank));
}

// ---------------------------------------------------------------- serial reading (rank 0)
struct Data {
  std::vector<hsize_t> dims;
  std::vector<double> v;
  std::vector<long long> i;
};

bool exists(hid_t f, const std::string& name) {
  std::size_t pos = 0;
  for (;;) {
    pos = name.find('/', pos + 1);
    if (H5Lexists(f, name.substr(0, pos).c_str(), H5P_DEFAULT) <= 0) return false;
    if (pos == std::string::npos) return true;
  }
}

Data read(hid_t f, const std::string& name, bool integer = false) {
  Data d;
  hid_t ds = H5Dopen2(f, name.c_str(), H5P_DEFAULT);
  if (ds < 0) throw std::runtime_error("cannot open " + name);
  hid_t sp = H5Dget_space(ds);
  const int nd = H5Sget_simple_extent_ndims(sp);
  d.dims.resize(nd);
  H5Sget_simple_extent_dims(sp, d.dims.data(), nullptr);
  const hssize_t n = H5Sget_simple_extent_npoints(sp);
  herr_t st;
  if (integer) {
    d.i.resize(n);
    st = n ? H5Dread(ds, H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, d.i.data()) : 0;
  } else {
    d.v.resize(n);
    st = n ? H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, d.v.data()) : 0;
  }
  H5Sclose(sp);
  H5Dclose(ds);
  if (st < 0) throw std::runtime_error("cannot read " + name);
  return d;
}

long long readIntAttr(hid_t f, const char* name) {
  long long v = -1;
  hid_t a = H5Aopen(f, name, H5P_DEFAULT);
  if (a < 0) throw std::runtime_error(std::string("no attribute ") + name);
  H5Aread(a, H5T_NATIVE_LLONG, &v);
  H5Aclose(a);
  return v;
}

std::string readStringAttr(hid_t f, const char* name) {
  hid_t a = H5Aopen(f, name, H5P_DEFAULT);
  if (a < 0) throw std::runtime_error(std::string("no attribute ") + name);
  hid_t t = H5Tcopy(H5T_C_S1);
  H5Tset_size(t, H5T_VARIABLE);
  H5Tset_cset(t, H5T_CSET_UTF8);
  char* s = nullptr;
  H5Aread(a, t, &s);
  std::string out = s ? s : "";
  H5free_memory(s);
  H5Tclose(t);
  H5Aclose(a);
  return out;
}

std::string dimsText(const std::vector<hsize_t>& d) {
  std::string s = "[";
  for (std::size_t k = 0; k < d.size(); ++k) {
    if (k) s += ',';
    s += std::to_string(d[k]);
  }
  return s + "]";
}

void expectDims(const Data& d, std::vector<hsize_t> want, const std::string& name) {
  expect(d.dims == want, name + " shape " + dimsText(d.dims) + ", expected " + dimsText(want));
}

// A [ns, rows, m] table, ns = written.size(): row `s` holds val(f, s, i, c) when written[s], else NaN.
void checkTable(hid_t f, const std::string& name, int field, long rows, std::vector<hsize_t> inner,
                const std::vector<bool>& written) {
  const Data d = read(f, name);
  const int ns = static_cast<int>(written.size());
  std::vector<hsize_t> want{hsize_t(ns), hsize_t(rows)};
  want.insert(want.end(), inner.begin(), inner.end());
  expectDims(d, want, name);
  long m = 1;
  for (hsize_t k : inner) m *= long(k);
  if (d.v.size() != std::size_t(ns * rows * m)) return;
  int bad = 0;
  for (int s = 0; s < ns; ++s)
    for (long i = 0; i < rows; ++i)
      for (long c = 0; c < m; ++c) {
        const double x = d.v[(s * rows + i) * m + c];
        if (written[s] ? x != val(field, s, i, c) : !std::isnan(x)) ++bad;
      }
  expect(bad == 0, name + ": " + std::to_string(bad) + " wrong values");
}

std::size_t countOf(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

void checkMainFile(const std::string& path, const std::string& xdmf, const std::string& scene) {
  namespace fs = std::filesystem;
  expect(fs::exists(path), path + " exists");
  expect(!fs::exists(path + ".part"), path + ".part is gone");
  hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) {
    expect(false, "open " + path);
    return;
  }
  // Root attributes.
  expect(readStringAttr(f, "version") == "sinew-test 1.0", "attribute version");
  expect(readStringAttr(f, "scene") == scene, "attribute scene (" + std::to_string(scene.size()) + " bytes)");
  expect(readIntAttr(f, "ndof") == 42, "attribute ndof");
  expect(readIntAttr(f, "nranks") == nproc, "attribute nranks");
  expect(readIntAttr(f, "converged") == 1, "attribute converged");

  // Step values.
  const Data lf = read(f, "load_factor");
  expectDims(lf, {3}, "load_factor");
  for (int s = 0; s < 3 && lf.v.size() == 3; ++s) expect(lf.v[s] == kStepValues[s], "load_factor value");

  // Tables.
  checkTable(f, "node/p", 1, kNodes, {3}, {true, true, true});
  checkTable(f, "node/CMglob", 2, kNodes, {6, 6}, {true, false, true});
  checkTable(f, "node/Freac", 3, kNodes, {3}, {false, true, false});
  checkTable(f, "element/stressmax", 4, kElements, {}, {true, true, true});
  checkTable(f, "element/force", 5, kElements, {2}, {true, true, true});
  checkTable(f, "mesh/p", 6, kMesh, {3}, {true, true, true});
  checkTable(f, "mesh/u", 7, kMesh, {3}, {true, true, true});
  checkTable(f, "mesh/mode_1", 8, kMesh, {}, {false, false, true});
  const long numLines = long(nproc) * (nproc + 1) / 2;
  checkTable(f, "cell/lines/stress", 10, numLines, {}, {true, true, true});
  checkTable(f, "cell/triangles/membrane_n11", 11, 2, {}, {false, false, true});
  const Data ffStep = read(f, "formfinding/step");
  expectDims(ffStep, {3}, "formfinding/step");
  expect(ffStep.v.size() == 3 && ffStep.v[0] == val(12, 0, 0, 0) && std::isnan(ffStep.v[1]) && std::isnan(ffStep.v[2]),
         "formfinding/step values (NaN on load steps)");
  const Data meshP0 = read(f, "mesh/p0");
  expectDims(meshP0, {kMesh, 3}, "mesh/p0");
  for (long k = 0; k < long(meshP0.v.size()); ++k) expect(meshP0.v[k] == val(9, 0, k / 3, k % 3), "mesh/p0 value");

  // Step rows.
  const Data freq = read(f, "freq");
  expectDims(freq, {3, 4}, "freq");
  for (int s = 0; s < 3 && freq.v.size() == 12; ++s) {
    std::vector<double> want = freqRow(s);
    want.resize(4, 0.0);
    for (int k = 0; k < 4; ++k) expect(freq.v[s * 4 + k] == want[k], "freq value");
  }
  const Data smax = read(f, "stressmax");
  expectDims(smax, {3}, "stressmax");
  for (int s = 0; s < 3 && smax.v.size() == 3; ++s) expect(smax.v[s] == 7.0 * (s + 1), "stressmax value");
  const Data tip = read(f, "sensors/tip");
  expectDims(tip, {3, 2}, "sensors/tip");
  if (tip.v.size() == 6)
    expect(std::isnan(tip.v[0]) && std::isnan(tip.v[1]) && tip.v[2] == 0.5 && tip.v[3] == -0.5 && tip.v[4] == 1.5 &&
               tip.v[5] == -1.5,
           "sensors/tip values (row 0 NaN: first written at step 1)");
  expect(!exists(f, "late"), "a row with no values at any step creates no dataset");
  expect(!exists(f, "node/new"), "a failed write creates no dataset");

  // Arrays.
  const Data p0 = read(f, "node/p0");
  expectDims(p0, {kNodes, 3}, "node/p0");
  for (long k = 0; k < long(p0.v.size()); ++k) expect(p0.v[k] == 0.5 * k, "node/p0 value");
  const Data A = read(f, "statespace/A");
  expectDims(A, {2, 2}, "statespace/A");
  expect(A.v == std::vector<double>{1, 2, 3, 4}, "statespace/A values");
  const Data r = read(f, "formfinding/residual");
  expectDims(r, {3}, "formfinding/residual");
  expect(r.v == std::vector<double>{1e-1, 1e-4, 1e-9}, "formfinding/residual values");

  // Mesh cells: rank r contributed r + 1 lines, in rank order.
  std::vector<long long> lines, lineElem;
  for (int q = 0; q < nproc; ++q)
    for (long j = 0; j <= q; ++j) {
      lines.push_back((q + j) % kMesh);
      lines.push_back((q + j + 1) % kMesh);
      lineElem.push_back(1 + (q + j) % kElements);
    }
  const Data ml = read(f, "mesh/lines", true), mle = read(f, "mesh/lines_element", true);
  expectDims(ml, {lineElem.size(), 2}, "mesh/lines");
  expect(ml.i == lines, "mesh/lines values");
  expect(mle.i == lineElem, "mesh/lines_element values");
  const Data mt = read(f, "mesh/triangles", true), mte = read(f, "mesh/triangles_element", true);
  expectDims(mt, {2, 3}, "mesh/triangles");
  expect(mt.i == std::vector<long long>{0, 1, 2, 2, 3, 4}, "mesh/triangles values");
  expect(mte.i == std::vector<long long>{4, 5}, "mesh/triangles_element values");
  expect(!exists(f, "mesh/quads") && !exists(f, "mesh/quads_element"), "no /mesh/quads without quads");
  H5Fclose(f);

  // XDMF beside the file.
  std::ifstream in(xdmf);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string x = ss.str();
  expect(!x.empty(), "XDMF " + xdmf + " written");
  expect(!fs::exists(xdmf + ".part"), "XDMF .part gone");
  const std::string h5 = fs::path(path).filename().string();
  expect(x.find("CollectionType=\"Temporal\"") != std::string::npos, "XDMF temporal collection");
  // Row 0 is a form-finding row (time -1), rows 1 and 2 load steps at their load factors.
  for (const char* t : {"<Time Value=\"-1\"/>", "<Time Value=\"0.5\"/>", "<Time Value=\"1\"/>"})
    expect(countOf(x, t) == 1, std::string("XDMF has ") + t);
  expect(countOf(x, "ItemType=\"HyperSlab\"") > 0, "XDMF HyperSlab items");
  // Two cell kinds: each step is a spatial collection of a Polyline and a Triangle grid.
  expect(countOf(x, "CollectionType=\"Spatial\"") == 3, "XDMF spatial collection per step");
  expect(countOf(x, "TopologyType=\"Polyline\"") == 3 && countOf(x, "NodesPerElement=\"2\"") == 3, "XDMF Polyline");
  expect(countOf(x, "TopologyType=\"Triangle\"") == 3, "XDMF Triangle");
  expect(countOf(x, "Quadrilateral") == 0, "XDMF without quads");
  // Reference geometry /mesh/p0 (a plain HDF item) + displacement /mesh/u; /mesh/p is not shown.
  expect(countOf(x, "Format=\"HDF\">" + h5 + ":/mesh/p0</DataItem>") == 6, "XDMF geometry references " + h5 + ":/mesh/p0");
  expect(countOf(x, h5 + ":/mesh/p</DataItem>") == 0, "XDMF does not show /mesh/p");
  expect(countOf(x, h5 + ":/mesh/u</DataItem>") == 6 && countOf(x, "Name=\"displacement\"") == 6,
         "XDMF attribute displacement (mesh/u) at every step");
  expect(countOf(x, h5 + ":/mesh/mode_1</DataItem>") == 2, "XDMF attribute mode_1 only at step 2");
  expect(countOf(x, "2 0 0  1 1 1  1 9 3</DataItem>") == 2, "XDMF hyperslab of step 2");
  expect(countOf(x, "AttributeType=\"Vector\"") == 6, "XDMF vector attributes");
  expect(countOf(x, "Name=\"stress\" AttributeType=\"Scalar\" Center=\"Cell\"") == 3 &&
             countOf(x, h5 + ":/cell/lines/stress</DataItem>") == 3,
         "XDMF cell attribute stress on the lines at every step");
  expect(countOf(x, "Name=\"membrane_n11\" AttributeType=\"Scalar\" Center=\"Cell\"") == 1 &&
             countOf(x, "2 0  1 1  1 2</DataItem>") == 1,
         "XDMF cell attribute membrane_n11 on the triangles at step 2");
  expect(countOf(x, "Name=\"load_factor\" AttributeType=\"Scalar\" Center=\"Grid\"") == 6 &&
             countOf(x, "Name=\"hdf5_row\"") == 6,
         "XDMF field data load_factor and hdf5_row");
  expect(x.find("/node/") == std::string::npos, "XDMF lists mesh fields only");
}

void checkInterruptedFile(const std::string& path) {
  namespace fs = std::filesystem;
  expect(!fs::exists(path + ".part"), path + ".part is gone after the destructor");
  hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) {
    expect(false, "open " + path);
    return;
  }
  expect(readIntAttr(f, "converged") == 0, "destructor sets converged = 0");
  const Data t = read(f, "time");
  expectDims(t, {1}, "time");
  expect(t.v == std::vector<double>{0.125}, "time value");
  checkTable(f, "node/p", 1, kNodes, {3}, {true});
  // /mesh/p0 is written at creation, whatever the steps write
  const Data meshP0 = read(f, "mesh/p0");
  expectDims(meshP0, {kMesh, 3}, "interrupted: mesh/p0");
  for (long k = 0; k < long(meshP0.v.size()); ++k) expect(meshP0.v[k] == val(9, 0, k / 3, k % 3), "interrupted: mesh/p0 value");
  H5Fclose(f);
  // its XDMF: one step on the reference geometry, no point attributes (no mesh field written)
  const std::string xdmf = std::filesystem::path(path).replace_extension(".xdmf").string();
  std::ifstream in(xdmf);
  const std::string x((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  expect(countOf(x, "<Time Value=\"0.125\"/>") == 1 && countOf(x, ":/mesh/p0</DataItem>") == 2 &&
             countOf(x, "Center=\"Node\"") == 0 && countOf(x, "Name=\"time\"") == 2,
         "interrupted: XDMF of one step on /mesh/p0 with field data time");
}

int runScript(const std::string& command) {
  const int rc = std::system(command.c_str());
  return rc == -1 ? -1 : WEXITSTATUS(rc);
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &nproc);
  const std::string path = argc > 1 ? argv[1] : "test_result_file.h5";
  namespace fs = std::filesystem;
  if (rank == 0) {
    fs::remove(path);
    std::ofstream(path) << "an older result";  // replaced only when the new file is closed
  }
  MPI_Barrier(MPI_COMM_WORLD);

  // A scene larger than the 64 KiB limit of compact attributes, with non-ASCII text.
  std::string scene = "title: Brüls test\nnodes:\n";
  while (scene.size() < 100000) scene += "  - [0.125, 0.25, 0.5]\n";

  std::string xdmf;
  try {
    const sinew::ResultLayout L = makeLayout(scene);
    sinew::Hdf5ResultFile rf(MPI_COMM_WORLD, path, L);
    xdmf = rf.xdmfPath();
    expect(rf.path() == path, "path()");
    expect(fs::path(xdmf).extension() == ".xdmf" && fs::path(xdmf).stem() == fs::path(path).stem(), "xdmfPath()");
    expectThrowOnAllRanks([&] { rf.writeNodeField("node/p", rowsOf(1, 0, L.ownedNodes, 3), {3}); },
                          "writing before beginStep");
    const std::vector<double> p0 = [] {
      std::vector<double> v(kNodes * 3);
      for (std::size_t k = 0; k < v.size(); ++k) v[k] = 0.5 * k;
      return v;
    }();
    // Only rank 0's values and shape count.
    rf.writeArray("node/p0", rank == 0 ? std::span<const double>(p0) : std::span<const double>(), {kNodes, 3});
    rf.writeArray("statespace/A", std::vector<double>{1, 2, 3, 4}, {2, 2});
    // this rank's cells: rank r holds lines r (r + 1) / 2 ... + r, rank 0 both triangles
    std::vector<long> myLines, myTriangles;
    for (long j = 0; j <= rank; ++j) myLines.push_back(long(rank) * (rank + 1) / 2 + j);
    if (rank == 0) myTriangles = {0, 1};

    for (int s = 0; s < 3; ++s) {
      rf.beginStep(s, kStepValues[s]);
      expect(rf.stepsWritten() == s + 1, "stepsWritten()");
      if (rank == 0 && s == 0) {
        std::ifstream old(path);
        std::string content;
        std::getline(old, content);
        // crash safety: the final name holds this run's file (no steps yet) from construction on
        expect(content != "an older result" && H5Fis_hdf5(path.c_str()) > 0, "old file replaced by this run's at construction");
        expect(fs::exists(path + ".part"), "writing goes to .part");
      }
      rf.writeNodeField("node/p", rowsOf(1, s, L.ownedNodes, 3), {3});
      if (s != 1) rf.writeNodeField("node/CMglob", rowsOf(2, s, L.ownedNodes, 36), {6, 6});
      if (s == 1) rf.writeNodeField("/node/Freac", rowsOf(3, s, L.ownedNodes, 3), {3});
      rf.writeElementField("element/stressmax", rowsOf(4, s, L.ownedElements, 1), {});
      rf.writeElementField("element/force", rowsOf(5, s, L.ownedElements, 2), {2});
      rf.writeMeshField("mesh/p", rowsOf(6, s, L.ownedMeshNodes, 3), {3});
      rf.writeMeshField("mesh/u", rowsOf(7, s, L.ownedMeshNodes, 3), {3});
      if (s == 2) rf.writeMeshField("mesh/mode_1", rowsOf(8, s, L.ownedMeshNodes, 1), {});
      rf.writeCellField("lines", "stress", rowsOf(10, s, myLines, 1), {});
      if (s == 2) rf.writeCellField("triangles", "membrane_n11", rowsOf(11, s, myTriangles, 1), {});
      if (s == 0) rf.writeStepRow("formfinding/step", std::vector<double>{val(12, 0, 0, 0)});
      const std::vector<double> fr = freqRow(s);
      rf.writeStepRow("freq", fr);
      rf.writeStepRow("stressmax", std::vector<double>{7.0 * (s + 1)});
      // Rank 0's values only; the row length is fixed by the first row that has values.
      const std::vector<double> tip = s == 0 ? std::vector<double>{} : std::vector<double>{s - 0.5, 0.5 - s};
      rf.writeStepRow("sensors/tip", rank == 0 ? std::span<const double>(tip) : std::span<const double>());
      rf.writeStepRow("late", std::vector<double>{});
    }
    // Errors are raised on every rank, and the file stays usable afterwards.
    expectThrowOnAllRanks([&] { rf.writeStepRow("freq", std::vector<double>{1, 2, 3, 4, 5}); },
                          "a step row longer than its first");
    expectThrowOnAllRanks(
        [&] {
          std::vector<double> v = rowsOf(1, 2, L.ownedNodes, 3);
          if (rank == nproc - 1) v.pop_back();
          rf.writeNodeField("node/p", v, {3});
        },
        "wrong value count on one rank");
    expectThrowOnAllRanks(
        [&] {
          std::vector<double> v = rowsOf(1, 2, L.ownedNodes, 3);
          if (rank == nproc - 1) v.push_back(0.0);
          rf.writeNodeField("node/new", v, {3});  // a new name: the lookup stays collective
        },
        "wrong value count on one rank, new dataset");
    expectThrowOnAllRanks([&] { rf.writeNodeField("node/p", rowsOf(2, 2, L.ownedNodes, 36), {6, 6}); },
                          "changing the inner shape");
    expectThrowOnAllRanks([&] { rf.writeNodeField("node/p0", rowsOf(1, 2, L.ownedNodes, 3), {3}); },
                          "a field over an array");
    expectThrowOnAllRanks([&] { rf.writeArray("mesh/lines", std::vector<double>{1}, {1}); }, "an array over a mesh dataset");
    expectThrowOnAllRanks([&] { rf.beginStep(5, 2.0); }, "a step out of order");
    expectThrowOnAllRanks([&] { rf.writeArray("bad", std::vector<double>{1, 2, 3}, {2, 2}); }, "a wrong array size");
    rf.writeArray("formfinding/residual", std::vector<double>{1e-1, 1e-4, 1e-9}, {3});
    rf.close(true);
    rf.close(false);  // idempotent: keeps converged = 1
    expectThrowOnAllRanks([&] { rf.beginStep(3, 2.0); }, "a step after close");
  } catch (const std::exception& e) {
    expect(false, std::string("unexpected exception: ") + e.what());
  }
  MPI_Barrier(MPI_COMM_WORLD);
  if (rank == 0) checkMainFile(path, xdmf, scene);

  // XDMF times: form-finding rows at -nff .. -1, load steps at their load factor when increasing,
  // otherwise (a continuation path turning back) at their number; dynamics from t = 0.
  using V = std::vector<double>;
  using F = std::vector<char>;
  expect(sinew::xdmfTimes(V{0, 0, 0, 0.5, 1}, F{1, 1, 1}) == V{-3, -2, -1, 0.5, 1}, "xdmfTimes: form finding + statics");
  expect(sinew::xdmfTimes(V{0, 0, 0.5, 0.4}, F{1, 1}) == V{-2, -1, 1, 2}, "xdmfTimes: a path turning back");
  expect(sinew::xdmfTimes(V{0, 0.1, 0.2}, F{}) == V{0, 0.1, 0.2}, "xdmfTimes: dynamics");
  expect(sinew::xdmfTimes(V{0, -0.1}, F{}) == V{1, 2}, "xdmfTimes: a negative load factor");

  // An interrupted run: the destructor closes with converged = 0, and the file is still published.
  const std::string path2 = fs::path(path).replace_filename(fs::path(path).stem().string() + "_interrupted.h5");
  try {
    sinew::ResultLayout L = makeLayout("interrupted");
    L.stepName = "time";
    sinew::Hdf5ResultFile rf(MPI_COMM_WORLD, path2, L);
    rf.beginStep(0, 0.125);
    rf.writeNodeField("node/p", rowsOf(1, 0, L.ownedNodes, 3), {3});
  } catch (const std::exception& e) {
    expect(false, std::string("unexpected exception: ") + e.what());
  }
  MPI_Barrier(MPI_COMM_WORLD);
  if (rank == 0) checkInterruptedFile(path2);

  // Layout errors are caught on every rank before the file is created.
  expectThrowOnAllRanks(
      [&] {
        sinew::ResultLayout L = makeLayout("bad");
        if (rank == 0) L.ownedNodes.push_back(kNodes);
        sinew::Hdf5ResultFile rf(MPI_COMM_WORLD, path + ".bad.h5", L);
      },
      "an owned row out of range");
  expectThrowOnAllRanks(
      [&] {
        sinew::ResultLayout L = makeLayout("bad");
        if (rank == nproc - 1) L.meshReference.pop_back();
        sinew::Hdf5ResultFile rf(MPI_COMM_WORLD, path + ".bad.h5", L);
      },
      "a mesh reference of the wrong size");
  if (nproc > 1)
    expectThrowOnAllRanks(
      [&] {
        sinew::ResultLayout L = makeLayout("bad");
        L.ownedNodes.assign(1, 0);  // every rank claims node 0
        sinew::Hdf5ResultFile rf(MPI_COMM_WORLD, path + ".bad.h5", L);
      },
      "a row owned twice");

  // The Python tools, when python3 with h5py is at hand.
  if (rank == 0) {
    std::string root = fs::path(__FILE__).parent_path().parent_path().parent_path().string();
    if (root.empty()) root = ".";
    for (const char* py : {"python3", "/usr/bin/python3"}) {
      if (runScript(std::string(py) + " -c 'import h5py, matplotlib' >/dev/null 2>&1") != 0) continue;
      expect(runScript(std::string(py) + " -c 'import xml.etree.ElementTree as E; E.parse(\"" + xdmf + "\")'") == 0,
             "XDMF parses as XML");
      expect(runScript(std::string(py) + " " + root + "/scripts/h5check.py " + path + " >/dev/null") == 0,
             "scripts/h5check.py");
      const std::string png = path + ".loadpath.png";
      expect(runScript(std::string(py) + " " + root + "/scripts/plot_loadpath.py " + path + " --node 2 --dir abs -o " +
                       png + " >/dev/null") == 0 && fs::exists(png),
             "scripts/plot_loadpath.py");
      break;
    }
  }

  int total = failures;
  MPI_Allreduce(MPI_IN_PLACE, &total, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  if (rank == 0) std::cout << (total ? "test_result_file: FAILED " + std::to_string(total) : std::string("test_result_file: OK")) << "\n";
  MPI_Finalize();
  return total ? 1 : 0;
}
