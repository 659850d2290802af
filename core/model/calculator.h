#pragma once
// The "universal calculator" (Gröller & Wegenkittl 1994, §4.3): three muparser expressions map each
// selected node to a new absolute position.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "model/operation.h"

namespace gridifs {

/// A syntax or name error in one of the three expressions.
struct CalculatorDiagnostic {
  int expression = 0;   // 0: x, 1: y, 2: z
  int position = -1;    // character offset in that expression, -1 when unknown
  std::string message;  // one sentence, e.g. `unknown name "q" at position 4`
};

/// Parsed once per edit, applied to every node in one bulk pass (never per-node parsing).
/// Not thread-safe: one instance per evaluating thread.
class CompiledCalculator {
 public:
  /// Throws ModelError (path "x", "y" or "z") on a syntax error or an unknown name.
  explicit CompiledCalculator(const CalculatorOp& op);
  ~CompiledCalculator();
  CompiledCalculator(const CompiledCalculator&) = delete;
  CompiledCalculator& operator=(const CompiledCalculator&) = delete;

  /// Replaces the selected nodes with (x̂, ŷ, ẑ). `center` feeds cx, cy, cz; `time` feeds t.
  void apply(std::vector<Vec3>& nodes, const Index3& resolution, const std::vector<unsigned char>& mask,
             const Vec3& center, double time = 0.0);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Checks the three expressions without evaluating them; empty when they compile.
std::optional<CalculatorDiagnostic> checkCalculator(const CalculatorOp& op);

/// Whether any of the three expressions reads the time variable t.
bool calculatorUsesTime(const CalculatorOp& op);

/// The deterministic rand() of the calculator: a hash of the op seed, the expression
/// (0..2), the node indices and the call's ordinal within that node, mapped to [0, 1).
double calculatorRandom(std::uint64_t seed, int expression, int i, int j, int k, int call);

}  // namespace gridifs
