// Recursive-descent compiler and dual-number evaluator for user force laws (see expression.hpp).
#include "math/expression.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace sinew {

namespace {

const char* const kVarNames[kNumUfVars] = {
    "t",
    "axialPositionNormalized",
    "axialStrain",
    "axialStrain_t",
    "axialStrainRef",
    "curvature",
    "curvature_t",
    "curvatureRef",
    "physicsAxialStiffness",
    "physicsAxialDamping",
    "physicsBendingStiffness",
    "physicsBendingDamping",
    "physicsMassPerLength",
    "physicsReferenceAxialStrain",
    "physicsReferenceCurvature",
};

struct FunctionInfo {
  const char* name;
  Expression::Op op;
  int arity;
};
const FunctionInfo kFunctions[] = {
    {"sin", Expression::Op::Sin, 1},     {"cos", Expression::Op::Cos, 1},
    {"tan", Expression::Op::Tan, 1},     {"asin", Expression::Op::Asin, 1},
    {"acos", Expression::Op::Acos, 1},   {"atan", Expression::Op::Atan, 1},
    {"atan2", Expression::Op::Atan2, 2}, {"sinh", Expression::Op::Sinh, 1},
    {"cosh", Expression::Op::Cosh, 1},   {"tanh", Expression::Op::Tanh, 1},
    {"exp", Expression::Op::Exp, 1},     {"log", Expression::Op::Log, 1},
    {"sqrt", Expression::Op::Sqrt, 1},   {"abs", Expression::Op::Abs, 1},
    {"min", Expression::Op::Min, 2},     {"max", Expression::Op::Max, 2},
    {"pow", Expression::Op::Pow, 2},     {"sign", Expression::Op::Sign, 1},
    {"step", Expression::Op::Step, 1},   {"ramp", Expression::Op::Ramp, 1},
    {"smoothstep", Expression::Op::SmoothStep, 5},
};

/// Derivative slot of a state argument, -1 for the others.
int derivativeSlot(int var) {
  switch (static_cast<UfVar>(var)) {
    case UfVar::axialStrain: return 0;
    case UfVar::axialStrain_t: return 1;
    case UfVar::curvature: return 2;
    case UfVar::curvature_t: return 3;
    default: return -1;
  }
}

// Forward-mode dual number with the four partial derivatives.
struct Dual {
  double v = 0.0;
  double d[4] = {0.0, 0.0, 0.0, 0.0};
};
inline Dual constant(double v) {
  Dual r;
  r.v = v;
  return r;
}
/// Chain rule for a unary function: value f, derivative fp.
inline Dual chain(const Dual& a, double f, double fp) {
  Dual r;
  r.v = f;
  for (int k = 0; k < 4; ++k) r.d[k] = fp * a.d[k];
  return r;
}

// Arithmetic on plain doubles and on duals behind one interface, so one interpreter serves both.
struct DoubleOps {
  using T = double;
  static T cst(double v) { return v; }
  static T var(const UserFunctionArgs& a, int i) { return a.v[i]; }
  static double val(T x) { return x; }
  static T add(T a, T b) { return a + b; }
  static T sub(T a, T b) { return a - b; }
  static T mul(T a, T b) { return a * b; }
  static T div(T a, T b) { return a / b; }
  static T neg(T a) { return -a; }
  static T pow(T a, T b) { return std::pow(a, b); }
  static T atan2(T y, T x) { return std::atan2(y, x); }
  static T unary(Expression::Op op, T a) {
    using O = Expression::Op;
    switch (op) {
      case O::Sin: return std::sin(a);
      case O::Cos: return std::cos(a);
      case O::Tan: return std::tan(a);
      case O::Asin: return std::asin(a);
      case O::Acos: return std::acos(a);
      case O::Atan: return std::atan(a);
      case O::Sinh: return std::sinh(a);
      case O::Cosh: return std::cosh(a);
      case O::Tanh: return std::tanh(a);
      case O::Exp: return std::exp(a);
      case O::Log: return std::log(a);
      case O::Sqrt: return std::sqrt(a);
      case O::Abs: return std::fabs(a);
      case O::Sign: return a > 0 ? 1.0 : (a < 0 ? -1.0 : 0.0);
      case O::Step: return a >= 0 ? 1.0 : 0.0;
      case O::Ramp: return a > 0 ? a : 0.0;
      default: return a;
    }
  }
};

struct DualOps {
  using T = Dual;
  static T cst(double v) { return constant(v); }
  static T var(const UserFunctionArgs& a, int i) {
    Dual r = constant(a.v[i]);
    const int s = derivativeSlot(i);
    if (s >= 0) r.d[s] = 1.0;
    return r;
  }
  static double val(const T& x) { return x.v; }
  static T add(const T& a, const T& b) {
    Dual r;
    r.v = a.v + b.v;
    for (int k = 0; k < 4; ++k) r.d[k] = a.d[k] + b.d[k];
    return r;
  }
  static T sub(const T& a, const T& b) {
    Dual r;
    r.v = a.v - b.v;
    for (int k = 0; k < 4; ++k) r.d[k] = a.d[k] - b.d[k];
    return r;
  }
  static T mul(const T& a, const T& b) {
    Dual r;
    r.v = a.v * b.v;
    for (int k = 0; k < 4; ++k) r.d[k] = a.d[k] * b.v + a.v * b.d[k];
    return r;
  }
  static T div(const T& a, const T& b) {
    Dual r;
    r.v = a.v / b.v;
    const double ib = 1.0 / b.v;
    for (int k = 0; k < 4; ++k) r.d[k] = (a.d[k] - r.v * b.d[k]) * ib;
    return r;
  }
  static T neg(const T& a) { return chain(a, -a.v, -1.0); }
  // d(a^b) = b a^(b-1) da + a^b ln(a) db; the second term only when b varies.
  static T pow(const T& a, const T& b) {
    Dual r;
    r.v = std::pow(a.v, b.v);
    const double da = (b.v == 0.0) ? 0.0 : b.v * std::pow(a.v, b.v - 1.0);
    const bool bVaries = b.d[0] != 0.0 || b.d[1] != 0.0 || b.d[2] != 0.0 || b.d[3] != 0.0;
    const double db = bVaries ? r.v * std::log(a.v) : 0.0;
    for (int k = 0; k < 4; ++k) r.d[k] = da * a.d[k] + (bVaries ? db * b.d[k] : 0.0);
    return r;
  }
  // d atan2(y, x) = (x dy - y dx) / (x^2 + y^2)
  static T atan2(const T& y, const T& x) {
    Dual r;
    r.v = std::atan2(y.v, x.v);
    const double inv = 1.0 / (x.v * x.v + y.v * y.v);
    for (int k = 0; k < 4; ++k) r.d[k] = (x.v * y.d[k] - y.v * x.d[k]) * inv;
    return r;
  }
  static T unary(Expression::Op op, const T& a) {
    using O = Expression::Op;
    const double x = a.v;
    switch (op) {
      case O::Sin: return chain(a, std::sin(x), std::cos(x));
      case O::Cos: return chain(a, std::cos(x), -std::sin(x));
      case O::Tan: {
        const double c = std::cos(x);
        return chain(a, std::tan(x), 1.0 / (c * c));
      }
      case O::Asin: return chain(a, std::asin(x), 1.0 / std::sqrt(1.0 - x * x));
      case O::Acos: return chain(a, std::acos(x), -1.0 / std::sqrt(1.0 - x * x));
      case O::Atan: return chain(a, std::atan(x), 1.0 / (1.0 + x * x));
      case O::Sinh: return chain(a, std::sinh(x), std::cosh(x));
      case O::Cosh: return chain(a, std::cosh(x), std::sinh(x));
      case O::Tanh: {
        const double th = std::tanh(x);
        return chain(a, th, 1.0 - th * th);
      }
      case O::Exp: {
        const double e = std::exp(x);
        return chain(a, e, e);
      }
      case O::Log: return chain(a, std::log(x), 1.0 / x);
      case O::Sqrt: {
        const double s = std::sqrt(x);
        return chain(a, s, 0.5 / s);
      }
      case O::Abs: return chain(a, std::fabs(x), x >= 0.0 ? 1.0 : -1.0);
      case O::Sign: return constant(x > 0 ? 1.0 : (x < 0 ? -1.0 : 0.0));
      case O::Step: return constant(x >= 0 ? 1.0 : 0.0);
      case O::Ramp: return chain(a, x > 0 ? x : 0.0, x > 0 ? 1.0 : 0.0);
      default: return a;
    }
  }
};

// Second-order jet in t: value, first and second derivative (time functions: loads, prescribed motions).
struct Jet {
  double v = 0.0, d1 = 0.0, d2 = 0.0;
};
/// f(a(t)): d/dt = f' a1, d2/dt2 = f'' a1^2 + f' a2.
inline Jet chain2(const Jet& a, double f, double fp, double fpp) { return {f, fp * a.d1, fpp * a.d1 * a.d1 + fp * a.d2}; }

struct JetOps {
  using T = Jet;
  static T cst(double v) { return {v, 0.0, 0.0}; }
  static T var(const UserFunctionArgs& a, int i) { return {a.v[i], i == static_cast<int>(UfVar::t) ? 1.0 : 0.0, 0.0}; }
  static double val(const T& x) { return x.v; }
  static T add(const T& a, const T& b) { return {a.v + b.v, a.d1 + b.d1, a.d2 + b.d2}; }
  static T sub(const T& a, const T& b) { return {a.v - b.v, a.d1 - b.d1, a.d2 - b.d2}; }
  static T mul(const T& a, const T& b) { return {a.v * b.v, a.d1 * b.v + a.v * b.d1, a.d2 * b.v + 2.0 * a.d1 * b.d1 + a.v * b.d2}; }
  // r = a / b: r' = (a' - r b') / b, r'' = (a'' - 2 r' b' - r b'') / b
  static T div(const T& a, const T& b) {
    const double r = a.v / b.v, r1 = (a.d1 - r * b.d1) / b.v;
    return {r, r1, (a.d2 - 2.0 * r1 * b.d1 - r * b.d2) / b.v};
  }
  static T neg(const T& a) { return {-a.v, -a.d1, -a.d2}; }
  // a^b: a constant exponent by the power rule, a varying one as exp(b log a)
  static T pow(const T& a, const T& b) {
    if (b.d1 == 0.0 && b.d2 == 0.0) {
      const double p = b.v;
      const double fp = p == 0.0 ? 0.0 : p * std::pow(a.v, p - 1.0);
      const double fpp = (p == 0.0 || p == 1.0) ? 0.0 : p * (p - 1.0) * std::pow(a.v, p - 2.0);
      return chain2(a, std::pow(a.v, p), fp, fpp);
    }
    const T l = chain2(a, std::log(a.v), 1.0 / a.v, -1.0 / (a.v * a.v));
    const T m = mul(b, l);
    const double e = std::exp(m.v);
    return chain2(m, e, e, e);
  }
  // atan2(y, x) = N / D with N = x y' - y x', D = x^2 + y^2 as its derivative
  static T atan2(const T& y, const T& x) {
    const double D = x.v * x.v + y.v * y.v, N = x.v * y.d1 - y.v * x.d1;
    const double N1 = x.v * y.d2 - y.v * x.d2, D1 = 2.0 * (x.v * x.d1 + y.v * y.d1);
    return {std::atan2(y.v, x.v), N / D, (N1 * D - N * D1) / (D * D)};
  }
  static T unary(Expression::Op op, const T& a) {
    using O = Expression::Op;
    const double x = a.v;
    switch (op) {
      case O::Sin: return chain2(a, std::sin(x), std::cos(x), -std::sin(x));
      case O::Cos: return chain2(a, std::cos(x), -std::sin(x), -std::cos(x));
      case O::Tan: {
        const double tn = std::tan(x), s2 = 1.0 + tn * tn;
        return chain2(a, tn, s2, 2.0 * tn * s2);
      }
      case O::Asin: {
        const double q = 1.0 - x * x;
        return chain2(a, std::asin(x), 1.0 / std::sqrt(q), x / (q * std::sqrt(q)));
      }
      case O::Acos: {
        const double q = 1.0 - x * x;
        return chain2(a, std::acos(x), -1.0 / std::sqrt(q), -x / (q * std::sqrt(q)));
      }
      case O::Atan: {
        const double q = 1.0 + x * x;
        return chain2(a, std::atan(x), 1.0 / q, -2.0 * x / (q * q));
      }
      case O::Sinh: return chain2(a, std::sinh(x), std::cosh(x), std::sinh(x));
      case O::Cosh: return chain2(a, std::cosh(x), std::sinh(x), std::cosh(x));
      case O::Tanh: {
        const double th = std::tanh(x), s = 1.0 - th * th;
        return chain2(a, th, s, -2.0 * th * s);
      }
      case O::Exp: {
        const double e = std::exp(x);
        return chain2(a, e, e, e);
      }
      case O::Log: return chain2(a, std::log(x), 1.0 / x, -1.0 / (x * x));
      case O::Sqrt: {
        const double s = std::sqrt(x);
        return chain2(a, s, 0.5 / s, -0.25 / (s * x));
      }
      case O::Abs: return chain2(a, std::fabs(x), x >= 0.0 ? 1.0 : -1.0, 0.0);
      case O::Sign: return cst(x > 0 ? 1.0 : (x < 0 ? -1.0 : 0.0));
      case O::Step: return cst(x >= 0 ? 1.0 : 0.0);
      case O::Ramp: return chain2(a, x > 0 ? x : 0.0, x > 0 ? 1.0 : 0.0, 0.0);
      default: return a;
    }
  }
};

template <class Ops>
typename Ops::T run(const std::vector<Expression::Instr>& code, const std::vector<double>& constants,
                    const UserFunctionArgs& args) {
  using T = typename Ops::T;
  using O = Expression::Op;
  std::array<T, Expression::kMaxStack> st;
  int sp = 0;  // number of entries on the stack
  const int n = static_cast<int>(code.size());
  for (int pc = 0; pc < n; ++pc) {
    const Expression::Instr& in = code[pc];
    switch (in.op) {
      case O::Const: st[sp++] = Ops::cst(constants[in.arg]); break;
      case O::Var: st[sp++] = Ops::var(args, in.arg); break;
      case O::Neg: st[sp - 1] = Ops::neg(st[sp - 1]); break;
      case O::Add: --sp; st[sp - 1] = Ops::add(st[sp - 1], st[sp]); break;
      case O::Sub: --sp; st[sp - 1] = Ops::sub(st[sp - 1], st[sp]); break;
      case O::Mul: --sp; st[sp - 1] = Ops::mul(st[sp - 1], st[sp]); break;
      case O::Div: --sp; st[sp - 1] = Ops::div(st[sp - 1], st[sp]); break;
      case O::Pow: --sp; st[sp - 1] = Ops::pow(st[sp - 1], st[sp]); break;
      case O::Atan2: --sp; st[sp - 1] = Ops::atan2(st[sp - 1], st[sp]); break;
      case O::Min: --sp; if (Ops::val(st[sp]) < Ops::val(st[sp - 1])) st[sp - 1] = st[sp]; break;
      case O::Max: --sp; if (Ops::val(st[sp]) > Ops::val(st[sp - 1])) st[sp - 1] = st[sp]; break;
      case O::Lt: --sp; st[sp - 1] = Ops::cst(Ops::val(st[sp - 1]) < Ops::val(st[sp]) ? 1.0 : 0.0); break;
      case O::Gt: --sp; st[sp - 1] = Ops::cst(Ops::val(st[sp - 1]) > Ops::val(st[sp]) ? 1.0 : 0.0); break;
      case O::Le: --sp; st[sp - 1] = Ops::cst(Ops::val(st[sp - 1]) <= Ops::val(st[sp]) ? 1.0 : 0.0); break;
      case O::Ge: --sp; st[sp - 1] = Ops::cst(Ops::val(st[sp - 1]) >= Ops::val(st[sp]) ? 1.0 : 0.0); break;
      case O::Eq: --sp; st[sp - 1] = Ops::cst(Ops::val(st[sp - 1]) == Ops::val(st[sp]) ? 1.0 : 0.0); break;
      case O::Ne: --sp; st[sp - 1] = Ops::cst(Ops::val(st[sp - 1]) != Ops::val(st[sp]) ? 1.0 : 0.0); break;
      case O::SmoothStep: {
        // Exudyn's SmoothStep(x, x0, x1, value0, value1): value0 + (value1 - value0) (1 - cos(pi s)) / 2,
        // s = (x - x0) / (x1 - x0), between x0 and x1; value0 before, value1 after
        sp -= 4;
        const T x = st[sp - 1], x0 = st[sp], x1 = st[sp + 1], v0 = st[sp + 2], v1 = st[sp + 3];
        if (Ops::val(x) <= Ops::val(x0)) st[sp - 1] = v0;
        else if (Ops::val(x) >= Ops::val(x1)) st[sp - 1] = v1;
        else {
          const T s = Ops::div(Ops::sub(x, x0), Ops::sub(x1, x0));
          const T c = Ops::unary(O::Cos, Ops::mul(Ops::cst(3.141592653589793238462643383279502884), s));
          st[sp - 1] = Ops::add(v0, Ops::mul(Ops::sub(v1, v0), Ops::mul(Ops::cst(0.5), Ops::sub(Ops::cst(1.0), c))));
        }
        break;
      }
      case O::JumpIfZero:
        --sp;
        if (Ops::val(st[sp]) == 0.0) pc = in.arg - 1;
        break;
      case O::Jump: pc = in.arg - 1; break;
      default: st[sp - 1] = Ops::unary(in.op, st[sp - 1]); break;
    }
  }
  return st[0];
}

}  // namespace

