// The kind-neutral kernel interfaces the analyses use instead of casts to concrete kernels
// (include/sinew/element_kernel.hpp): FormFindingKernel (form finding), the sensor methods
// (hasSensors, sensorPosition, sensorValueCount, sensorValue), tensionOnly/slack (the assembler's slack-cable spring), referenceLength. Each gives
// bit for bit what the kind's own methods give.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "elements/ancf_cable2d.hpp"
#include "elements/beam_corotational.hpp"
#include "elements/cable3d.hpp"
#include "elements/membrane.hpp"
#include "sinew/rotation.hpp"

using namespace sinew;

namespace {

std::vector<double> force(const ElementKernel& k, const double* q) {
  KernelOutput out;
  k.evaluate(KernelInput{q}, KernelNeeds{true, false, false}, out);
  std::vector<double> r = out.f;
  r.insert(r.end(), out.K.begin(), out.K.end());
  return r;
}

std::vector<double> checkpoint(const ElementKernel& k) {
  std::vector<double> c(static_cast<size_t>(k.checkpointSize()));
  k.saveCheckpoint(c.data());
  return c;
}

}  // namespace

TEST(KernelInterfaces, CableFormFindingThroughTheInterface) {
  Cable3D direct({0, 0, 0}, {2, 0, 0}, 1e-4, 2e11, 0.0, 4.0);
  Cable3D viaInterface = direct;
  FormFindingKernel* f = static_cast<ElementKernel&>(viaInterface).formFinding();
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->shapeType(), FormFindingKernel::Shape::Line);
  const double q[6] = {0.1, 0, 0.2, 1.4, 0.3, -0.1};
  // step of form finding: homotopy 0.3, stress adaption lambdaMax 1.25, relaxation 0.1
  direct.setFormFinding(true, 0.3);
  direct.setStressAdaption(1.25, 0.1);
  f->enterFormFinding(0.3, true);
  f->setAdaption(1.25, 0.1, 2.0);
  EXPECT_TRUE(viaInterface.inFormFinding());
  EXPECT_EQ(force(viaInterface, q), force(direct, q));
  EXPECT_EQ(f->size(q), direct.length(q));
  EXPECT_EQ(f->meshQuality(q), 1.0);
  direct.updateReference(q);
  f->updateReference(q);
  EXPECT_EQ(checkpoint(viaInterface), checkpoint(direct));
  // the shape axis is the unit chord
  const Vec3 a = f->shapeAxis(q);
  EXPECT_NEAR(norm(a), 1.0, 1e-15);
  EXPECT_NEAR(dot(a, Vec3{1.3, 0.3, -0.3}), std::sqrt(1.3 * 1.3 + 0.18), 1e-15);
  // collapsed: zero length relative to the model size
  const double zero[6] = {1, 1, 1, 1, 1, 1 + 1e-14};
  EXPECT_TRUE(f->collapsed(zero, 0.0, 100.0));
  EXPECT_FALSE(f->collapsed(q, 0.0, 100.0));
  // elastic restart NONE: no prestress, reference from the initial shape
  f->leaveFormFinding();
  EXPECT_FALSE(viaInterface.inFormFinding());
  f->clearPrestress();
  const double X[6] = {0, 0, 0, 3, 4, 0};
  f->setReference(X);
  EXPECT_EQ(viaInterface.prestressForce(), 0.0);
  EXPECT_EQ(viaInterface.referenceLength(), 5.0);
  EXPECT_EQ(static_cast<const ElementKernel&>(viaInterface).referenceLength(), 5.0);
}

