// The library entry point (sinew/simulation.hpp) on the ranks it is started with (ctest: 1 and 2):
// - a cantilever built as a Model in code runs with its results in memory, writes no file, and gives
//   the datasets of the same scene given as YAML text bit for bit, with the tip deflection of beam
//   theory (P L^3 / 3EI, a small load);
// - settings.output.file writes the HDF5 file, whose /node/p equals the in-memory one bit for bit;
// - a scene error, an unknown flag and a PETSc error come back as RunError with the exit code and
//   the message naming the field or flag; a Newton failure returns its converged steps (exit 3,
//   converged 0); the process goes on after each.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <set>

#include "settings/settings.hpp"
#include "sinew/simulation.hpp"

namespace {

constexpr double kL = 0.5, kE = 210e9, kG = 80e9, kB = 0.02, kH = 0.004, kP = 0.5;

/// Cantilever along x, clamped at node 1, a load -P in z at node 2; 8 beam elements.
sinew::Model cantileverModel() {
  sinew::Model m;
  m.title = "cantilever";
  m.nodes = {{0, 0, 0}, {kL, 0, 0}};
  m.elements = {{0, 1}};
  m.elementSet = {0};
  m.connectedNodes = 2;
  m.nprops[0].fix = true;
  m.nprops[1].force = {0, 0, -kP};
  sinew::ElementSet set;
  set.elems = {0};
  set.nbeams = 8;
  sinew::BeamProperties beam;
  beam.flex = {true, true, true, true, true, true};
  beam.emod = kE;
  beam.smod = kG;
  beam.cshape = sinew::CrossSection::Rect;
  beam.dim = {kB, kH};
  beam.orien = sinew::Vec3{0, 1, 0};
  set.props = beam;
  m.eprops = {set};
  m.opt.loadsteps = 2;
  m.opt.calccompl = false;
  m.opt.filename = "cantilever";
  return m;
}

const char* kCantileverYaml = R"(title: cantilever
nodes: [[0, 0, 0], [0.5, 0, 0]]
elements: [[1, 2]]
nprops:
  1: {fix: true}
  2: {force: [0, 0, -0.5]}
eprops:
  - {elems: [1], nbeams: 8, flex: [1, 2, 3, 4, 5, 6], emod: 210e9, smod: 80e9, cshape: rect, dim: [0.02, 0.004], orien: [0, 1, 0]}
opt: {loadsteps: 2, calccompl: false, filename: cantilever}
)";

std::set<std::string> filesHere() {
  std::set<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(".")) names.insert(e.path().filename().string());
  return names;
}

bool sameBits(const sinew::ResultArray& a, const sinew::ResultArray& b) {
  if (a.shape != b.shape || a.integers != b.integers || a.values.size() != b.values.size()) return false;
  for (std::size_t i = 0; i < a.values.size(); ++i)
    if (std::memcmp(&a.values[i], &b.values[i], sizeof(double)) != 0) return false;
  return true;
}

std::vector<double> readDataset(const std::string& file, const char* name) {
  std::vector<double> out;
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t d = H5Dopen2(f, name, H5P_DEFAULT);
  const hid_t s = H5Dget_space(d);
  out.resize(static_cast<std::size_t>(H5Sget_simple_extent_npoints(s)));
  H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data());
  H5Sclose(s);
  H5Dclose(d);
  H5Fclose(f);
  return out;
}

TEST(SimulationApi, ModelFromDataInMemoryNoFile) {
  const std::set<std::string> before = filesHere();
  sinew::Settings settings;
  const sinew::RunOutput data = sinew::run(MPI_COMM_WORLD, sinew::SceneSource::fromModel(cantileverModel()), settings);
  const sinew::RunOutput text = sinew::run(MPI_COMM_WORLD, sinew::SceneSource::yaml(kCantileverYaml), settings);
  MPI_Barrier(MPI_COMM_WORLD);
  EXPECT_EQ(filesHere(), before) << "an in-memory run wrote a file";
  ASSERT_EQ(data.exitCode, 0) << data.output;
  EXPECT_TRUE(data.file.empty());
  EXPECT_EQ(data.results.numbers.at("converged"), 1);
  const sinew::ResultArray* p = data.results.find("node/p");
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(p->shape, (std::vector<long>{2, 2, 3}));
  // beam theory: w = P L^3 / (3 E I), I = b h^3 / 12 (bending about y, h along z)
  const double I = kB * kH * kH * kH / 12, w = kP * kL * kL * kL / (3 * kE * I);
  EXPECT_NEAR(p->values[(1 * 2 + 1) * 3 + 2], -w, 2e-3 * w);
  for (const char* name : {"load_factor", "node/p", "node/r_quat", "node/Freac", "mesh/p0", "mesh/lines"}) {
    ASSERT_TRUE(text.results.find(name)) << name;
    EXPECT_TRUE(sameBits(*data.results.find(name), *text.results.find(name))) << name;
  }
  EXPECT_EQ(data.results.datasets.size(), text.results.datasets.size());
  for (const auto& [name, a] : data.results.datasets)  // on every rank (/node/p0: rank 0's array)
    EXPECT_EQ(a.integer ? a.integers.size() : a.values.size(), static_cast<std::size_t>(a.size())) << name;
  EXPECT_EQ(data.results.find("node/p0")->shape, (std::vector<long>{2, 3}));
}

