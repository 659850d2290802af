#pragma once
// The operations of a function's stack (Gröller & Wegenkittl 1994, §2).
// Each operation is a plain value: parameters + center + selection + muted flag.
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "field/fractal_field.h"
#include "model/selection.h"

namespace gridifs {

/// Center of transformation: the centroid of the current nodes, of the selected
/// nodes, or an explicit point (Gröller & Wegenkittl 1994, §4.3).
struct Center {
  enum class Kind { Grid, Selection, Point };
  Kind kind = Kind::Grid;
  Vec3 point{0.0};
  bool operator==(const Center&) const = default;
};

struct TranslateOp {
  Vec3 offset{0.0};
  bool operator==(const TranslateOp&) const = default;
};
/// Euler angles in degrees, R = Rz·Ry·Rx (x applied first).
struct RotateOp {
  Vec3 angles{0.0};
  bool operator==(const RotateOp&) const = default;
};
struct ScaleOp {
  Vec3 factors{1.0};
  bool operator==(const ScaleOp&) const = default;
};
/// Gröller & Wegenkittl 1994, §2.2 taper: (a, b) *= f(t).
struct TaperOp {
  Axis axis = Axis::Z;
  Profile profile = Profile::Linear;
  double k = 0.0, omega = 1.0;
  bool operator==(const TaperOp&) const = default;
};
/// Gröller & Wegenkittl 1994, §2.3 twist: rotate (a, b) by φ(t); k in radians per unit.
struct TwistOp {
  Axis axis = Axis::Z;
  Profile profile = Profile::Linear;
  double k = 0.0, omega = 1.0;
  bool operator==(const TwistOp&) const = default;
};
/// Gröller & Wegenkittl 1994, §2.4 bend (Barr), whole grid: bend `axis` toward `toward` with curvature k.
struct BendOp {
  Axis axis = Axis::Z;
  Axis toward = Axis::Y;
  double k = 0.0;
  bool operator==(const BendOp&) const = default;
};
/// Gröller & Wegenkittl 1994, §2.5 magnet, absolute coordinates.
struct MagnetOp {
  Vec3 point{0.0};
  double dmax = 0.5, strength = 0.5, falloff = 2.0;
  bool operator==(const MagnetOp&) const = default;
};
/// Gröller & Wegenkittl 1994, §2.6 point morphing with radial basis functions, absolute coordinates.
struct MorphPair {
  Vec3 from{0.0}, to{0.0};
  bool operator==(const MorphPair&) const = default;
};
struct MorphOp {
  std::vector<MorphPair> pairs;
  double strength = 1.0;
  bool operator==(const MorphOp&) const = default;
};
/// A calculator user variable: a value shown as a slider over [min, max].
struct CalculatorVar {
  double value = 0.0, min = -1.0, max = 1.0;
  bool operator==(const CalculatorVar&) const = default;
};
/// Gröller & Wegenkittl 1994, §4.3 "universal calculator": x̂, ŷ, ẑ as expressions.
struct CalculatorOp {
  std::string x = "x", y = "y", z = "z";
  std::array<CalculatorVar, 3> vars{};
  std::uint64_t seed = 1;
  bool operator==(const CalculatorOp&) const = default;
};
/// Direct manipulation: node (i, j, k) moves by a displacement.
struct NodeMove {
  Index3 index{0, 0, 0};
  Vec3 displacement{0.0};
  bool operator==(const NodeMove&) const = default;
};
struct NodesOp {
  std::vector<NodeMove> moves;
  bool operator==(const NodesOp&) const = default;
};
/// Colonna's fractal field as a displacement, absolute coordinates: q += amplitude ⊙ F(q + wind·t, t).
using FieldOp = FractalFieldParams;

using OpParams = std::variant<TranslateOp, RotateOp, ScaleOp, TaperOp, TwistOp, BendOp, MagnetOp, MorphOp, CalculatorOp,
                              NodesOp, FieldOp>;

struct Operation {
  OpParams params;
  Center center;
  Selection selection;
  bool muted = false;
  bool operator==(const Operation&) const = default;
};

}  // namespace gridifs
