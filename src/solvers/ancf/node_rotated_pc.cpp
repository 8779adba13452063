// R B^-1 R^T with node rotations R (useNodeRotatedPC).
#include "solvers/ancf/node_rotated_pc.hpp"

namespace sinew {

namespace {

struct NodeRotatedPC {
  KSP inner = nullptr;  ///< holds B^-1 (its PC), set up with B
  PC pc = nullptr;      ///< inner's PC
  const Assembler* assembler = nullptr;
  const bool* active = nullptr;
  Vec w = nullptr;  ///< R^T x
};

PetscErrorCode rotatedDestroy(PC pc) {
  PetscFunctionBeginUser;
  NodeRotatedPC* ctx = nullptr;
  PetscCall(PCShellGetContext(pc, &ctx));
  PetscCall(KSPDestroy(&ctx->inner));
  PetscCall(VecDestroy(&ctx->w));
  delete ctx;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode rotatedSetUp(PC pc) {
  PetscFunctionBeginUser;
  NodeRotatedPC* ctx = nullptr;
  PetscCall(PCShellGetContext(pc, &ctx));
  Mat B;
  PetscCall(PCGetOperators(pc, nullptr, &B));
  PetscCall(KSPSetOperators(ctx->inner, B, B));
  PetscCall(KSPSetUp(ctx->inner));
  if (!ctx->w) PetscCall(MatCreateVecs(B, &ctx->w, nullptr));
  PetscCall(KSPGetPC(ctx->inner, &ctx->pc));
  PCFailedReason why = PC_NOERROR;
  PetscCall(PCGetFailedReasonRank(ctx->pc, &why));
  if (why != PC_NOERROR) PetscCall(PCSetFailedReason(pc, why));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode rotatedApply(PC pc, Vec x, Vec y) {
  PetscFunctionBeginUser;
  NodeRotatedPC* ctx = nullptr;
  PetscCall(PCShellGetContext(pc, &ctx));
  if (!*ctx->active) PetscFunctionReturn(PCApply(ctx->pc, x, y));
  const PetscScalar* xa;
  PetscScalar* a;
  PetscCall(VecGetArrayRead(x, &xa));
  PetscCall(VecGetArray(ctx->w, &a));
  ctx->assembler->rotateNodes(xa, a, true);
  PetscCall(VecRestoreArray(ctx->w, &a));
  PetscCall(VecRestoreArrayRead(x, &xa));
  PetscCall(PCApply(ctx->pc, ctx->w, y));
  PetscCall(VecGetArray(y, &a));
  ctx->assembler->rotateNodes(a, a, false);
  PetscCall(VecRestoreArray(y, &a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode rotatedView(PC pc, PetscViewer viewer) {
  PetscFunctionBeginUser;
  NodeRotatedPC* ctx = nullptr;
  PetscCall(PCShellGetContext(pc, &ctx));
  PetscCall(PetscViewerASCIIPrintf(viewer, "  R B^-1 R^T, R: node turns since B was built (%s); B^-1:\n",
                                   *ctx->active ? "in use" : "not yet in use"));
  PetscCall(PetscViewerASCIIPushTab(viewer));
  PetscCall(KSPView(ctx->inner, viewer));
  PetscCall(PetscViewerASCIIPopTab(viewer));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace

PetscErrorCode useNodeRotatedPC(KSP ksp, const Assembler& assembler, const bool* active, KSP* inner) {
  PetscFunctionBeginUser;
  auto* ctx = new NodeRotatedPC;
  ctx->assembler = &assembler;
  ctx->active = active;
  PetscCall(KSPCreate(PetscObjectComm(reinterpret_cast<PetscObject>(ksp)), &ctx->inner));
  PetscCall(KSPSetType(ctx->inner, KSPPREONLY));
  PC pc;
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCSHELL));
  PetscCall(PCShellSetContext(pc, ctx));
  PetscCall(PCShellSetSetUp(pc, rotatedSetUp));
  PetscCall(PCShellSetApply(pc, rotatedApply));
  PetscCall(PCShellSetDestroy(pc, rotatedDestroy));
  PetscCall(PCShellSetView(pc, rotatedView));
  PetscCall(PCShellSetName(pc, "node-rotated kept Newton matrix"));
  *inner = ctx->inner;
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