TEST(KernelInterfaces, CableSlackSpring) {
  const Cable3D taut({0, 0, 0}, {2, 0, 0}, 1e-4, 2e11, 0.0, 4.0);
  const ElementKernel& k = taut;
  EXPECT_TRUE(k.tensionOnly());
  const double stretched[6] = {0, 0, 0, 2.1, 0, 0}, shortened[6] = {0, 0, 0, 1.5, 0, 0};
  double axial = -1.0;
  EXPECT_FALSE(k.slack(stretched, &axial));
  ASSERT_TRUE(k.slack(shortened, &axial));
  EXPECT_EQ(axial, taut.emod() * taut.area());
  // without EA the spring is the prestress force
  const Cable3D soft({0, 0, 0}, {2, 0, 0}, 1e-4, 0.0, 0.0, 0.0);
  ASSERT_TRUE(static_cast<const ElementKernel&>(soft).slack(shortened, &axial));
  EXPECT_EQ(axial, 0.0);
  // never slack in form finding
  Cable3D ff = taut;
  ff.setFormFinding(true, 0.0);
  EXPECT_FALSE(static_cast<const ElementKernel&>(ff).slack(shortened, &axial));
}

TEST(KernelInterfaces, MembraneFormFindingThroughTheInterface) {
  const std::vector<Vec3> X = {{0, 0, 0}, {1, 0, 0}, {1.1, 0.9, 0.1}, {0, 1, 0}};
  MembraneProps mp;
  mp.thickness = 0.01;
  mp.emod = 1e6;
  mp.nu = 0.3;
  mp.prestress = {2.0, 1.0, 0.2};
  Membrane direct(X, mp, PrestressFrame::direction({1, 0.2, 0}));
  Membrane viaInterface = direct;
  FormFindingKernel* f = static_cast<ElementKernel&>(viaInterface).formFinding();
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->shapeType(), FormFindingKernel::Shape::Surface);
  const double q[12] = {0, 0, 0.1, 1.5, 0, 0, 1.3, 1.2, 0.4, 0, 1.1, 0.2};
  direct.setFormFinding(true, 0.4);
  direct.setXurs(true);
  direct.setStressAdaption(1.2, 0.25);
  direct.setDistortionControl(1.5);
  f->enterFormFinding(0.4, true);
  f->setAdaption(1.2, 0.25, 1.5);
  EXPECT_TRUE(viaInterface.inFormFinding());
  EXPECT_TRUE(viaInterface.xurs());
  EXPECT_EQ(force(viaInterface, q), force(direct, q));
  EXPECT_EQ(f->meshQuality(q), direct.meshQuality(q));
  // size: half the cross product of the diagonals; the axis carries it as a a^T = A n n^T
  const Vec3 d1{1.3, 1.2, 0.3}, d2{-1.5, 1.1, 0.2};
  const double area = 0.5 * norm(cross(d1, d2));
  EXPECT_NEAR(f->size(q), area, 1e-15);
  EXPECT_NEAR(dot(f->shapeAxis(q), f->shapeAxis(q)), area, 1e-15);
  EXPECT_FALSE(f->collapsed(q, area, 10.0));
  EXPECT_TRUE(f->collapsed(q, 1001.0 * area, 10.0));
  direct.updateReference(q);
  f->updateReference(q);
  EXPECT_EQ(checkpoint(viaInterface), checkpoint(direct));
  // elastic restart NONE
  f->leaveFormFinding();
  EXPECT_FALSE(viaInterface.inFormFinding());
  EXPECT_FALSE(viaInterface.xurs());
  f->clearPrestress();
  const double X0[12] = {0, 0, 0, 1, 0, 0, 1.1, 0.9, 0.1, 0, 1, 0};
  f->setReference(X0);
  direct.setFormFinding(false, 0.0);
  direct.setXurs(false);
  direct.setPrestress({0.0, 0.0, 0.0});
  direct.setReference(X0);
  EXPECT_EQ(checkpoint(viaInterface), checkpoint(direct));
  EXPECT_EQ(force(viaInterface, q), force(direct, q));
}

TEST(KernelInterfaces, KindsWithoutAnInterfaceSayNo) {
  const std::vector<Vec3> X = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  Membrane m(X, MembraneProps{});
  EXPECT_FALSE(static_cast<const ElementKernel&>(m).hasSensors());
  EXPECT_FALSE(static_cast<const ElementKernel&>(m).tensionOnly());
  EXPECT_EQ(static_cast<const ElementKernel&>(m).referenceLength(), 0.0);
  BeamSection s;
  s.EA = 3.0;
  s.GIt = s.EIy = s.EIz = 1.0;
  BeamCorotational b({0, 0, 0}, {2, 0, 0}, Vec3{0, 0, 1}, s, {}, false, 1.0);
  EXPECT_EQ(static_cast<ElementKernel&>(b).formFinding(), nullptr);
  EXPECT_FALSE(static_cast<const ElementKernel&>(b).tensionOnly());
  EXPECT_EQ(static_cast<const ElementKernel&>(b).referenceLength(), 2.0);
}

