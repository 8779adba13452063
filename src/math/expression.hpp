// A small compiler for scalar user force laws (Exudyn ObjectANCFCable2D axialForceUserFunction /
// bendingMomentUserFunction written as expressions).
//
// Grammar (lowest to highest precedence):
//   expr    := compare ('?' expr ':' expr)?
//   compare := sum (('<' | '>' | '<=' | '>=' | '==' | '!=') sum)*
//   sum     := product (('+' | '-') product)*
//   product := unary (('*' | '/') unary)*
//   unary   := ('-' | '+') unary | power
//   power   := primary (('^' | '**') unary)?          (right associative, -a^2 = -(a^2))
//   primary := number | name | function '(' expr (',' expr)* ')' | '(' expr ')'
// The text is compiled once into stack bytecode. Evaluation runs on forward-mode dual numbers
// carrying the partial derivatives with respect to axialStrain, axialStrain_t, curvature and
// curvature_t, so the element tangent is exact; min, max and abs differentiate their active branch,
// comparisons, sign and step have zero derivative. step(x) = 1 for x >= 0 (else 0), ramp(x) =
// max(x, 0), smoothstep(x, x0, x1, value0, value1) = Exudyn's SmoothStep (value0 up to x0, value1
// from x1, a half cosine between). timeJet() evaluates f, f' and f'' w.r.t. t (second-order jets).
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace sinew {

/// The arguments a cable force law may use (Exudyn's names); index into UserFunctionArgs::v.
enum class UfVar : int {
  t = 0,
  axialPositionNormalized,
  axialStrain,
  axialStrain_t,
  axialStrainRef,
  curvature,
  curvature_t,
  curvatureRef,
  physicsAxialStiffness,
  physicsAxialDamping,
  physicsBendingStiffness,
  physicsBendingDamping,
  physicsMassPerLength,
  physicsReferenceAxialStrain,
  physicsReferenceCurvature,
  count
};
constexpr int kNumUfVars = static_cast<int>(UfVar::count);

/// Name of an argument as written in expressions.
const char* ufVarName(UfVar v);

struct UserFunctionArgs {
  std::array<double, kNumUfVars> v{};
  double& operator[](UfVar k) { return v[static_cast<int>(k)]; }
  double operator[](UfVar k) const { return v[static_cast<int>(k)]; }
};

/// Value of a force law and its partial derivatives w.r.t. the four state arguments.
struct UserFunctionValue {
  double value = 0.0;
  double dAxialStrain = 0.0, dAxialStrain_t = 0.0, dCurvature = 0.0, dCurvature_t = 0.0;
};

class Expression {
 public:
  /// Compile `text`. `name` prefixes error messages (e.g. "axialForceUserFunction").
  /// Throws std::invalid_argument on a syntax error or an unknown name; the message gives the
  /// 1-based column and repeats the expression with a caret under the offending character.
  static Expression compile(const std::string& text, const std::string& name = "expression");

  /// Value and exact partial derivatives. Allocation-free and thread-safe.
  UserFunctionValue evaluate(const UserFunctionArgs& args) const;
  /// Value only (same bytecode, plain doubles).
  double value(const UserFunctionArgs& args) const;
  /// A function of time alone (time-dependent loads and prescribed motions): f(t) and its exact first
  /// and second derivatives by second-order forward differentiation (every other argument 0).
  struct TimeJet {
    double f = 0.0, df = 0.0, ddf = 0.0;
  };
  TimeJet timeJet(double t) const;

  /// True when the expression reads argument `v`.
  bool uses(UfVar v) const { return (usedMask_ >> static_cast<int>(v)) & 1u; }
  const std::string& text() const { return text_; }
  const std::string& name() const { return name_; }

  /// Valid argument and function names, comma separated (for messages).
  static std::string validNames();

  enum class Op : std::uint8_t {
    Const, Var, Neg, Add, Sub, Mul, Div, Pow, Lt, Gt, Le, Ge, Eq, Ne,
    Sin, Cos, Tan, Asin, Acos, Atan, Atan2, Sinh, Cosh, Tanh, Exp, Log, Sqrt, Abs, Min, Max, Sign,
    Step, Ramp, SmoothStep, JumpIfZero, Jump
  };
  struct Instr {
    Op op;
    int arg;  ///< constant index, variable index or jump target
  };
  static constexpr int kMaxStack = 64;

 private:
  std::string text_, name_;
  std::vector<Instr> code_;
  std::vector<double> constants_;
  std::uint32_t usedMask_ = 0;
  friend class ExpressionParser;
};

}  // namespace sinew
