#include "schema/operation_table.h"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <variant>

#include "model/calculator.h"
#include "model/stack_evaluator.h"

namespace gridifs {
namespace {

const ChoiceNames kAxes{{"x", "y", "z"}, {"x", "y", "z"}};
const ChoiceNames kFieldInterpolations{{"linear", "cubic"}, {"linear", "cubic"}};
const ChoiceNames kProfiles{{"linear", "sine", "pingpong"}, {"linear", "sine", "ping-pong"}};

const char* const kProfileHelp =
    "linear: k·t · sine: k·sin(ω·t) · ping-pong: k·tri(ω·t) (Gröller & Wegenkittl 1994, figure 13)";
const char* const kOmegaHelp = "Frequency ω of the sine and ping-pong profiles along the axis";

template <class Op>
bool periodicProfile(const void* params) {
  return std::get<Op>(*static_cast<const OpParams*>(params)).profile != Profile::Linear;
}

std::string format(const char* pattern, auto... values) {
  char text[160];
  std::snprintf(text, sizeof text, pattern, values...);
  return text;
}

/// Axis, profile, k (a slider over ±kRange) and omega (greyed out for the linear profile).
template <class Op>
std::vector<ParamSpec> profileParams(double kRange, const char* kHelp) {
  return {param<&Op::axis>({.key = "axis", .label = "Axis", .tooltip = "The axis t runs along", .choices = &kAxes}),
          param<&Op::profile>({.key = "profile", .label = "Profile", .tooltip = kProfileHelp, .choices = &kProfiles}),
          param<&Op::k>({.key = "k", .label = "k", .tooltip = kHelp, .sliderMin = -kRange, .sliderMax = kRange}),
          param<&Op::omega>({.key = "omega",
                             .label = "omega",
                             .tooltip = kOmegaHelp,
                             .sliderMin = 0.0,
                             .sliderMax = 4.0 * M_PI,
                             .enabled = periodicProfile<Op>})};
}

template <class Op>
std::string profileSummary(const OpParams& params) {
  const Op& p = std::get<Op>(params);
  return format("%s %s k=%.2f", axisName(p.axis), profileName(p.profile), p.k);
}

/// The table's row for operation `Op`; every alternative of OpParams has one.
template <class Op>
OperationSpec row() = delete;

template <>
OperationSpec row<TranslateOp>() {
  return {.type = "translate",
          .title = "Translate",
          .heading = "Translate",
          .defaults = TranslateOp{},
          .params = {param<&TranslateOp::offset>(
              {.key = "offset", .label = "Offset", .tooltip = "Moves every node by this vector"})},
          .summary = [](const OpParams& o) {
            const Vec3& v = std::get<TranslateOp>(o).offset;
            return format("%.2f %.2f %.2f", v.x, v.y, v.z);
          }};
}

template <>
OperationSpec row<RotateOp>() {
  return {.type = "rotate",
          .title = "Rotate",
          .heading = "Rotate (R = Rz·Ry·Rx, degrees)",
          .defaults = RotateOp{},
          .params = {param<&RotateOp::angles>({.key = "angles",
                                               .label = "Angles",
                                               .tooltip = "Euler angles in degrees, x applied first",
                                               .sliderMin = -360.0,
                                               .sliderMax = 360.0,
                                               .speed = 0.5,
                                               .format = "%.1f°"})},
          .summary = [](const OpParams& o) {
            const Vec3& v = std::get<RotateOp>(o).angles;
            return format("%.0f° %.0f° %.0f°", v.x, v.y, v.z);
          }};
}

template <>
OperationSpec row<ScaleOp>() {
  return {.type = "scale",
          .title = "Scale",
          .heading = "Scale",
          .defaults = ScaleOp{},
          .params = {param<&ScaleOp::factors>({.key = "factors",
                                               .label = "Factors",
                                               .tooltip = "Scale factors along x, y and z",
                                               .sliderMin = -10.0,
                                               .sliderMax = 10.0})},
          .summary = [](const OpParams& o) {
            const Vec3& v = std::get<ScaleOp>(o).factors;
            return format("%.2f %.2f %.2f", v.x, v.y, v.z);
          }};
}

// Gröller & Wegenkittl 1994, §2.2 and §2.3: taper and twist share the axis and profile.
template <>
OperationSpec row<TaperOp>() {
  return {.type = "taper",
          .title = "Taper",
          .heading = "Taper (Gröller & Wegenkittl 1994, §2.2)",
          .defaults = TaperOp{},
          .params = profileParams<TaperOp>(3.0, "Taper strength: the cross-section scales by f(t) = 1 + k·profile(t)"),
          .summary = profileSummary<TaperOp>};
}

template <>
OperationSpec row<TwistOp>() {
  return {.type = "twist",
          .title = "Twist",
          .heading = "Twist (Gröller & Wegenkittl 1994, §2.3)",
          .defaults = TwistOp{},
          .params = profileParams<TwistOp>(2.0 * M_PI, "Twist rate in radians per unit along the axis"),
          .summary = profileSummary<TwistOp>};
}

template <>
OperationSpec row<BendOp>() {
  return {.type = "bend",
          .title = "Bend",
          .heading = "Bend (Gröller & Wegenkittl 1994, §2.4, Barr)",
          .defaults = BendOp{},
          .params = {param<&BendOp::axis>(
                         {.key = "axis", .label = "Axis", .tooltip = "The axis that is bent", .choices = &kAxes}),
                     param<&BendOp::toward>({.key = "toward",
                                             .label = "Toward",
                                             .tooltip = "The axis the bend curves toward",
                                             .choices = &kAxes}),
                     param<&BendOp::k>({.key = "k",
                                        .label = "k",
                                        .tooltip = "Curvature: the bend radius is 1/k; 0 leaves the grid straight",
                                        .sliderMin = -3.0,
                                        .sliderMax = 3.0})},
          .rules =
              [](const OpParams& o) {
                const BendOp& b = std::get<BendOp>(o);
                if (b.axis == b.toward)
                  throw ModelError("toward", "the bend must go toward an axis other than its own");
              },
          .summary =
              [](const OpParams& o) {
                const BendOp& b = std::get<BendOp>(o);
                return format("%s→%s k=%.2f", axisName(b.axis), axisName(b.toward), b.k);
              }};
}

template <>
OperationSpec row<MagnetOp>() {
  return {.type = "magnet",
          .title = "Magnet",
          .heading = "Magnet (Gröller & Wegenkittl 1994, §2.5)",
          .defaults = MagnetOp{},
          .params = {param<&MagnetOp::point>({.key = "point",
                                              .label = "Point",
                                              .tooltip = "The magnet's position; drag the magenta dot in a grid view",
                                              .placeable = true}),
                     param<&MagnetOp::dmax>({.key = "dmax",
                                             .label = "Distance",
                                             .tooltip = "Range d_max: nodes farther from the magnet do not move",
                                             .min = 0.0,
                                             .sliderMin = 0.0,
                                             .sliderMax = 3.0}),
                     param<&MagnetOp::strength>({.key = "strength",
                                                 .label = "Strength",
                                                 .tooltip = "Pull toward the magnet (negative pushes away)",
                                                 .sliderMin = -1.0,
                                                 .sliderMax = 1.0}),
                     param<&MagnetOp::falloff>({.key = "falloff",
                                                .label = "Decrease",
                                                .tooltip = "Falloff exponent p of ((d_max - d)/d_max)^p",
                                                .min = 0.0,
                                                .max = 1000.0,
                                                .sliderMin = 0.0,
                                                .sliderMax = 8.0})},
          .absolute = true,
          // A new magnet sits at the selection and does nothing until its strength is raised.
          .placeAt =
              [](OpParams& o, const Vec3& anchor) {
                MagnetOp& m = std::get<MagnetOp>(o);
                m.point = anchor;
                m.strength = 0.0;
              },
          .summary =
              [](const OpParams& o) {
                const MagnetOp& m = std::get<MagnetOp>(o);
                return format("s=%.2f d=%.2f", m.strength, m.dmax);
              }};
}

template <>
OperationSpec row<MorphOp>() {
  return {
      .type = "morph",
      .title = "Morph",
      .heading = "Point morph (Gröller & Wegenkittl 1994, §2.6)",
      .defaults = MorphOp{},
      .params = {param<&MorphOp::pairs>(
                     {.key = "pairs", .label = "Vector", .tooltip = "Start point P_i and end point Q_i (absolute)"}),
                 param<&MorphOp::strength>(
                     {.key = "strength",
                      .label = "Strength",
                      .tooltip =
                          "1: every start point lands exactly on its end point (Gröller & Wegenkittl 1994, §2.6)",
                      .sliderMin = -2.0,
                      .sliderMax = 2.0})},
      .absolute = true,
      .rules =
          [](const OpParams& o) {
            std::vector<Vec3> alpha;
            std::vector<double> radius;
            solveMorph(std::get<MorphOp>(o), alpha, radius);
          },
      .placeAt =
          [](OpParams& o, const Vec3& anchor) {
            std::get<MorphOp>(o).pairs = {MorphPair{anchor, anchor + Vec3(0.0, 0.0, 0.25)}};
          },
      .summary =
          [](const OpParams& o) {
            const std::size_t n = std::get<MorphOp>(o).pairs.size();
            return format("%zu pair%s", n, n == 1 ? "" : "s");
          }};
}

template <>
OperationSpec row<CalculatorOp>() {
  const char* const kExpressionHelp =
      "Variables x y z (node), cx cy cz (center), i j k (indices), v1 v2 v3, t (time); sin cos tan asin acos atan sinh "
      "cosh "
      "tanh log exp sqrt abs min max pow rand(), pi, e";
  return {
      .type = "calculator",
      .title = "Calculator",
      .heading = "Universal calculator (Gröller & Wegenkittl 1994, §4.3)",
      .defaults = CalculatorOp{},
      .params = {param<&CalculatorOp::x>({.key = "x", .label = "x =", .tooltip = kExpressionHelp}),
                 param<&CalculatorOp::y>({.key = "y", .label = "y =", .tooltip = kExpressionHelp}),
                 param<&CalculatorOp::z>({.key = "z", .label = "z =", .tooltip = kExpressionHelp}),
                 param<&CalculatorOp::vars>(
                     {.key = "vars",
                      .label = "v",
                      .tooltip = "A user variable of the expressions (Gröller & Wegenkittl 1994, §4.3); its range is "
                                 "editable on both sides",
                      .speed = 0.01,
                      .format = "%.2f"}),
                 param<&CalculatorOp::seed>(
                     {.key = "seed", .label = "rand() seed", .tooltip = "The seed of the expressions' rand()"})},
      .rules =
          [](const OpParams& o) {
            if (auto diagnostic = checkCalculator(std::get<CalculatorOp>(o)))
              throw ModelError(std::string(1, "xyz"[diagnostic->expression]), diagnostic->message);
          },
      .summary = [](const OpParams& o) { return std::get<CalculatorOp>(o).x.substr(0, 24); }};
}

template <>
OperationSpec row<NodesOp>() {
  return {.type = "nodes",
          .title = "Nodes",
          .heading = "Direct node moves",
          .defaults = NodesOp{},
          .params = {param<&NodesOp::moves>(
              {.key = "moves", .label = "Moves", .tooltip = "Drag selected nodes in a grid view to add moves"})},
          .addable = false,
          .summary = [](const OpParams& o) {
            const std::size_t n = std::get<NodesOp>(o).moves.size();
            return format("%zu move%s", n, n == 1 ? "" : "s");
          }};
}

// Colonna, "Animation of fractal objects", §2 (fractal fields) and §3.2 (wind, periodic loops).
template <>
OperationSpec row<FieldOp>() {
  return {
      .type = "field",
      .title = "Field",
      .heading = "Fractal field (Colonna 1994, §2 and §3.2)",
      .defaults = FieldOp{},
      .params =
          {param<&FieldOp::amplitude>({.key = "amplitude",
                                       .label = "Amplitude",
                                       .tooltip = "The largest displacement along x, y and z",
                                       .sliderMin = 0.0,
                                       .sliderMax = 1.0}),
           param<&FieldOp::scale>({.key = "scale",
                                   .label = "Scale",
                                   .tooltip = "Cell size of the coarsest mesh: the size of the largest features",
                                   .min = 1e-6,
                                   .max = 1e6,
                                   .sliderMin = 0.01,
                                   .sliderMax = 4.0}),
           param<&FieldOp::ratio>({.key = "ratio",
                                   .label = "Ratio",
                                   .tooltip = "Each finer mesh's cell size is the previous one's times this (0 to 1)",
                                   .min = 0.0,
                                   .max = 1.0,
                                   .sliderMin = 0.05,
                                   .sliderMax = 0.95}),
           param<&FieldOp::octaves>({.key = "octaves",
                                     .label = "Octaves",
                                     .tooltip = "Number of superposed meshes (1 to 16)",
                                     .min = 1,
                                     .max = FractalFieldParams::kMaxOctaves,
                                     .sliderMin = 1,
                                     .sliderMax = FractalFieldParams::kMaxOctaves,
                                     .format = "%.0f"}),
           param<&FieldOp::gain>(
               {.key = "gain",
                .label = "Gain",
                .tooltip = "Weight of mesh k is proportional to gain^k: small gains give smooth fields",
                .min = 1e-6,
                .max = 1e3,
                .sliderMin = 0.05,
                .sliderMax = 1.5}),
           param<&FieldOp::interpolation>({.key = "interpolation",
                                           .label = "Interpolation",
                                           .tooltip = "linear: quadrilinear; cubic: Colonna's pseudo n-cubic (smooth)",
                                           .choices = &kFieldInterpolations}),
           param<&FieldOp::seed>({.key = "seed",
                                  .label = "Seed",
                                  .tooltip = "Random values of the meshes; axes use seed, seed+1, seed+2"}),
           param<&FieldOp::wind>({.key = "wind",
                                  .label = "Wind",
                                  .tooltip = "Drift of the field per unit of time (x, y, z)",
                                  .sliderMin = -2.0,
                                  .sliderMax = 2.0}),
           param<&FieldOp::period>({.key = "period",
                                    .label = "Period",
                                    .tooltip =
                                        "Lx, Ly, Lz, Lt: the field repeats with these periods; 0 = none. A period "
                                        "in t makes a seamless loop",
                                    .min = 0.0,
                                    .sliderMin = 0.0,
                                    .sliderMax = 10.0})},
      .absolute = true,
      .rules =
          [](const OpParams& o) {
            const FieldOp& f = std::get<FieldOp>(o);
            if (!(f.ratio > 0.0 && f.ratio < 1.0))
              throw ModelError("ratio", "the ratio must lie strictly between 0 and 1, so each mesh is finer");
          },
      .summary =
          [](const OpParams& o) {
            const FieldOp& f = std::get<FieldOp>(o);
            return format("%s %d oct s=%.2f", toString(f.interpolation), f.octaves, f.scale);
          }};
}

/// The rows of the table, in the order it lists them.
using TableOrder = std::tuple<TranslateOp, RotateOp, ScaleOp, TaperOp, TwistOp, BendOp, MagnetOp, MorphOp, CalculatorOp,
                              NodesOp, FieldOp>;

/// Whether row i of `Order` describes alternative i of `Variant`, for every i of both.
template <class Order, class Variant>
constexpr bool sameOrder() {
  if constexpr (std::tuple_size_v<Order> != std::variant_size_v<Variant>) {
    return false;
  } else {
    return []<std::size_t... I>(std::index_sequence<I...>) {
      return (std::is_same_v<std::tuple_element_t<I, Order>, std::variant_alternative_t<I, Variant>> && ...);
    }
    (std::make_index_sequence<std::tuple_size_v<Order>>{});
  }
}
// operationSpec() finds an operation's row by its index in OpParams, so an operation added to the
// variant and not to the table (or in another place) must not compile.
static_assert(sameOrder<TableOrder, OpParams>(),
              "the operation table's rows (TableOrder) must list OpParams' alternatives in variant order");

template <class... Op>
std::vector<OperationSpec> rows(std::tuple<Op...>) {
  return {row<Op>()...};
}

[[noreturn]] void fail(const std::string& path, const std::string& message) { throw ModelError(path, message); }

std::string item(const std::string& path, std::size_t index) { return path + "[" + std::to_string(index) + "]"; }

void checkNumber(double v, const std::string& path, double lo, double hi) {
  if (!std::isfinite(v)) fail(path, "expected a finite number");
  if (v < lo || v > hi) {
    std::ostringstream s;
    s << "expected a number between " << lo << " and " << hi << ", found " << v;
    fail(path, s.str());
  }
}

void checkCoordinates(const Vec3& v, const std::string& path) {
  for (int c = 0; c < 3; ++c)
    checkNumber(v[c], item(path, std::size_t(c)), -limits::kMaxCoordinate, limits::kMaxCoordinate);
}

void checkParam(const ParamSpec& s, const OpParams& params) {
  const std::string key = s.key;
  switch (s.type) {
    case ParamType::Number:
      checkNumber(s.number(params), key, s.min, s.max);
      break;
    case ParamType::Integer: {
      const int v = s.value<int>(params);
      if (v < s.min || v > s.max)
        fail(key, "expected an integer between " + std::to_string(std::int64_t(s.min)) + " and " +
                      std::to_string(std::int64_t(s.max)));
      break;
    }
    case ParamType::Vector:
      for (int c = 0; c < s.components; ++c) checkNumber(s.number(params, c), item(key, std::size_t(c)), s.min, s.max);
      break;
    case ParamType::Expression:
      if (s.value<std::string>(params).size() > s.maxLength)
        fail(key, "the string is longer than " + std::to_string(s.maxLength) + " characters");
      break;
    case ParamType::CalculatorVars: {
      const auto& vars = s.value<std::array<CalculatorVar, 3>>(params);
      for (int v = 0; v < 3; ++v) {
        const std::string vp = key + ".v" + std::to_string(v + 1);
        checkNumber(vars[std::size_t(v)].min, vp + ".min", -limits::kMaxCoordinate, limits::kMaxCoordinate);
        checkNumber(vars[std::size_t(v)].max, vp + ".max", -limits::kMaxCoordinate, limits::kMaxCoordinate);
        checkNumber(vars[std::size_t(v)].value, vp + ".value", -limits::kMaxCoordinate, limits::kMaxCoordinate);
        if (vars[std::size_t(v)].min > vars[std::size_t(v)].max)
          fail(vp + ".min", "the slider minimum is larger than its maximum");
      }
      break;
    }
    case ParamType::MorphPairs: {
      const auto& pairs = s.value<std::vector<MorphPair>>(params);
      if (pairs.size() > std::size_t(limits::kMaxMorphPairs))
        fail(key, "more than " + std::to_string(limits::kMaxMorphPairs) + " morph pairs");
      for (std::size_t i = 0; i < pairs.size(); ++i) {
        checkCoordinates(pairs[i].from, item(item(key, i), 0));
        checkCoordinates(pairs[i].to, item(item(key, i), 1));
      }
      break;
    }
    case ParamType::NodeMoves: {
      const auto& moves = s.value<std::vector<NodeMove>>(params);
      if (moves.size() > std::size_t(limits::kMaxNodeMoves)) fail(key, "too many node moves");
      for (std::size_t m = 0; m < moves.size(); ++m) {
        for (int d = 0; d < 3; ++d)
          if (moves[m].index[d] < 0 || moves[m].index[d] > limits::kMaxResolution - 1)
            fail(item(item(key, m), std::size_t(d)),
                 "expected an integer between 0 and " + std::to_string(limits::kMaxResolution - 1));
        checkCoordinates(moves[m].displacement, item(item(key, m), 3));
      }
      break;
    }
    case ParamType::Seed:
    case ParamType::Choice:
      break;  // every value of the C++ type is valid
    case ParamType::Count:
    case ParamType::Boolean:
    case ParamType::OptionalNumber:
      break;  // no operation has these
  }
}

}  // namespace

const std::vector<OperationSpec>& operationTable() {
  static const std::vector<OperationSpec> table = [] {
    std::vector<OperationSpec> t = rows(TableOrder{});
    for (std::size_t i = 0; i < t.size(); ++i)
      if (t[i].defaults.index() != i) throw std::logic_error("an operation table row holds another operation");
    return t;
  }();
  return table;
}

const OperationSpec& operationSpec(const OpParams& params) { return operationTable()[params.index()]; }

const OperationSpec* findOperation(std::string_view type) {
  for (const OperationSpec& spec : operationTable())
    if (type == spec.type) return &spec;
  return nullptr;
}

const char* opTypeName(const OpParams& params) { return operationSpec(params).type; }

std::string operationTypeList() {
  std::vector<std::string> names;
  for (const OperationSpec& spec : operationTable()) names.push_back(spec.type);
  return listWithOr(names);
}

std::string operationSummary(const OpParams& params) {
  const OperationSpec& spec = operationSpec(params);
  if (spec.summary) return spec.summary(params);
  std::string text;
  int shown = 0;
  for (const ParamSpec& s : spec.params) {
    if (shown == 2) break;
    if (s.type != ParamType::Number && s.type != ParamType::Integer) continue;
    text += (shown++ ? " " : "") + std::string(s.key) + "=" + format("%.2f", s.number(params));
  }
  return text;
}

void validateOperationParams(const OpParams& params) {
  const OperationSpec& spec = operationSpec(params);
  for (const ParamSpec& s : spec.params) checkParam(s, params);
  if (spec.rules) spec.rules(params);
}

}  // namespace gridifs
