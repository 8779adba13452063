// readSettings (src/settings/read_settings.cpp) maps flags to settings fields, and an analysis is
// built with settings chosen in code, without any option in PETSc's database. Exit status 0 only
// when every check passed.
//  (1) An empty options object gives the structs' defaults (Settings{}).
//  (2) Flags set in an options object land in their fields: numbers, bools, choices (also the
//      optional ones), texts, given-only options and scene opt fields.
//  (3) StaticAnalysis on an ANCF cable with tangentOperator Elementwise solves its Newton systems
//      by GMRES, with Assembled by the LU alone (KSPPREONLY): the settings object decides.
#include <petscsnes.h>

#include <cstdio>
#include <string>

#include "analysis/static_analysis.hpp"
#include "assembly/assembler.hpp"
#include "assembly/kernel_factory.hpp"
#include "mesh/distributed_mesh.hpp"
#include "mesh/fe_mesh.hpp"
#include "scene/scene_reader.hpp"
#include "settings/read_settings.hpp"

namespace {

int failures = 0;

void expect(bool ok, const char* what) {
  PetscPrintf(PETSC_COMM_WORLD, "  %-66s %s\n", what, ok ? "ok" : "FAILED");
  if (!ok) ++failures;
}

PetscErrorCode readFrom(const char* flags, sinew::Settings* s) {
  PetscFunctionBeginUser;
  PetscOptions options;
  PetscCall(PetscOptionsCreate(&options));
  PetscCall(PetscOptionsInsertString(options, flags));
  PetscCall(sinew::readSettings(options, s));
  PetscCall(PetscOptionsDestroy(&options));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode checkReader() {
  PetscFunctionBeginUser;
  sinew::Settings s;
  s.statics.maxCuts = 7;  // chosen in code: an absent flag keeps it
  PetscCall(readFrom("", &s));
  expect(s.statics.maxCuts == 7, "an absent flag leaves its field as it was");
  s = sinew::Settings{};
  PetscCall(readFrom("", &s));
  expect(s == sinew::Settings{}, "no flags: the structs' defaults");
  PetscCall(readFrom("-max_cuts 3 -predictor false -force_rtol 1e-9 -tangent_operator assembled -dynamics_scheme midpoint "
                     "-dynamics_adapt error -dynamics_dt_min 1e-3 -dynamics_modified_newton false -ancf_coarse_ratio 0 "
                     "-eps_target 2.5 -buck_eps_nev 4 -compliance_method dense -mat_mumps_icntl_14 50 -o out.h5 "
                     "-restart old.h5 -checkpoint no -loadsteps 40 -calcbuck -beam_mass lumped -dynamics_energy",
                     &s));
  expect(s.statics.maxCuts == 3, "-max_cuts 3");
  expect(s.statics.predictor == std::optional<bool>(false), "-predictor false");
  expect(s.statics.forceRtol == std::optional<double>(1e-9), "-force_rtol 1e-9");
  expect(s.statics.tangentOperator == sinew::OperatorChoice::Assembled, "-tangent_operator assembled");
  expect(s.statics.divergedIts == std::nullopt, "-newton_diverged_its not given: left to the model");
  expect(s.dynamics.scheme == sinew::DynamicsScheme::Midpoint, "-dynamics_scheme midpoint");
  expect(s.dynamics.adapt == sinew::TimeStepControl::Error, "-dynamics_adapt error");
  expect(s.dynamics.dtMin == std::optional<double>(1e-3) && !s.dynamics.dtMax, "-dynamics_dt_min 1e-3 (dt_max: the scene's)");
  expect(s.dynamics.modifiedNewton == sinew::AutoSwitch::Off, "-dynamics_modified_newton false");
  expect(s.dynamics.mumpsWorkspace == 50, "-mat_mumps_icntl_14 50");
  expect(s.dynamics.beamMass == sinew::BeamMass::Lumped && s.dynamics.energy, "-beam_mass lumped -dynamics_energy");
  expect(s.ancf.coarseRatio == std::optional<int>(0), "-ancf_coarse_ratio 0");
  expect(s.eigen.userTarget && s.eigen.userBucklingNev, "-eps_target and -buck_eps_nev given");
  expect(s.compliance.method == sinew::ComplianceMethod::DenseRhs, "-compliance_method dense");
  expect(s.output.file == std::optional<std::string>("out.h5") && s.output.restart == "old.h5" && !s.output.checkpoint,
         "-o out.h5 -restart old.h5 -checkpoint no");
  expect(s.sceneOpt.size() == 2 && s.sceneOpt["loadsteps"] == "40" && s.sceneOpt["calcbuck"].empty(),
         "scene opt fields -loadsteps 40 -calcbuck");
  const sinew::OptionOverride over = sinew::sceneOverrides(s);
  expect(over("loadsteps") == std::optional<std::string>("40") && !over("nfreq"), "sceneOverrides gives them to the reader");
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode newtonKsp(const sinew::StaticsSettings& statics, std::string* type) {
  PetscFunctionBeginUser;
  const std::string scene =
      R"({"nodes": [[0, 0], [1.5, 0]], "elements": [[1, 2]], "nprops": {1: {"fix_coords": [1, 1, 0, 1]}, 2: {"force": [0, -1.0]}},
          "eprops": [{"elems": [1], "type": "ancf_cable2d", "physicsMassPerLength": 1.0, "physicsBendingStiffness": 2.0,
          "physicsAxialStiffness": 5.0e6, "nbeams": 16}], "opt": {"loadsteps": 1, "calcfreq": false}})";
  const sinew::Settings defaults;
  const sinew::Model model = sinew::parseScene(scene, ".");
  const sinew::FeMesh fe = sinew::discretize(model);
  sinew::DistributedMesh mesh =
      sinew::distributeMesh(PETSC_COMM_WORLD, model, fe, sinew::makeKernelFactory(model, defaults.dynamics.beamMassInUse()));
  sinew::Assembler assembler(mesh, model.opt.gravity, statics.assemblyCoo);
  sinew::AncfSettings ancf;
  ancf.coarseRatio = 0;
  sinew::StaticAnalysis analysis(assembler, 1, statics, ancf);
  KSP ksp;
  PetscCall(SNESGetKSP(analysis.snes(), &ksp));
  KSPType t;
  PetscCall(KSPGetType(ksp, &t));
  *type = t;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode checkAnalysis() {
  PetscFunctionBeginUser;
  sinew::StaticsSettings statics;
  std::string type;
  statics.tangentOperator = sinew::OperatorChoice::Elementwise;
  PetscCall(newtonKsp(statics, &type));
  expect(type == KSPGMRES, "tangentOperator Elementwise: GMRES on the element-wise operator");
  statics.tangentOperator = sinew::OperatorChoice::Assembled;
  PetscCall(newtonKsp(statics, &type));
  expect(type == KSPPREONLY, "tangentOperator Assembled: the LU alone");
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace

int main(int argc, char** argv) {
  PetscCall(PetscInitialize(&argc, &argv, nullptr, nullptr));
  PetscPrintf(PETSC_COMM_WORLD, "readSettings:\n");
  PetscCall(checkReader());
  PetscPrintf(PETSC_COMM_WORLD, "StaticAnalysis with settings chosen in code:\n");
  PetscCall(checkAnalysis());
  int all = failures;
  MPI_Allreduce(MPI_IN_PLACE, &all, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD);
  PetscPrintf(PETSC_COMM_WORLD, "%s\n", all ? "FAILED" : "all checks passed");
  PetscCall(PetscFinalize());
  return all ? 1 : 0;
}
