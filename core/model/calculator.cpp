#include "model/calculator.h"

#include "base/hash.h"

#include <muParser.h>

#include <array>
#include <cctype>
#include <cmath>
#include <mutex>

namespace gridifs {
namespace {

double powFunction(double a, double b) { return std::pow(a, b); }
double atan2Function(double y, double x) { return std::atan2(y, x); }

/// State read by the rand() callback: the node being evaluated and how many times
/// rand() was called for it, so the n-th call of a node always gives the same value.
struct RandomContext {
  std::uint64_t seed = 0;
  int expression = 0;
  int i = 0, j = 0, k = 0;
  int calls = 0;
};

double randomCallback(void* data) {
  auto* ctx = static_cast<RandomContext*>(data);
  return calculatorRandom(ctx->seed, ctx->expression, ctx->i, ctx->j, ctx->k, ctx->calls++);
}

std::string describeParserError(const mu::Parser::exception_type& e) {
  std::string message = e.GetMsg();
  // muparser's messages end with a period or not; keep one sentence without it.
  while (!message.empty() && (message.back() == '.' || message.back() == ' ')) message.pop_back();
  if (!message.empty()) message[0] = char(std::tolower(static_cast<unsigned char>(message[0])));
  return message;
}

}  // namespace

double calculatorRandom(std::uint64_t seed, int expression, int i, int j, int k, int call) {
  std::uint64_t h = splitmix64(seed);
  h = splitmix64(h ^ std::uint64_t(expression));
  h = splitmix64(h ^ std::uint64_t(std::uint32_t(i)));
  h = splitmix64(h ^ std::uint64_t(std::uint32_t(j)));
  h = splitmix64(h ^ std::uint64_t(std::uint32_t(k)));
  h = splitmix64(h ^ std::uint64_t(std::uint32_t(call)));
  return double(h >> 11) * 0x1.0p-53;
}

struct CompiledCalculator::Impl {
  static constexpr int kVariables = 13;
  static constexpr const char* kVariableNames[kVariables] = {"x", "y", "z",  "cx", "cy", "cz", "i",
                                                             "j", "k", "v1", "v2", "v3", "t"};
  std::array<mu::Parser, 3> parsers;
  std::array<RandomContext, 3> random;
  // The parsers read the variables through these addresses; muparser compiles the
  // expressions to bytecode once, so each node costs one bytecode run per expression
  // (its bulk mode measured no faster here and cannot pass node indices to rand()).
  std::array<double, kVariables> variables{};
  // Expressions that are just their own coordinate ("z" for ẑ, as in figure 14) need no
  // bytecode run: -1 when the parser must run, else the coordinate index to copy.
  std::array<int, 3> passThrough{-1, -1, -1};
  CalculatorOp op;
};

namespace {
int passThroughCoordinate(const std::string& expression) {
  const auto first = expression.find_first_not_of(" \t");
  const auto last = expression.find_last_not_of(" \t");
  if (first == std::string::npos || last != first) return -1;
  const char c = expression[first];
  return c == 'x' ? 0 : c == 'y' ? 1 : c == 'z' ? 2 : -1;
}
}  // namespace

CompiledCalculator::CompiledCalculator(const CalculatorOp& op) : impl_(std::make_unique<Impl>()) {
  impl_->op = op;
  const std::string* expressions[3] = {&op.x, &op.y, &op.z};
  static const char* kPaths[3] = {"x", "y", "z"};
  for (int e = 0; e < 3; ++e) {
    mu::Parser& p = impl_->parsers[e];
    impl_->random[e].seed = op.seed;
    impl_->random[e].expression = e;
    try {
      p.DefineConst("pi", M_PI);
      p.DefineConst("e", M_E);
      p.DefineFun("pow", powFunction);
      p.DefineFun("atan2", atan2Function);
      // Not optimizable: constant folding would turn rand() into one number.
      p.DefineFunUserData("rand", randomCallback, &impl_->random[e], false);
      for (int v = 0; v < Impl::kVariables; ++v) p.DefineVar(Impl::kVariableNames[v], &impl_->variables[v]);
      if (expressions[e]->find_first_not_of(" \t") == std::string::npos)
        throw ModelError(kPaths[e], "the expression is empty");
      p.SetExpr(*expressions[e]);
      impl_->passThrough[e] = passThroughCoordinate(*expressions[e]);
      p.Eval();  // forces the parse so errors surface now, at edit time
    } catch (const mu::Parser::exception_type& error) {
      throw ModelError(kPaths[e], describeParserError(error));
    }
  }
}

CompiledCalculator::~CompiledCalculator() = default;

void CompiledCalculator::apply(std::vector<Vec3>& nodes, const Index3& resolution,
                               const std::vector<unsigned char>& mask, const Vec3& center, double time) {
  Impl& s = *impl_;
  static const char* kPaths[3] = {"x", "y", "z"};
  auto& var = s.variables;
  var[3] = center.x, var[4] = center.y, var[5] = center.z;
  for (int v = 0; v < 3; ++v) var[9 + v] = s.op.vars[v].value;
  var[12] = time;
  // Every expression reads the node's old position, so results go to a copy.
  std::vector<Vec3> out = nodes;
  std::size_t n = 0;
  for (int k = 0; k < resolution[2]; ++k)
    for (int j = 0; j < resolution[1]; ++j)
      for (int i = 0; i < resolution[0]; ++i, ++n) {
        if (!mask[n]) continue;
        var[0] = nodes[n].x, var[1] = nodes[n].y, var[2] = nodes[n].z;
        var[6] = i, var[7] = j, var[8] = k;
        for (int e = 0; e < 3; ++e) {
          if (s.passThrough[e] >= 0) {
            out[n][e] = var[s.passThrough[e]];
            continue;
          }
          RandomContext& r = s.random[e];
          r.i = i, r.j = j, r.k = k, r.calls = 0;
          double value;
          try {
            value = s.parsers[e].Eval();
          } catch (const mu::Parser::exception_type& error) {
            throw ModelError(kPaths[e], describeParserError(error));
          }
          if (!std::isfinite(value))
            throw ModelError(kPaths[e], "the expression gives a non-finite value at node (" + std::to_string(i) + ", " +
                                            std::to_string(j) + ", " + std::to_string(k) + ")");
          out[n][e] = value;
        }
      }
  nodes.swap(out);
}

bool calculatorUsesTime(const CalculatorOp& op) {
  // A name token "t" (muparser names are letters, digits and underscores, not starting with a
  // digit); "tan", "t2" or "pt" are other names.
  auto isNameChar = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (const std::string* e : {&op.x, &op.y, &op.z}) {
    for (std::size_t i = 0; i < e->size(); ++i) {
      if ((*e)[i] != 't') continue;
      const bool startsName = i == 0 || !isNameChar((*e)[i - 1]);
      const bool endsName = i + 1 == e->size() || !isNameChar((*e)[i + 1]);
      if (startsName && endsName) return true;
    }
  }
  return false;
}

std::optional<CalculatorDiagnostic> checkCalculator(const CalculatorOp& op) {
  try {
    CompiledCalculator compiled(op);
  } catch (const ModelError& error) {
    CalculatorDiagnostic d;
    d.expression = error.path() == "x" ? 0 : error.path() == "y" ? 1 : 2;
    d.message = error.message();
    const auto at = d.message.rfind("at position ");
    if (at != std::string::npos) d.position = std::atoi(d.message.c_str() + at + 12);
    return d;
  }
  return std::nullopt;
}

}  // namespace gridifs
