// Unit tests of the user force-law expression compiler (src/math/expression.hpp):
// values, exact dual-number derivatives vs. central differences, syntax errors with columns.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "math/expression.hpp"

using sinew::Expression;
using sinew::UfVar;
using sinew::UserFunctionArgs;

namespace {

UserFunctionArgs sampleArgs() {
  UserFunctionArgs a;
  a[UfVar::t] = 0.37;
  a[UfVar::axialPositionNormalized] = 0.25;
  a[UfVar::axialStrain] = 0.013;
  a[UfVar::axialStrain_t] = -0.21;
  a[UfVar::axialStrainRef] = 0.002;
  a[UfVar::curvature] = 0.47;
  a[UfVar::curvature_t] = 1.3;
  a[UfVar::curvatureRef] = 0.1;
  a[UfVar::physicsAxialStiffness] = 1e5;
  a[UfVar::physicsAxialDamping] = 5e3;
  a[UfVar::physicsBendingStiffness] = 2000;
  a[UfVar::physicsBendingDamping] = 200;
  a[UfVar::physicsMassPerLength] = 78;
  a[UfVar::physicsReferenceAxialStrain] = 0.001;
  a[UfVar::physicsReferenceCurvature] = 0.05;
  return a;
}

double eval(const std::string& s) { return Expression::compile(s).value(sampleArgs()); }

/// Max relative error of the four dual derivatives against central differences.
double derivativeError(const Expression& e, const UserFunctionArgs& a0) {
  const sinew::UserFunctionValue v = e.evaluate(a0);
  const double exact[4] = {v.dAxialStrain, v.dAxialStrain_t, v.dCurvature, v.dCurvature_t};
  const UfVar vars[4] = {UfVar::axialStrain, UfVar::axialStrain_t, UfVar::curvature, UfVar::curvature_t};
  double err = 0.0, scale = 1e-300;
  for (int k = 0; k < 4; ++k) scale = std::max(scale, std::fabs(exact[k]));
  for (int k = 0; k < 4; ++k) {
    const double h = 1e-6 * std::max(1.0, std::fabs(a0[vars[k]]));
    UserFunctionArgs ap = a0, am = a0;
    ap[vars[k]] += h;
    am[vars[k]] -= h;
    const double fd = (e.value(ap) - e.value(am)) / (2 * h);
    err = std::max(err, std::fabs(fd - exact[k]) / scale);
  }
  EXPECT_DOUBLE_EQ(v.value, e.value(a0));
  if (std::getenv("EXPR_VERBOSE")) std::printf("  %-60.60s rel err %.2e\n", e.text().c_str(), err);
  return err;
}

std::string errorOf(const std::string& text, const std::string& name = "axialForceUserFunction") {
  try {
    Expression::compile(text, name);
  } catch (const std::invalid_argument& ex) {
    return ex.what();
  }
  return "";
}

}  // namespace