TEST(KernelInterfaces, BeamSensorThroughTheInterface) {
  BeamSection s;
  s.EA = 3.0; s.GIt = 0.7; s.EIy = 1.3; s.EIz = 0.9; s.kGAy = 40.0; s.kGAz = 25.0;
  constexpr BeamMode F = BeamMode::Flexible;
  const Vec3 Xp{0.1, -0.2, 0.3}, Xq{1.1, 0.4, 0.1};
  const BeamCorotational b(Xp, Xq, Vec3{0, 0, 1}, s, {F, F, F, F, F, F}, false, 1.0);
  const ElementKernel* k = &b;
  ASSERT_TRUE(k->hasSensors());
  // xi counts along the split scene element
  EXPECT_EQ(k->sensorPosition(0.7, 0.35, 4), 0.35 * 4);
  std::array<double, 24> q{};
  const Vec3 xp = Xp + Vec3{0.01, 0.02, -0.01}, xq = Xq + Vec3{-0.02, 0.01, 0.03};
  const Mat3 Rp = expSO3({0.1, -0.05, 0.2}), Rq = expSO3({-0.1, 0.15, 0.05});
  for (int i = 0; i < 3; ++i) q[i] = xp[i], q[12 + i] = xq[i];
  for (int i = 0; i < 9; ++i) q[3 + i] = Rp[i], q[15 + i] = Rq[i];
  const double disp[6] = {0.01, 0.02, -0.01, -0.02, 0.01, 0.03};
  double rates[12];
  for (int i = 0; i < 12; ++i) rates[i] = 0.1 * (i + 1) - 0.5;
  SensorInput in;
  in.q = q.data();
  in.disp = disp;
  in.qdot = rates;
  for (const std::string& var : BeamCorotational::sensorVariables()) {
    EXPECT_EQ(k->sensorValueCount(var), 3);
    const std::array<double, 3> direct = b.sensorValue(var, 0.3, q.data(), disp, rates, nullptr);
    EXPECT_EQ(k->sensorValue(var, 0.3, in), std::vector<double>(direct.begin(), direct.end())) << var;
  }
}

TEST(KernelInterfaces, AncfSensorThroughTheInterface) {
  AncfCable2DParameters p;
  p.physicsMassPerLength = 1.0;
  p.physicsAxialStiffness = 1e4;
  p.physicsBendingStiffness = 30.0;
  p.physicsAxialDamping = 40.0;
  const double L = 0.5;
  const AncfCable2D c({0, 0, 1, 0, L, 0, 1, 0}, L, p);
  const ElementKernel* k = &c;
  ASSERT_TRUE(k->hasSensors());
  EXPECT_EQ(static_cast<const ElementKernel&>(c).referenceLength(), L);
  // x counts along the scene element split into 4 elements of length L
  EXPECT_EQ(k->sensorPosition(1.3, 0.65, 4), 1.3 / (L * 4) * 4);
  const double q[8] = {0.01, 0.02, 0.99, 0.05, 0.51, 0.04, 0.98, -0.03};
  const double qd[8] = {0.1, -0.2, 0.01, 0.02, 0.3, 0.1, -0.01, 0.0};
  const double qdd[8] = {1.0, 0.5, 0.0, 0.1, -0.2, 0.3, 0.02, 0.01};
  SensorInput in;
  in.q = q;
  in.qdot = qd;
  in.qddot = qdd;
  in.t = 0.25;
  for (const std::string& var : AncfCable2D::outputVariables()) {
    const std::vector<double> direct = c.output(var, 0.3 * L, q, qd, qdd, 0.25);
    EXPECT_EQ(k->sensorValue(var, 0.3, in), direct) << var;
    EXPECT_EQ(k->sensorValueCount(var), static_cast<int>(direct.size())) << var;
  }
}
