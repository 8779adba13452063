#include "app/phases/run_context.hpp"
#include "step/buckling_analysis.hpp"
#include "step/compliance_analysis.hpp"
#include "step/modal_analysis.hpp"
#include "step/sensor_analysis.hpp"
#include "step/state_space.hpp"

namespace sinew {

PetscErrorCode addStepAnalyses(RunContext& ctx) {
  PetscFunctionBeginUser;
  // eigen analyses: no EPS object and no mass matrix unless the plan asks for them
  if (ctx.plan.frequencies || ctx.plan.transfer) {
    auto modal = std::make_unique<ModalAnalysis>(ctx.assembler, ctx.model.opt.nfreq, ctx.plan.frequencies, ctx.settings.eigen);
    const ModalAnalysis& modes = *modal;
    ctx.stepAnalyses.push_back(std::move(modal));
    if (ctx.plan.transfer)
      ctx.stepAnalyses.push_back(
          std::make_unique<StateSpaceAnalysis>(ctx.assembler, modes, ctx.model, ctx.model.opt.transfer_zeta));
  }
  if (ctx.plan.buckling)
    ctx.stepAnalyses.push_back(std::make_unique<BucklingAnalysis>(ctx.assembler, ctx.model.opt.nbuck, ctx.settings.eigen));
  if (ctx.plan.compliance)
    ctx.stepAnalyses.push_back(
        std::make_unique<ComplianceAnalysis>(ctx.assembler, ctx.model.opt.compliance_nodes, ctx.settings.compliance,
                                             ctx.settings.statics.denseMaxUnknowns));
  if (!ctx.model.sensors.empty())
    ctx.stepAnalyses.push_back(std::make_unique<SensorAnalysis>(ctx.assembler, ctx.model.sensors));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
