// The `field` operation (Colonna, "Animation of fractal objects", §2 and §3.2) in the stack:
// displacement by the field at the project time, loops that close, continuity in time,
// determinism, the file round trip and the errors of bad parameters.
#include <gtest/gtest.h>

#include <cmath>

#include "io/project_io.h"
#include "model/evaluation_cache.h"
#include "model/stack_evaluator.h"
#include "model_error_text.h"
#include "op_test_support.h"
#include "schema/project_time.h"

using namespace gridifs;
using namespace gridifs::test_support;

namespace {

FieldOp cloudField() {
  FieldOp f;
  f.amplitude = {0.2, 0.1, 0.3};
  f.scale = 0.6;
  f.ratio = 0.5;
  f.octaves = 5;
  f.gain = 0.6;
  f.seed = 9;
  f.wind = {0.25, 0.0, -0.1};
  f.period = {0.0, 0.0, 0.0, 3.0};
  return f;
}

Grid atTime(const Function& f, double t) { return evaluateFunction(f, std::size_t(-1), true, t); }

double largestDifference(const Grid& a, const Grid& b) {
  double d = 0.0;
  for (std::size_t n = 0; n < a.nodes().size(); ++n)
    for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(a.nodes()[n][c] - b.nodes()[n][c]));
  return d;
}

}  // namespace

TEST(FieldOperation, DisplacesEachSelectedNodeByTheFieldAtTheProjectTime) {
  for (FieldInterpolation interpolation : {FieldInterpolation::Linear, FieldInterpolation::Cubic}) {
    FieldOp p = cloudField();
    p.interpolation = interpolation;
    const FractalField field(p);
    const double t = 1.3;
    const Function f = functionWith({5, 4, 6}, {op(p, {}, {{{1, 3}, {0, 3}, {0, 5}, SelectionOp::Or}})});
    const Grid g = atTime(f, t);
    const Grid u(f.resolution);
    for (int k = 0; k < 6; ++k)
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 5; ++i) {
          const Vec3 q = u.node(i, j, k);
          // Written out from the formula: s = q + wind·t, then F of seeds S, S+1, S+2.
          const Vec3 s = q + p.wind * t;
          const Vec3 expected = (i >= 1 && i <= 3) ? q + p.amplitude * Vec3{field.value(0, {s.x, s.y, s.z, t}),
                                                                            field.value(1, {s.x, s.y, s.z, t}),
                                                                            field.value(2, {s.x, s.y, s.z, t})}
                                                   : q;
          // The op evaluates a whole grid at once, summing in single precision (field_step.h).
          for (int c = 0; c < 3; ++c) ASSERT_NEAR(g.node(i, j, k)[c], expected[c], 1e-7) << i << j << k;
        }
  }
}

TEST(FieldOperation, StaysWithinItsAmplitudeTimesTheBound) {
  for (FieldInterpolation interpolation : {FieldInterpolation::Linear, FieldInterpolation::Cubic}) {
    FieldOp p = cloudField();
    p.interpolation = interpolation;
    const Function f = functionWith({9, 9, 9}, {op(p)});
    const Grid u(f.resolution);
    const double bound = FractalField(p).bound();
    for (double t : {0.0, 0.7, 2.2}) {
      const Grid g = atTime(f, t);
      for (std::size_t n = 0; n < u.nodes().size(); ++n)
        for (int c = 0; c < 3; ++c)
          ASSERT_LE(std::abs(g.nodes()[n][c] - u.nodes()[n][c]), p.amplitude[c] * bound + 1e-12);
    }
  }
}

TEST(FieldOperation, LoopsCloseExactlyWithAPeriodInTime) {
  // Colonna §3.2: wrapping t modulo Lt, and the wind's shift modulo the space periods, closes the loop.
  for (FieldInterpolation interpolation : {FieldInterpolation::Linear, FieldInterpolation::Cubic}) {
    FieldOp p = cloudField();
    p.interpolation = interpolation;
    p.wind = {0.5, 0.0, 0.0};
    p.period = {2.0, 0.0, 0.0, 4.0};  // the wind crosses exactly one x period per loop
    const Function f = functionWith({7, 6, 5}, {op(p)});
    for (double t : {0.0, 0.35, 1.9, 3.99}) EXPECT_LE(largestDifference(atTime(f, t), atTime(f, t + 4.0)), 1e-9) << t;
    EXPECT_GT(largestDifference(atTime(f, 0.0), atTime(f, 2.0)), 1e-3);
  }
}

TEST(FieldOperation, IsContinuousInTime) {
  FieldOp p = cloudField();
  const Function f = functionWith({6, 6, 6}, {op(p)});
  // A step of 1e-6 in t moves no node by more than a small multiple of the step times the
  // amplitude over the finest cell (the slope of the field).
  const double finest = p.scale * std::pow(p.ratio, p.octaves - 1);
  for (double t : {0.0, 0.5, 1.5, 2.999999}) {
    const double d = largestDifference(atTime(f, t), atTime(f, t + 1e-6));
    EXPECT_LE(d, 10.0 * 1e-6 * 0.3 / finest) << t;
  }
}

TEST(FieldOperation, IsTheSameOnEveryThreadCount) {
  FractalField field(cloudField());
  Grid u({24, 20, 16});
  std::vector<unsigned char> mask(u.nodes().size(), 1);
  std::vector<Vec3> one = u.nodes(), four = u.nodes(), all = u.nodes();
  field.displaceNodes(one, mask, 0.8, 1);
  field.displaceNodes(four, mask, 0.8, 4);
  field.displaceNodes(all, mask, 0.8, 0);
  EXPECT_EQ(one, four);
  EXPECT_EQ(one, all);
  EXPECT_NE(one, u.nodes());
}

