// The path-following checkpoint: the path so far as one row of numbers (written after every
// point, restart/), its older layout, and the resume from it.
#include "analysis/continuation_analysis.hpp"

#include <algorithm>
#include <limits>

namespace sinew {

// Checkpoint row: [points, lambda, ds, dlPrev, prevNeg, switched, switchedAt, critical points], then
// kCkPointCols per point, then kCkCritCols per critical point (fixed capacity: max_steps each). ds is
// the step of the point just reported (adapted after it, in run(), also on resume).
std::vector<double> ContinuationAnalysis::checkpointState() const {
  std::vector<double> v(static_cast<size_t>(checkpointSize(opt_.max_steps)), 0.0);
  const PathPoint* last = points_.empty() ? nullptr : &points_.back();
  v[0] = static_cast<double>(points_.size());
  v[1] = last ? last->loadFactor : 0.0;
  v[2] = ckDs_;
  v[3] = ckDlPrev_;
  v[4] = last ? last->negativeEigenvalues : -1;
  v[5] = switched_ ? 1 : 0;
  v[6] = switchedAt_;
  v[7] = static_cast<double>(critical_.size());
  v[8] = ckIts_;
  size_t k = kCkHeader;
  for (size_t i = 0; i < points_.size() && i < static_cast<size_t>(opt_.max_steps); ++i, k += kCkPointCols) {
    const PathPoint& p = points_[i];
    const double row[kCkPointCols] = {static_cast<double>(p.step), p.loadFactor, p.arcLength, static_cast<double>(p.iterations),
                                      static_cast<double>(p.cuts), static_cast<double>(p.negativeEigenvalues), p.controlValue,
                                      p.slopeLoad, p.slopeControl, p.lowestEigenvalue, p.nearestNegative, p.nearestPositive};
    std::copy(row, row + kCkPointCols, v.begin() + static_cast<long>(k));
  }
  k = kCkHeader + static_cast<size_t>(opt_.max_steps) * kCkPointCols;
  for (size_t i = 0; i < critical_.size() && i < static_cast<size_t>(opt_.max_steps); ++i, k += kCkCritCols) {
    const CriticalPoint& c = critical_[i];
    const double row[kCkCritCols] = {static_cast<double>(c.kind), c.interpolated ? 1.0 : 0.0, static_cast<double>(c.afterStep),
                                     c.loadFactor, c.controlValue};
    std::copy(row, row + kCkCritCols, v.begin() + static_cast<long>(k));
  }
  return v;
}

std::vector<double> ContinuationAnalysis::currentCheckpointLayout(const std::vector<double>& v, int maxSteps) {
  if (static_cast<long>(v.size()) != legacyCheckpointSize(maxSteps)) return v;
  std::vector<double> out(static_cast<size_t>(checkpointSize(maxSteps)), std::numeric_limits<double>::quiet_NaN());
  const size_t ms = static_cast<size_t>(maxSteps);
  std::copy_n(v.begin(), kCkHeader, out.begin());
  for (size_t i = 0; i < ms; ++i)
    std::copy_n(v.begin() + static_cast<long>(kCkHeader + i * kCkLegacyPointCols), kCkLegacyPointCols,
                out.begin() + static_cast<long>(kCkHeader + i * kCkPointCols));
  std::copy_n(v.begin() + static_cast<long>(kCkHeader + ms * kCkLegacyPointCols), ms * kCkCritCols,
              out.begin() + static_cast<long>(kCkHeader + ms * kCkPointCols));
  return out;
}

PetscErrorCode ContinuationAnalysis::resume(const std::vector<double>& v, Vec dU) {
  PetscFunctionBeginUser;
  PetscCheck(static_cast<long>(v.size()) >= kCkHeader, asm_.mesh().comm, PETSC_ERR_ARG_SIZ, "path checkpoint: too short");
  const int np = static_cast<int>(v[0]), nc = static_cast<int>(v[7]);
  const long cap = (static_cast<long>(v.size()) - kCkHeader) / (kCkPointCols + kCkCritCols);
  PetscCheck(np >= 1 && np <= cap && nc <= cap, asm_.mesh().comm, PETSC_ERR_ARG_SIZ, "path checkpoint: inconsistent");
  resumeLambda_ = v[1];
  resumeDs_ = v[2];
  resumeDlPrev_ = v[3];
  resumePrevNeg_ = static_cast<int>(v[4]);
  switched_ = v[5] != 0.0;
  switchedAt_ = static_cast<int>(v[6]);
  resumeIts_ = static_cast<int>(v[8]);
  points_.clear();
  critical_.clear();
  for (int i = 0; i < np; ++i) {
    const double* r = &v[kCkHeader + static_cast<size_t>(i) * kCkPointCols];
    PathPoint p;
    p.step = static_cast<int>(r[0]);
    p.loadFactor = r[1];
    p.arcLength = r[2];
    p.iterations = static_cast<int>(r[3]);
    p.cuts = static_cast<int>(r[4]);
    p.negativeEigenvalues = static_cast<int>(r[5]);
    p.controlValue = r[6];
    p.slopeLoad = r[7];
    p.slopeControl = r[8];
    p.lowestEigenvalue = r[9];
    p.nearestNegative = r[10];
    p.nearestPositive = r[11];
    points_.push_back(p);
  }
  for (int i = 0; i < nc; ++i) {
    const double* r = &v[kCkHeader + static_cast<size_t>(cap) * kCkPointCols + static_cast<size_t>(i) * kCkCritCols];
    CriticalPoint c;
    c.kind = static_cast<CriticalPoint::Kind>(static_cast<int>(r[0]));
    c.interpolated = r[1] != 0.0;
    c.afterStep = static_cast<int>(r[2]);
    c.loadFactor = r[3];
    c.controlValue = r[4];
    critical_.push_back(c);
  }
  PetscCall(VecCopy(dU, dUprev_));
  resumed_ = true;
  PetscFunctionReturn(PETSC_SUCCESS);
}

}  // namespace sinew
