// The universal calculator (Gröller & Wegenkittl 1994, §4.3): muparser expressions over node variables.
#include <cmath>

#include "model/calculator.h"
#include "op_test_support.h"

using namespace gridifs;
using namespace gridifs::test_support;

namespace {
CalculatorOp calc(std::string x, std::string y, std::string z) {
  CalculatorOp c;
  c.x = std::move(x);
  c.y = std::move(y);
  c.z = std::move(z);
  return c;
}
}  // namespace

TEST(Calculator, Figure14ExpressionMatchesTheFormula) {
  CalculatorOp c = calc("x*cos(v1*sqrt(x^2+y^2)) - y*sin(v1*sqrt(x^2+y^2))",
                        "x*sin(v1*sqrt(x^2+y^2)) + y*cos(v1*sqrt(x^2+y^2))", "z");
  c.vars[0].value = 0.2;
  expectNodes(functionWith({6, 6, 4}, {op(c)}), [](const Vec3& p, int, int, int) {
    const double d = std::sqrt(p.x * p.x + p.y * p.y), v1 = 0.2;
    return Vec3{p.x * std::cos(v1 * d) - p.y * std::sin(v1 * d), p.x * std::sin(v1 * d) + p.y * std::cos(v1 * d), p.z};
  });
}

TEST(Calculator, ProvidesTheDocumentedVariablesAndFunctions) {
  CalculatorOp c =
      calc("sin(x)+cos(y)+tan(z*0.5)+asin(x*0.5)+acos(y*0.5)+atan(z)+sinh(x)+cosh(y)+tanh(z)",
           "log(2+x)+exp(y)+sqrt(2+z)+abs(x)+min(x,y)+max(y,z)+pow(2,x)+pi+e", "cx+cy+cz+i+2*j+3*k+v1+v2+v3");
  c.vars = {CalculatorVar{0.1, -1, 1}, CalculatorVar{0.2, -1, 1}, CalculatorVar{0.3, -1, 1}};
  const Vec3 center{0.05, -0.1, 0.2};
  expectNodes(functionWith({3, 3, 3}, {op(c, {Center::Kind::Point, center})}), [&](const Vec3& p, int i, int j, int k) {
    const double x = p.x, y = p.y, z = p.z;
    return Vec3{std::sin(x) + std::cos(y) + std::tan(z * 0.5) + std::asin(x * 0.5) + std::acos(y * 0.5) + std::atan(z) +
                    std::sinh(x) + std::cosh(y) + std::tanh(z),
                std::log(2 + x) + std::exp(y) + std::sqrt(2 + z) + std::abs(x) + std::min(x, y) + std::max(y, z) +
                    std::pow(2, x) + M_PI + M_E,
                center.x + center.y + center.z + i + 2 * j + 3 * k + 0.6};
  });
}

TEST(Calculator, RandIsDeterministicPerNodeAndPerOp) {
  CalculatorOp c = calc("x + 0.1*rand()", "y + 0.1*rand() - 0.1*rand()", "z");
  c.seed = 42;
  const Function f = functionWith({5, 5, 5}, {op(c)});
  const Grid a = evaluateFunction(f), b = evaluateFunction(f);
  EXPECT_EQ(a, b);  // re-evaluating never jitters the grid
  const Grid u(f.resolution);
  bool anyMoved = false;
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 5; ++i) {
        const double expected = u.node(i, j, k).x + 0.1 * calculatorRandom(42, 0, i, j, k, 0);
        EXPECT_DOUBLE_EQ(a.node(i, j, k).x, expected);
        // two calls in one expression draw two different numbers
        EXPECT_NE(calculatorRandom(42, 1, i, j, k, 0), calculatorRandom(42, 1, i, j, k, 1));
        anyMoved |= a.node(i, j, k).y != u.node(i, j, k).y;
      }
  EXPECT_TRUE(anyMoved);
  CalculatorOp other = c;
  other.seed = 43;
  EXPECT_NE(evaluateFunction(functionWith({5, 5, 5}, {op(other)})), a);
  // values lie in [0, 1) and look uniform
  double sum = 0;
  for (int n = 0; n < 10000; ++n) {
    const double v = calculatorRandom(7, 0, n % 37, n / 37, 3, n % 3);
    ASSERT_GE(v, 0.0);
    ASSERT_LT(v, 1.0);
    sum += v;
  }
  EXPECT_NEAR(sum / 10000, 0.5, 0.02);
}

TEST(Calculator, RandIsUnaffectedBySelectionAndOtherNodes) {
  CalculatorOp c = calc("x + rand()", "y", "z");
  const Grid all = evaluateFunction(functionWith({4, 4, 4}, {op(c)}));
  const Grid some = evaluateFunction(functionWith({4, 4, 4}, {op(c, {}, {{{2, 3}, {0, 3}, {0, 3}, SelectionOp::Or}})}));
  EXPECT_DOUBLE_EQ(all.node(3, 1, 2).x, some.node(3, 1, 2).x);
}

TEST(Calculator, SyntaxErrorsAreReportedWithAPosition) {
  auto d = checkCalculator(calc("x*(y+", "y", "z"));
  ASSERT_TRUE(d.has_value());
  EXPECT_EQ(d->expression, 0);
  EXPECT_FALSE(d->message.empty());
  d = checkCalculator(calc("x", "y + foo", "z"));
  ASSERT_TRUE(d.has_value());
  EXPECT_EQ(d->expression, 1);
  EXPECT_NE(d->message.find("foo"), std::string::npos) << d->message;
  EXPECT_GE(d->position, 0);
  d = checkCalculator(calc("x", "y", ""));
  ASSERT_TRUE(d.has_value());
  EXPECT_EQ(d->expression, 2);
  EXPECT_FALSE(checkCalculator(calc("x", "y", "z")).has_value());
}

TEST(Calculator, NonFiniteResultsAreErrorsNotNodes) {
  EXPECT_THROW(evaluateFunction(functionWith({3, 3, 3}, {op(calc("sqrt(x-2)", "y", "z"))})), ModelError);
  EXPECT_THROW(evaluateFunction(functionWith({3, 3, 3}, {op(calc("1/(x-x)", "y", "z"))})), ModelError);
}
