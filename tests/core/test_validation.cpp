// Validation of an edit checks only the functions that changed, with the same verdict and the
// same JSON-path errors as checking the whole project.
#include <gtest/gtest.h>

#include <string>

#include "edit/document.h"
#include "edit/project_edit.h"
#include "schema/validation.h"

using namespace gridifs;

namespace {

Project twoCalculators() {
  Project p;
  for (int i = 0; i < 2; ++i) {
    Function f;
    f.name = "f" + std::to_string(i);
    f.placement.scale = Vec3{0.5};
    Operation op;
    CalculatorOp calc;
    calc.x = "x*cos(v1) - y*sin(v1)";
    calc.y = "x*sin(v1) + y*cos(v1)";
    op.params = calc;
    f.ops.push_back(op);
    p.functions.push_back(f);
  }
  return p;
}

std::string errorPath(const std::function<void()>& check) {
  try {
    check();
  } catch (const ModelError& e) {
    return e.path() + ": " + e.message();
  }
  return "(valid)";
}

}  // namespace

TEST(Validation, ChangeOfOneFunctionGivesTheFullVerdict) {
  const Project before = twoCalculators();
  validateProject(before);
  Project broken = before;
  std::get<CalculatorOp>(broken.functions[1].ops[0].params).y = "x + (";
  const std::string full = errorPath([&] { validateProject(broken); });
  EXPECT_NE(full, "(valid)");
  EXPECT_EQ(full.rfind("functions[1].ops[0].y", 0), 0u) << full;
  EXPECT_EQ(errorPath([&] { validateProjectChange(broken, before); }), full);

  Project weightless = before;
  for (Function& f : weightless.functions) f.weight = 0.0;
  EXPECT_EQ(errorPath([&] { validateProjectChange(weightless, before); }),
            errorPath([&] { validateProject(weightless); }));
}

TEST(Validation, DocumentRefusesABrokenEditAfterValidEdits) {
  Document document(twoCalculators());
  Operation turned = document.project().functions[0].ops[0];
  std::get<CalculatorOp>(turned.params).vars[0].value = 0.3;
  document.apply("Turn", SetOperation{FunctionRef(0), 0, turned});
  const Project good = document.project();
  Operation broken = document.project().functions[1].ops[0];
  std::get<CalculatorOp>(broken.params).x = "sin(";
  EXPECT_THROW(document.apply("Break", SetOperation{FunctionRef(1), 0, broken}), ModelError);
  EXPECT_EQ(document.project(), good);
  document.beginGesture("Drag");
  Index3 flat = document.project().functions[0].resolution;
  flat[0] = 1;
  EXPECT_THROW(document.updateGesture(SetFunctionResolution{FunctionRef(0), flat}), ModelError);
  EXPECT_EQ(document.project(), good);
  document.endGesture();
}

TEST(Validation, DocumentChecksAProjectFromOutsideInFull) {
  // A Document may be handed an unchecked project; its first edit checks every function.
  Project invalid = twoCalculators();
  std::get<CalculatorOp>(invalid.functions[1].ops[0].params).z = "z +";
  Document document(invalid);
  EXPECT_THROW(document.apply(SetParameter{"functions[0].weight", 2.0}), ModelError);
}