TEST(FieldOperation, TheCalculatorReadsTheTime) {
  CalculatorOp c;
  c.x = "x + t";
  c.y = "y*cos(t)";
  const Function f = functionWith({3, 3, 3}, {op(c)});
  EXPECT_TRUE(dependsOnTime(f));
  expectNodes(f, [](const Vec3& q, int, int, int) { return q; });  // t = 0
  const Grid g = atTime(f, 0.5);
  const Grid u(f.resolution);
  EXPECT_DOUBLE_EQ(g.node(1, 2, 0).x, u.node(1, 2, 0).x + 0.5);
  EXPECT_DOUBLE_EQ(g.node(1, 2, 0).y, u.node(1, 2, 0).y * std::cos(0.5));
  CalculatorOp still;
  still.x = "x + tan(y) + v1";
  EXPECT_FALSE(dependsOnTime(functionWith({3, 3, 3}, {op(still)})));
  EXPECT_TRUE(dependsOnTime(functionWith({3, 3, 3}, {op(cloudField())})));
}

TEST(FieldOperation, TheEvaluationCacheFollowsTheTimeOnlyWhereItMatters) {
  Project p;
  p.functions.push_back(functionWith({4, 4, 4}, {op(cloudField())}));
  p.functions.push_back(functionWith({4, 4, 4}, {op(TwistOp{Axis::Z, Profile::Linear, 1.0, 1.0})}));
  EvaluationCache cache;
  const auto field0 = cache.function(p, 0), twist0 = cache.function(p, 1);
  p.time = 1.0;
  const auto field1 = cache.function(p, 0), twist1 = cache.function(p, 1);
  EXPECT_NE(*field0, *field1);
  EXPECT_EQ(twist0, twist1);  // the same grid object: not evaluated again
  EXPECT_EQ(*field1, atTime(p.functions[0], 1.0));
}

TEST(FieldOperation, RoundTripsThroughTheFile) {
  Project p;
  FieldOp f = cloudField();
  f.interpolation = FieldInterpolation::Linear;
  f.seed = 123456789012345ull;
  p.functions.push_back(functionWith({4, 4, 4}, {op(f)}));
  const std::string text = serializeProject(p);
  EXPECT_NE(text.find("\"type\": \"field\""), std::string::npos) << text;
  const Project back = parseProject(text);
  EXPECT_EQ(back, p);
  EXPECT_EQ(serializeProject(back), text);
  // The design's example, key for key.
  const Project example = parseProject(R"({"format":"gridifs","version":1,"functions":[{"name":"a","ops":[
    {"type": "field", "amplitude": [0.1, 0.1, 0.1], "scale": 0.5, "ratio": 0.5, "octaves": 6,
     "gain": 0.5, "interpolation": "cubic", "seed": 3, "wind": [0.2, 0, 0], "period": [0, 0, 0, 4]}]}]})");
  const FieldOp& e = std::get<FieldOp>(example.functions[0].ops[0].params);
  EXPECT_EQ(e.octaves, 6);
  EXPECT_EQ(e.seed, 3u);
  EXPECT_EQ(e.period[3], 4.0);
  EXPECT_EQ(e.wind.x, 0.2);
}

TEST(FieldOperation, KeyframedFieldParametersFollowTheTime) {
  Project p;
  p.functions.push_back(functionWith({4, 4, 4}, {op(cloudField())}));
  p.tracks["functions[0].ops[0].amplitude[1]"].keys = {{0.0, 0.0, KeyInterpolation::Linear},
                                                       {2.0, 0.4, KeyInterpolation::Linear}};
  const Project at = projectAtTime(p, 1.0);
  EXPECT_DOUBLE_EQ(std::get<FieldOp>(at.functions[0].ops[0].params).amplitude.y, 0.2);
  EXPECT_EQ(at.time, 1.0);
}

TEST(FieldOperation, BadParametersAreErrorsWithTheirPath) {
  auto load = [](const std::string& field) {
    return modelErrorText([&] {
      parseProject(R"({"format":"gridifs","version":1,"functions":[{"name":"a","ops":[{"type":"field",)" + field +
                   "}]}]}");
    });
  };
  EXPECT_NE(load(R"("octaves": 0)").find("functions[0].ops[0].octaves"), std::string::npos) << load(R"("octaves": 0)");
  EXPECT_NE(load(R"("octaves": 17)").find("functions[0].ops[0].octaves"), std::string::npos);
  EXPECT_NE(load(R"("ratio": 1)").find("functions[0].ops[0].ratio"), std::string::npos) << load(R"("ratio": 1)");
  EXPECT_NE(load(R"("ratio": 0)").find("functions[0].ops[0].ratio"), std::string::npos);
  EXPECT_NE(load(R"("ratio": -0.5)").find("functions[0].ops[0].ratio"), std::string::npos);
  EXPECT_NE(load(R"("period": [0, 0, -1, 0])").find("functions[0].ops[0].period[2]"), std::string::npos)
      << load(R"("period": [0, 0, -1, 0])");
  EXPECT_NE(load(R"("interpolation": "quintic")").find("functions[0].ops[0].interpolation"), std::string::npos);
  EXPECT_NE(load(R"("scale": 0)").find("functions[0].ops[0].scale"), std::string::npos);
  EXPECT_EQ(load(R"("octaves": 16, "ratio": 0.9, "period": [1, 2, 3, 4])"), "");
}