const char* ufVarName(UfVar v) { return kVarNames[static_cast<int>(v)]; }

std::string Expression::validNames() {
  std::string s;
  for (int i = 0; i < kNumUfVars; ++i) {
    if (i) s += ", ";
    s += kVarNames[i];
  }
  s += ", pi; functions: ";
  bool first = true;
  for (const FunctionInfo& f : kFunctions) {
    if (!first) s += ", ";
    first = false;
    s += f.name;
  }
  return s;
}

// ------------------------------------------------------------------------------------------------
class ExpressionParser {
 public:
  ExpressionParser(const std::string& text, const std::string& name, Expression& e)
      : s_(text), name_(name), e_(e) {}

  void parse() {
    next();
    parseExpr();
    if (tok_.kind != Kind::End) fail("unexpected " + describe(tok_), tok_.pos);
    if (maxDepth_ > Expression::kMaxStack) fail("expression nests too deeply", 0);
  }

 private:
  enum class Kind { End, Number, Name, Op };
  struct Token {
    Kind kind = Kind::End;
    std::string text;
    double number = 0.0;
    std::size_t pos = 0;  // 0-based
  };

  [[noreturn]] void fail(const std::string& what, std::size_t pos, const std::string& detail = "") const {
    std::string msg = name_ + ": " + what + " at column " + std::to_string(pos + 1) + detail + "\n  " + s_ +
                      "\n  " + std::string(pos, ' ') + "^";
    throw std::invalid_argument(msg);
  }
  static std::string describe(const Token& t) {
    switch (t.kind) {
      case Kind::End: return "end of expression";
      case Kind::Number: return "number '" + t.text + "'";
      case Kind::Name: return "name '" + t.text + "'";
      default: return "'" + t.text + "'";
    }
  }

