// R B^-1 R^T with node rotations R: the registered PC type PCNODEROTATED (useNodeRotatedPC).
#include "solvers/ancf/node_rotated_pc.hpp"

#include <petsc/private/pcimpl.h>

namespace sinew {

namespace {

struct NodeRotatedPC {
  KSP inner = nullptr;  ///< holds B^-1 (its PC), set up with B
  PC pc = nullptr;      ///< inner's PC
  const CorotatedNewtonMatrix* turns = nullptr;
  const bool* active = nullptr;
  Vec w = nullptr;  ///< R^T x
};

NodeRotatedPC* data(PC pc) { return static_cast<NodeRotatedPC*>(pc->data); }

/// The inner KSP, created on first use with the options prefix -<this PC's prefix>rotated_.
PetscErrorCode innerKSP(PC pc, KSP* inner) {
  PetscFunctionBeginUser;
  NodeRotatedPC* ctx = data(pc);
  if (!ctx->inner) {
    PetscCall(KSPCreate(PetscObjectComm(reinterpret_cast<PetscObject>(pc)), &ctx->inner));
    PetscCall(KSPSetType(ctx->inner, KSPPREONLY));
    const char* prefix = nullptr;
    PetscCall(PCGetOptionsPrefix(pc, &prefix));
    PetscCall(KSPSetOptionsPrefix(ctx->inner, prefix));
    PetscCall(KSPAppendOptionsPrefix(ctx->inner, "rotated_"));
  }
  *inner = ctx->inner;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode rotatedReset(PC pc) {
  PetscFunctionBeginUser;
  NodeRotatedPC* ctx = data(pc);
  if (ctx->inner) PetscCall(KSPReset(ctx->inner));
  PetscCall(VecDestroy(&ctx->w));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode rotatedDestroy(PC pc) {
  PetscFunctionBeginUser;
  NodeRotatedPC* ctx = data(pc);
  PetscCall(rotatedReset(pc));
  PetscCall(KSPDestroy(&ctx->inner));
  delete ctx;
  pc->data = nullptr;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode rotatedSetFromOptions(PC pc, PetscOptionItems*) {
  PetscFunctionBeginUser;
  KSP inner = nullptr;
  PetscCall(innerKSP(pc, &inner));
  PetscCall(KSPSetFromOptions(inner));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode rotatedSetUp(PC pc) {
  PetscFunctionBeginUser;
  NodeRotatedPC* ctx = data(pc);
  if (!ctx->turns || !ctx->active)
    SETERRQ(PetscObjectComm(reinterpret_cast<PetscObject>(pc)), PETSC_ERR_ARG_WRONGSTATE,
            "PC noderotated: no node turns given (useNodeRotatedPC)");
  KSP inner = nullptr;
  PetscCall(innerKSP(pc, &inner));
  Mat B;
  PetscCall(PCGetOperators(pc, nullptr, &B));
  PetscCall(KSPSetOperators(inner, B, B));
  PetscCall(KSPSetUp(inner));
  if (!ctx->w) PetscCall(MatCreateVecs(B, &ctx->w, nullptr));
  PetscCall(KSPGetPC(inner, &ctx->pc));
  PCFailedReason why = PC_NOERROR;
  PetscCall(PCGetFailedReasonRank(ctx->pc, &why));
  if (why != PC_NOERROR) PetscCall(PCSetFailedReason(pc, why));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode rotatedApply(PC pc, Vec x, Vec y) {
  PetscFunctionBeginUser;
  NodeRotatedPC* ctx = data(pc);
  if (!*ctx->active) PetscFunctionReturn(PCApply(ctx->pc, x, y));
  const PetscScalar* xa;
  PetscScalar* a;
  PetscCall(VecGetArrayRead(x, &xa));
  PetscCall(VecGetArray(ctx->w, &a));
  ctx->turns->rotateNodes(xa, a, true);
  PetscCall(VecRestoreArray(ctx->w, &a));
  PetscCall(VecRestoreArrayRead(x, &xa));
  PetscCall(PCApply(ctx->pc, ctx->w, y));
  PetscCall(VecGetArray(y, &a));
  ctx->turns->rotateNodes(a, a, false);
  PetscCall(VecRestoreArray(y, &a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode rotatedView(PC pc, PetscViewer viewer) {
  PetscFunctionBeginUser;
  NodeRotatedPC* ctx = data(pc);
  PetscCall(PetscViewerASCIIPrintf(viewer, "  R B^-1 R^T, R: node turns since B was built (%s); B^-1:\n",
                                   ctx->active && *ctx->active ? "in use" : "not yet in use"));
  if (ctx->inner) {
    PetscCall(PetscViewerASCIIPushTab(viewer));
    PetscCall(KSPView(ctx->inner, viewer));
    PetscCall(PetscViewerASCIIPopTab(viewer));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/// PCCreate for PCNODEROTATED (PCRegister).
PetscErrorCode createNodeRotated(PC pc) {
  PetscFunctionBeginUser;
  pc->data = new NodeRotatedPC;
  pc->ops->setup = rotatedSetUp;
  pc->ops->apply = rotatedApply;
  pc->ops->reset = rotatedReset;
  pc->ops->destroy = rotatedDestroy;
  pc->ops->view = rotatedView;
  pc->ops->setfromoptions = rotatedSetFromOptions;
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace

PetscErrorCode registerNodeRotatedPC() {
  PetscFunctionBeginUser;
  PetscCall(PCRegister(PCNODEROTATED, createNodeRotated));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode useNodeRotatedPC(KSP ksp, const CorotatedNewtonMatrix& turns, const bool* active, KSP* inner) {
  PetscFunctionBeginUser;
  PetscCall(registerNodeRotatedPC());
  PC pc;
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCNODEROTATED));
  NodeRotatedPC* ctx = data(pc);
  ctx->turns = &turns;
  ctx->active = active;
  PetscCall(innerKSP(pc, inner));
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