TEST(Expression, ValuesAndPrecedence) {
  EXPECT_DOUBLE_EQ(eval("2+3*4"), 14.0);
  EXPECT_DOUBLE_EQ(eval("(2+3)*4"), 20.0);
  EXPECT_DOUBLE_EQ(eval("-2^2"), -4.0);   // Python: -2**2 = -4
  EXPECT_DOUBLE_EQ(eval("-2**2"), -4.0);
  EXPECT_DOUBLE_EQ(eval("2^3^2"), 512.0);  // right associative
  EXPECT_DOUBLE_EQ(eval("2**-1"), 0.5);
  EXPECT_DOUBLE_EQ(eval("10/4/5"), 0.5);   // left associative
  EXPECT_DOUBLE_EQ(eval("7-2-1"), 4.0);
  EXPECT_DOUBLE_EQ(eval("1.5e3 + .5 + 2E-1"), 1500.7);
  EXPECT_DOUBLE_EQ(eval("--3"), 3.0);
  EXPECT_DOUBLE_EQ(eval("+3"), 3.0);
  EXPECT_DOUBLE_EQ(eval("t"), 0.37);
  EXPECT_DOUBLE_EQ(eval("physicsAxialStiffness*axialStrain"), 1e5 * 0.013);
  EXPECT_DOUBLE_EQ(eval("min(3, 2) + max(3, 2) + abs(-4) + sign(-2) + sign(0)"), 2 + 3 + 4 - 1 + 0);
  EXPECT_DOUBLE_EQ(eval("pow(2, 10)"), 1024.0);
  EXPECT_NEAR(eval("atan2(1, -1)"), 3 * M_PI / 4, 1e-15);
  EXPECT_NEAR(eval("sin(pi/6) + cos(0) + tan(0) + exp(0) + log(1) + sqrt(16)"), 0.5 + 1 + 0 + 1 + 0 + 4, 1e-15);
  EXPECT_NEAR(eval("asin(1) + acos(1) + atan(1)"), M_PI / 2 + M_PI / 4, 1e-15);
  EXPECT_NEAR(eval("sinh(0.5) + cosh(0.5) - exp(0.5) + tanh(0)"), 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(eval("1 < 2"), 1.0);
  EXPECT_DOUBLE_EQ(eval("1 > 2"), 0.0);
  EXPECT_DOUBLE_EQ(eval("2 <= 2") + eval("3 >= 4") + eval("2 == 2") + eval("2 != 2"), 2.0);
  EXPECT_DOUBLE_EQ(eval("t < 1 ? 10 : 20"), 10.0);
  EXPECT_DOUBLE_EQ(eval("t > 1 ? 10 : 20"), 20.0);
  EXPECT_DOUBLE_EQ(eval("t > 1 ? 10 : t > 0.3 ? 30 : 40"), 30.0);  // nested, right associative
  EXPECT_DOUBLE_EQ(eval("1 + (t < 1 ? 2 : 3) * 2"), 5.0);
}

TEST(Expression, UsedVariables) {
  const Expression e = Expression::compile("physicsAxialDamping*axialStrain_t + curvature");
  EXPECT_TRUE(e.uses(UfVar::axialStrain_t));
  EXPECT_TRUE(e.uses(UfVar::curvature));
  EXPECT_TRUE(e.uses(UfVar::physicsAxialDamping));
  EXPECT_FALSE(e.uses(UfVar::axialStrain));
  EXPECT_FALSE(e.uses(UfVar::curvature_t));
}

// The user functions of Exudyn TestModels/ANCFcable2DuserFunction.py (reference A5).
TEST(Expression, A5LawsValuesAndDerivatives) {
  const Expression M = Expression::compile(
      "physicsBendingStiffness*0.1*atan(10*(curvature-curvatureRef)) + physicsBendingDamping*curvature_t",
      "bendingMomentUserFunction");
  const Expression N = Expression::compile(
      "max(0.02, 2 - t**0.5)*physicsAxialStiffness*(axialStrain-axialStrainRef) + physicsAxialDamping*axialStrain_t",
      "axialForceUserFunction");
  const UserFunctionArgs a = sampleArgs();
  const double EI = 2000, dK = 200, EA = 1e5, dE = 5e3, k = 0.47 - 0.1, e = 0.013 - 0.002;
  const double fact = std::max(0.02, 2 - std::sqrt(0.37));
  const sinew::UserFunctionValue m = M.evaluate(a), n = N.evaluate(a);
  EXPECT_NEAR(m.value, EI * 0.1 * std::atan(10 * k) + dK * 1.3, 1e-12 * std::fabs(m.value));
  EXPECT_NEAR(m.dCurvature, EI / (1 + 100 * k * k), 1e-12 * EI);
  EXPECT_DOUBLE_EQ(m.dCurvature_t, dK);
  EXPECT_EQ(m.dAxialStrain, 0.0);
  EXPECT_NEAR(n.value, fact * EA * e + dE * -0.21, 1e-12 * std::fabs(n.value));
  EXPECT_NEAR(n.dAxialStrain, fact * EA, 1e-10);
  EXPECT_DOUBLE_EQ(n.dAxialStrain_t, dE);
  // Measured: max rel. error vs central differences 9.9e-11 (M), 4.5e-13 (N).
  EXPECT_LT(derivativeError(M, a), 1e-7);
  EXPECT_LT(derivativeError(N, a), 1e-7);
  // Late time: the max() switches to its other branch (t = 9 -> 2 - 3 < 0.02).
  UserFunctionArgs late = a;
  late[UfVar::t] = 9.0;
  EXPECT_NEAR(N.evaluate(late).dAxialStrain, 0.02 * EA, 1e-9);
}

TEST(Expression, EveryFunctionDerivativeMatchesFiniteDifferences) {
  const char* exprs[] = {
      "sin(axialStrain*3 + curvature)",
      "cos(axialStrain_t*curvature)",
      "tan(0.3 + axialStrain)",
      "asin(0.2 + axialStrain) + acos(0.3 - curvature/10)",
      "atan(curvature*axialStrain_t)",
      "atan2(curvature, 1 + axialStrain)",
      "sinh(curvature) * cosh(axialStrain) + tanh(curvature_t)",
      "exp(axialStrain*curvature_t) + log(1 + curvature)",
      "sqrt(1 + axialStrain^2 + curvature**2)",
      "abs(axialStrain - curvature) + abs(curvature_t)",
      "min(axialStrain, curvature) + max(curvature_t, axialStrain_t)",
      "pow(1 + curvature, 1.5 + axialStrain) + (2 + axialStrain_t)^curvature",
      "sign(curvature)*curvature^3 - axialStrain/curvature_t",
      "curvature_t > 1 ? axialStrain^2 : curvature^2",
      "-axialStrain^2 * -curvature",
  };
  const UserFunctionArgs a = sampleArgs();
  for (const char* s : exprs) {
    const Expression e = Expression::compile(s);
    // Measured: 9e-13 .. 6.6e-10 (cos), see EXPR_VERBOSE=1.
    EXPECT_LT(derivativeError(e, a), 1e-7) << s;
  }
}

TEST(Expression, SyntaxErrorsReportColumnAndCaret) {
  std::string m = errorOf("2*axialStrain)");
  EXPECT_EQ(m.rfind("axialForceUserFunction: unexpected ')' at column 14", 0), 0u) << m;
  EXPECT_NE(m.find("\n  2*axialStrain)\n               ^"), std::string::npos) << m;

  m = errorOf("1 +", "bendingMomentUserFunction");
  EXPECT_EQ(m.rfind("bendingMomentUserFunction: unexpected end of expression at column 4", 0), 0u) << m;

  m = errorOf("(1 + 2");
  EXPECT_NE(m.find("expected ')' but found end of expression at column 7"), std::string::npos) << m;

  m = errorOf("1 $ 2");
  EXPECT_NE(m.find("unexpected character '$' at column 3"), std::string::npos) << m;

  m = errorOf("min(1 2)");
  EXPECT_NE(m.find("expected ')' but found number '2' at column 7"), std::string::npos) << m;

  m = errorOf("sin(1, 2)");
  EXPECT_NE(m.find("function 'sin' takes 1 argument(s), got 2 at column 1"), std::string::npos) << m;

  m = errorOf("1 ? 2");
  EXPECT_NE(m.find("expected ':' but found end of expression at column 6"), std::string::npos) << m;

  m = errorOf("3 * * 4");
  EXPECT_NE(m.find("unexpected '*' at column 5"), std::string::npos) << m;

  m = errorOf("1e+");
  EXPECT_NE(m.find("malformed exponent in number at column 2"), std::string::npos) << m;
}

TEST(Expression, UnknownNamesListValidOnes) {
  std::string m = errorOf("EA*axialStrain");
  EXPECT_EQ(m.rfind("axialForceUserFunction: unknown name 'EA' at column 1; valid names: t, axialPositionNormalized", 0),
            0u)
      << m;
  EXPECT_NE(m.find("physicsAxialStiffness"), std::string::npos);
  EXPECT_NE(m.find("curvature_t"), std::string::npos);
  m = errorOf("axialStrain + foo(2)");
  EXPECT_NE(m.find("unknown function 'foo' at column 15"), std::string::npos) << m;
  EXPECT_NE(m.find("atan2"), std::string::npos) << m;
}

// Functions of time (loads, prescribed motions): f' and f'' of timeJet (second-order jets) vs
// central differences of value(), for every function and operator that a time function may use.
TEST(Expression, TimeJetMatchesFiniteDifferences) {
  const char* cases[] = {
      "0.3*sin(2*pi*t) + cos(3*t)^2", "tan(0.5*t) - asin(0.3*t) + acos(0.2*t) + atan(t)", "atan2(sin(t), 1 + t*t)",
      "sinh(t) * cosh(0.5*t) / (2 + tanh(t))", "exp(-t) * log(1 + t) + sqrt(1 + t*t)", "t^3 - 2*t**2 + (1 + t)^t",
      "pow(2 + t, 1.5) * abs(t - 1) + min(t, 0.1) * max(t*t, 0.2)", "ramp(t - 0.1)^2 + 3*step(t - 2)",
      "smoothstep(t, 0.1, 0.9, 1, 3)", "t < 0.2 ? 2*t^2 : 0.1*sin(t)",
      "(1.5/15)*(t^2/2 + (15/(2*pi))^2*(cos(2*pi*t/15) - 1))"};
  for (const char* text : cases) {
    const Expression e = Expression::compile(text, "f");
    for (double t : {0.37, 0.6}) {
      UserFunctionArgs a;
      const double h = 1e-4;
      auto f = [&](double x) {
        a[UfVar::t] = x;
        return e.value(a);
      };
      const Expression::TimeJet j = e.timeJet(t);
      EXPECT_NEAR(j.f, f(t), 1e-14 * (1 + std::fabs(j.f))) << text;
      const double d1 = (f(t + h) - f(t - h)) / (2 * h), d2 = (f(t + h) - 2 * f(t) + f(t - h)) / (h * h);
      EXPECT_NEAR(j.df, d1, 1e-6 * (1 + std::fabs(d1))) << text << " at t = " << t;
      EXPECT_NEAR(j.ddf, d2, 1e-4 * (1 + std::fabs(d2))) << text << " at t = " << t;
    }
  }
  // Exudyn's SmoothStep: value0 before x0, value1 after x1, half cosine between
  const Expression s = Expression::compile("smoothstep(t, 1, 2, 5, 7)");
  EXPECT_EQ(s.timeJet(0.5).f, 5.0);
  EXPECT_EQ(s.timeJet(2.5).f, 7.0);
  EXPECT_NEAR(s.timeJet(1.5).f, 6.0, 1e-15);
  EXPECT_NEAR(s.timeJet(1.5).df, 2.0 * 0.5 * M_PI * std::sin(0.5 * M_PI), 1e-14);
  EXPECT_EQ(Expression::compile("step(t)").timeJet(0.0).f, 1.0);
  EXPECT_EQ(Expression::compile("step(t)").timeJet(-1e-300).f, 0.0);
}
