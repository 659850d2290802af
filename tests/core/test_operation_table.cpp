// The operation table: it covers every operation, and reading, writing and validation follow it
// (keys, ranges, choices, rules) for every parameter of every operation.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>

#include "io/project_io.h"
#include "model_error_text.h"
#include "schema/operation_table.h"

using namespace gridifs;

namespace {

Project projectWith(const OpParams& params) {
  Project p;
  Function f;
  f.ops.push_back(Operation{params, {}, {}, false});
  p.functions.push_back(f);
  return p;
}

std::string validationErrorOf(const Project& p) {
  return test_support::modelErrorText([&] { validateProject(p); });
}

std::string parseErrorOf(const std::string& text) {
  return test_support::modelErrorText([&] { parseProject(text); });
}

/// The written JSON of a project whose only op is `params`, with `edit` applied to the op.
std::string withOpJson(const OpParams& params, const std::function<void(nlohmann::json&)>& edit) {
  nlohmann::json root = nlohmann::json::parse(serializeProject(projectWith(params)));
  edit(root["functions"][0]["ops"][0]);
  return root.dump();
}

}  // namespace

TEST(OperationTable, DescribesEveryOperationOnceInVariantOrder) {
  const auto& table = operationTable();
  ASSERT_EQ(table.size(), std::variant_size_v<OpParams>);
  std::set<std::string> types;
  for (std::size_t i = 0; i < table.size(); ++i) {
    const OperationSpec& spec = table[i];
    SCOPED_TRACE(spec.type);
    EXPECT_EQ(spec.defaults.index(), i);
    EXPECT_TRUE(types.insert(spec.type).second);
    EXPECT_EQ(findOperation(spec.type), &spec);
    EXPECT_EQ(std::string(opTypeName(spec.defaults)), spec.type);
    std::set<std::string> keys;
    for (const ParamSpec& param : spec.params) {
      EXPECT_TRUE(keys.insert(param.key).second) << param.key;
      EXPECT_NE(std::string(param.key), "type");
      EXPECT_NE(std::string(param.label), "");
      if (param.type == ParamType::Choice) {
        ASSERT_NE(param.choices, nullptr);
        EXPECT_EQ(param.choices->names.size(), param.choices->labels.size());
      }
      EXPECT_LE(param.min, param.max);
    }
    EXPECT_EQ(validationErrorOf(projectWith(spec.defaults)), "") << "the defaults must be valid";
  }
  EXPECT_EQ(findOperation("warp"), nullptr);
  EXPECT_EQ(operationTypeList(),
            "translate, rotate, scale, taper, twist, bend, magnet, morph, calculator, nodes or field");
}

TEST(OperationTable, WritesEveryParameterUnderItsKeyInTableOrder) {
  for (const OperationSpec& spec : operationTable()) {
    SCOPED_TRACE(spec.type);
    const nlohmann::ordered_json op =
        nlohmann::ordered_json::parse(serializeProject(projectWith(spec.defaults)))["functions"][0]["ops"][0];
    auto it = op.begin();
    EXPECT_EQ(it.key(), "type");
    EXPECT_EQ(it.value(), spec.type);
    for (const ParamSpec& param : spec.params) {
      ++it;
      ASSERT_NE(it, op.end());
      EXPECT_EQ(it.key(), param.key);
    }
    EXPECT_EQ((++it).key(), "center");
  }
}

TEST(OperationTable, AbsentKeysReadAsTheDefaults) {
  for (const OperationSpec& spec : operationTable()) {
    SCOPED_TRACE(spec.type);
    const std::string text =
        std::string(R"({"format":"gridifs","version":1,"functions":[{"ops":[{"type":")") + spec.type + R"("}]}]})";
    EXPECT_EQ(parseProject(text).functions[0].ops[0].params, spec.defaults);
  }
}

// Every bounded number is refused past its bounds, in a file and in an in-memory edit, with the
// same path and message.
TEST(OperationTable, RangesApplyToFilesAndEditsAlike) {
  int checked = 0;
  for (const OperationSpec& spec : operationTable()) {
    for (const ParamSpec& param : spec.params) {
      if (param.type != ParamType::Number && param.type != ParamType::Vector) continue;
      SCOPED_TRACE(std::string(spec.type) + "." + param.key);
      for (const double bad : {param.min - 1.0, param.max + 1.0}) {
        OpParams params = spec.defaults;
        param.setNumber(params, 0, bad);
        const std::string path = std::string(param.key) + (param.type == ParamType::Vector ? "[0]" : "");
        const std::string edit = validationErrorOf(projectWith(params));
        EXPECT_EQ(edit.rfind("functions[0].ops[0]." + path + ": expected a number between ", 0), 0u) << edit;
        const std::string file = parseErrorOf(withOpJson(spec.defaults, [&](nlohmann::json& op) {
          if (param.type == ParamType::Vector)
            op[param.key][0] = bad;
          else
            op[param.key] = bad;
        }));
        EXPECT_EQ(file, edit);
        ++checked;
      }
    }
  }
  EXPECT_GE(checked, 20);
}

TEST(OperationTable, ChoicesAreReadByNameAndRefusedWithTheList) {
  const std::string bad = parseErrorOf(withOpJson(TwistOp{}, [](nlohmann::json& op) { op["profile"] = "square"; }));
  EXPECT_EQ(bad, R"(functions[0].ops[0].profile: expected "linear", "sine" or "pingpong")");
  const std::string axis = parseErrorOf(withOpJson(BendOp{}, [](nlohmann::json& op) { op["toward"] = "w"; }));
  EXPECT_EQ(axis, R"(functions[0].ops[0].toward: expected "x", "y" or "z")");
  const Project p = parseProject(withOpJson(TaperOp{}, [](nlohmann::json& op) { op["profile"] = "pingpong"; }));
  EXPECT_EQ(std::get<TaperOp>(p.functions[0].ops[0].params).profile, Profile::PingPong);
}

TEST(OperationTable, RulesRunForFilesAndEdits) {
  const std::string message = "functions[0].ops[0].toward: the bend must go toward an axis other than its own";
  EXPECT_EQ(validationErrorOf(projectWith(BendOp{Axis::Y, Axis::Y, 1.0})), message);
  EXPECT_EQ(parseErrorOf(withOpJson(BendOp{}, [](nlohmann::json& op) { op["toward"] = "z"; })), message);
  CalculatorOp calc;
  calc.vars[1].min = 2.0;  // above its maximum of 1
  EXPECT_EQ(validationErrorOf(projectWith(calc)),
            "functions[0].ops[0].vars.v2.min: the slider minimum is larger than its maximum");
  calc = CalculatorOp{};
  calc.y = "y +";
  EXPECT_EQ(validationErrorOf(projectWith(calc)).rfind("functions[0].ops[0].y: ", 0), 0u);
}

TEST(OperationTable, SummariesNameTheMainParameters) {
  EXPECT_EQ(operationSummary(TwistOp{Axis::X, Profile::Sine, 1.5, 2.0}), "x sine k=1.50");
  EXPECT_EQ(operationSummary(MorphOp{{MorphPair{}, MorphPair{}}, 1.0}), "2 pairs");
}