  void next() {
    std::size_t i = pos_;
    while (i < s_.size() && std::isspace(static_cast<unsigned char>(s_[i]))) ++i;
    tok_ = Token{};
    tok_.pos = i;
    if (i >= s_.size()) {
      tok_.kind = Kind::End;
      pos_ = i;
      return;
    }
    const char c = s_[i];
    if (std::isdigit(static_cast<unsigned char>(c)) ||
        (c == '.' && i + 1 < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i + 1])))) {
      std::size_t j = i;
      while (j < s_.size() && std::isdigit(static_cast<unsigned char>(s_[j]))) ++j;
      if (j < s_.size() && s_[j] == '.') {
        ++j;
        while (j < s_.size() && std::isdigit(static_cast<unsigned char>(s_[j]))) ++j;
      }
      if (j < s_.size() && (s_[j] == 'e' || s_[j] == 'E')) {
        std::size_t k = j + 1;
        if (k < s_.size() && (s_[k] == '+' || s_[k] == '-')) ++k;
        if (k < s_.size() && std::isdigit(static_cast<unsigned char>(s_[k]))) {
          while (k < s_.size() && std::isdigit(static_cast<unsigned char>(s_[k]))) ++k;
          j = k;
        } else {
          fail("malformed exponent in number", j);
        }
      }
      tok_.kind = Kind::Number;
      tok_.text = s_.substr(i, j - i);
      tok_.number = std::strtod(tok_.text.c_str(), nullptr);
      pos_ = j;
      return;
    }
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      std::size_t j = i;
      while (j < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[j])) || s_[j] == '_')) ++j;
      tok_.kind = Kind::Name;
      tok_.text = s_.substr(i, j - i);
      pos_ = j;
      return;
    }
    static const char* const two[] = {"**", "<=", ">=", "==", "!="};
    for (const char* op : two) {
      if (s_.compare(i, 2, op) == 0) {
        tok_.kind = Kind::Op;
        tok_.text.assign(op, 2);
        pos_ = i + 2;
        return;
      }
    }
    if (std::string("+-*/^(),<>?:").find(c) != std::string::npos) {
      tok_.kind = Kind::Op;
      tok_.text = std::string(1, c);
      pos_ = i + 1;
      return;
    }
    fail(std::string("unexpected character '") + c + "'", i);
  }

  bool isOp(const char* op) const { return tok_.kind == Kind::Op && tok_.text == op; }
  void expect(const char* op) {
    if (!isOp(op)) fail(std::string("expected '") + op + "' but found " + describe(tok_), tok_.pos);
    next();
  }

  // Emission with stack-depth bookkeeping.
  int emit(Expression::Op op, int arg, int depthChange) {
    e_.code_.push_back({op, arg});
    depth_ += depthChange;
    if (depth_ > maxDepth_) maxDepth_ = depth_;
    return static_cast<int>(e_.code_.size()) - 1;
  }
  void emitConst(double v) {
    e_.constants_.push_back(v);
    emit(Expression::Op::Const, static_cast<int>(e_.constants_.size()) - 1, +1);
  }

  void parseExpr() {
    parseCompare();
    if (isOp("?")) {
      next();
      const int jz = emit(Expression::Op::JumpIfZero, 0, -1);
      parseExpr();
      expect(":");
      const int jmp = emit(Expression::Op::Jump, 0, 0);
      --depth_;  // the else branch starts from the depth before the then branch
      e_.code_[jz].arg = static_cast<int>(e_.code_.size());
      parseExpr();
      e_.code_[jmp].arg = static_cast<int>(e_.code_.size());
    }
  }
  void parseCompare() {
    parseSum();
    for (;;) {
      Expression::Op op;
      if (isOp("<")) op = Expression::Op::Lt;
      else if (isOp(">")) op = Expression::Op::Gt;
      else if (isOp("<=")) op = Expression::Op::Le;
      else if (isOp(">=")) op = Expression::Op::Ge;
      else if (isOp("==")) op = Expression::Op::Eq;
      else if (isOp("!=")) op = Expression::Op::Ne;
      else return;
      next();
      parseSum();
      emit(op, 0, -1);
    }
  }
  void parseSum() {
    parseProduct();
    for (;;) {
      if (isOp("+")) {
        next();
        parseProduct();
        emit(Expression::Op::Add, 0, -1);
      } else if (isOp("-")) {
        next();
        parseProduct();
        emit(Expression::Op::Sub, 0, -1);
      } else {
        return;
      }
    }
  }
  void parseProduct() {
    parseUnary();
    for (;;) {
      if (isOp("*")) {
        next();
        parseUnary();
        emit(Expression::Op::Mul, 0, -1);
      } else if (isOp("/")) {
        next();
        parseUnary();
        emit(Expression::Op::Div, 0, -1);
      } else {
        return;
      }
    }
  }
  void parseUnary() {
    if (isOp("-")) {
      next();
      parseUnary();
      emit(Expression::Op::Neg, 0, 0);
    } else if (isOp("+")) {
      next();
      parseUnary();
    } else {
      parsePower();
    }
  }
  void parsePower() {
    parsePrimary();
    if (isOp("^") || isOp("**")) {
      next();
      parseUnary();
      emit(Expression::Op::Pow, 0, -1);
    }
  }
  void parsePrimary() {
    if (tok_.kind == Kind::Number) {
      emitConst(tok_.number);
      next();
      return;
    }
    if (isOp("(")) {
      next();
      parseExpr();
      expect(")");
      return;
    }
    if (tok_.kind == Kind::Name) {
      const Token nameTok = tok_;
      next();
      if (isOp("(")) {
        const FunctionInfo* fn = nullptr;
        for (const FunctionInfo& f : kFunctions)
          if (nameTok.text == f.name) fn = &f;
        if (!fn)
          fail("unknown function '" + nameTok.text + "'", nameTok.pos, "; valid names: " + Expression::validNames());
        next();
        int nargs = 0;
        if (!isOp(")")) {
          parseExpr();
          ++nargs;
          while (isOp(",")) {
            next();
            parseExpr();
            ++nargs;
          }
        }
        expect(")");
        if (nargs != fn->arity)
          fail(std::string("function '") + fn->name + "' takes " + std::to_string(fn->arity) +
                   " argument(s), got " + std::to_string(nargs),
               nameTok.pos);
        emit(fn->op, 0, 1 - fn->arity);
        return;
      }
      for (int i = 0; i < kNumUfVars; ++i) {
        if (nameTok.text == kVarNames[i]) {
          emit(Expression::Op::Var, i, +1);
          e_.usedMask_ |= (1u << i);
          return;
        }
      }
      if (nameTok.text == "pi") {
        emitConst(3.141592653589793238462643383279502884);
        return;
      }
      fail("unknown name '" + nameTok.text + "'", nameTok.pos, "; valid names: " + Expression::validNames());
    }
    fail("unexpected " + describe(tok_), tok_.pos);
  }

  const std::string& s_;
  const std::string& name_;
  Expression& e_;
  Token tok_;
  std::size_t pos_ = 0;
  int depth_ = 0, maxDepth_ = 0;
};

Expression Expression::compile(const std::string& text, const std::string& name) {
  Expression e;
  e.text_ = text;
  e.name_ = name;
  ExpressionParser p(e.text_, e.name_, e);
  p.parse();
  return e;
}

UserFunctionValue Expression::evaluate(const UserFunctionArgs& args) const {
  const Dual r = run<DualOps>(code_, constants_, args);
  return {r.v, r.d[0], r.d[1], r.d[2], r.d[3]};
}

double Expression::value(const UserFunctionArgs& args) const { return run<DoubleOps>(code_, constants_, args); }

Expression::TimeJet Expression::timeJet(double t) const {
  UserFunctionArgs args;
  args[UfVar::t] = t;
  const Jet r = run<JetOps>(code_, constants_, args);
  return {r.v, r.d1, r.d2};
}

}  // namespace sinew