TEST(SimulationApi, FileWhenAsked) {
  sinew::Settings settings;
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const std::string path = "api_file_" + std::to_string(size) + ".h5";
  settings.output.file = path;
  const sinew::RunOutput file = sinew::run(MPI_COMM_WORLD, sinew::SceneSource::yaml(kCantileverYaml), settings);
  EXPECT_EQ(file.file, path);
  EXPECT_TRUE(file.results.datasets.empty());
  const sinew::RunOutput memory = sinew::run(MPI_COMM_WORLD, sinew::SceneSource::yaml(kCantileverYaml), sinew::Settings{});
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0) {
    EXPECT_EQ(readDataset(path, "/node/p"), memory.results.find("node/p")->values);
  }
}

TEST(SimulationApi, SceneErrorNamesTheField) {
  std::string yaml = kCantileverYaml;
  yaml.replace(yaml.find("emod: 210e9"), 11, "emod: -1");
  try {
    sinew::run(MPI_COMM_WORLD, sinew::SceneSource::yaml(yaml), sinew::Settings{});
    ADD_FAILURE() << "no RunError";
  } catch (const sinew::RunError& e) {
    EXPECT_EQ(e.exitCode(), 2);
    EXPECT_NE(std::string(e.what()).find("eprops(1).emod"), std::string::npos) << e.what();
  }
}

/// A Model built in code gets the scene reader's checks of the model itself (before: an element
/// naming node 5 of 2 reached the mesh code unchecked and read past the node array).
TEST(SimulationApi, ModelFromCodeIsChecked) {
  const auto refused = [](sinew::Model m, const std::string& path) {
    try {
      sinew::run(MPI_COMM_WORLD, sinew::SceneSource::fromModel(std::move(m)), sinew::Settings{});
      ADD_FAILURE() << "no RunError for " << path;
    } catch (const sinew::RunError& e) {
      EXPECT_EQ(e.exitCode(), 2);
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
  };
  sinew::Model m = cantileverModel();
  m.elements = {{0, 4}};
  refused(m, "elements(1,2): expected a node number 1..2");
  m = cantileverModel();
  m.eprops[0].elems = {1};
  refused(m, "eprops(1).elems(1): expected a element number 1..1");
  m = cantileverModel();
  m.nprops[6].force = {1, 0, 0};
  refused(m, "nprops(7)");
  m = cantileverModel();
  m.nodes[1] = m.nodes[0];
  refused(m, "zero length");
  m = cantileverModel();
  m.elementSet = {-1};
  refused(m, "elementSet");
  // elementSet and connectedNodes are derived when left out: the same run as the complete Model
  m = cantileverModel();
  m.elementSet.clear();
  m.connectedNodes = 0;
  const sinew::RunOutput derived = sinew::run(MPI_COMM_WORLD, sinew::SceneSource::fromModel(m), sinew::Settings{});
  const sinew::RunOutput full = sinew::run(MPI_COMM_WORLD, sinew::SceneSource::fromModel(cantileverModel()), sinew::Settings{});
  EXPECT_EQ(derived.results.find("node/p")->values, full.results.find("node/p")->values);
}

TEST(SimulationApi, UnknownFlag) {
  try {
    sinew::run(MPI_COMM_WORLD, sinew::SceneSource::yaml(kCantileverYaml), std::vector<sinew::Flag>{{"loadstep", "3"}});
    ADD_FAILURE() << "no RunError";
  } catch (const sinew::RunError& e) {
    EXPECT_EQ(e.exitCode(), 2);
    EXPECT_NE(std::string(e.what()).find("did you mean -loadsteps?"), std::string::npos) << e.what();
  }
}

TEST(SimulationApi, NewtonFailureKeepsConvergedSteps) {
  // a load 2000 times larger in one step, Newton limited to 2 iterations and no cuts
  std::string yaml = kCantileverYaml;
  yaml.replace(yaml.find("-0.5"), 4, "-1000");
  const sinew::RunOutput out = sinew::run(MPI_COMM_WORLD, sinew::SceneSource::yaml(yaml),
                                          std::vector<sinew::Flag>{{"snes_max_it", "2"}, {"max_cuts", "0"}});
  EXPECT_EQ(out.exitCode, 3) << out.output;
  EXPECT_EQ(out.results.numbers.at("converged"), 0);
  EXPECT_NE(out.message.find("error"), std::string::npos);
  // the flags held for that run only: the same scene converges without them
  const sinew::RunOutput again = sinew::run(MPI_COMM_WORLD, sinew::SceneSource::yaml(kCantileverYaml), sinew::Settings{});
  EXPECT_EQ(again.exitCode, 0) << again.output;
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  sinew::initialize(&argc, &argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0) delete ::testing::UnitTest::GetInstance()->listeners().Release(
                     ::testing::UnitTest::GetInstance()->listeners().default_result_printer());
  int failed = RUN_ALL_TESTS();
  MPI_Allreduce(MPI_IN_PLACE, &failed, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  sinew::finalize();
  return failed;
}
