// The field schema that the operation table and the settings tables share: one accessor and one
// set of hints for a struct's member, whichever table it belongs to.
#include <gtest/gtest.h>

#include <type_traits>

#include "schema/field_schema.h"
#include "schema/operation_table.h"
#include "schema/settings_tables.h"

using namespace gridifs;

static_assert(std::is_same_v<ParamSpec, SettingSpec>, "operations and settings describe fields alike");
static_assert(std::is_same_v<ParamType, SettingType>);

namespace {

struct Sample {
  double ratio = 0.5;
  int count = 3;
  Vec3 offset{1.0, 2.0, 3.0};
  Axis axis = Axis::Y;
  std::optional<double> focus;
};

}  // namespace

TEST(FieldSchema, TypeAndAccessorsFollowTheMember) {
  const FieldSchema ratio = fieldSchema<&Sample::ratio>({.key = "ratio"});
  const FieldSchema count = fieldSchema<&Sample::count>({.key = "count"});
  const FieldSchema offset = fieldSchema<&Sample::offset>({.key = "offset"});
  const FieldSchema axis = fieldSchema<&Sample::axis>({.key = "axis"});
  const FieldSchema focus = fieldSchema<&Sample::focus>({.key = "focus"});
  EXPECT_EQ(ratio.type, FieldType::Number);
  EXPECT_EQ(count.type, FieldType::Integer);
  EXPECT_EQ(offset.type, FieldType::Vector);
  EXPECT_EQ(offset.components, 3);
  EXPECT_EQ(axis.type, FieldType::Choice);
  EXPECT_EQ(focus.type, FieldType::OptionalNumber);

  Sample s;
  EXPECT_TRUE(ratio.isDefault(&s));
  ratio.setNumber(s, 0, 0.25);
  EXPECT_EQ(s.ratio, 0.25);
  EXPECT_FALSE(ratio.isDefault(&s));
  count.setNumber(&s, 6.6);  // integers are rounded
  EXPECT_EQ(s.count, 7);
  offset.setNumber(s, 2, -4.0);
  EXPECT_EQ(offset.number(s, 2), -4.0);
  EXPECT_EQ(offset.value<Vec3>(s), Vec3(1.0, 2.0, -4.0));
  EXPECT_EQ(axis.choice(s), int(Axis::Y));
  axis.setChoice(s, int(Axis::Z));
  EXPECT_EQ(s.axis, Axis::Z);
  EXPECT_EQ(focus.number(&s), 0.0);  // unset
  focus.setNumber(&s, 2.5);
  EXPECT_EQ(s.focus, 2.5);
  EXPECT_THROW(axis.setNumber(&s, 1.0), std::logic_error);
}

// A parameter's owner is the OpParams variant; a setting's is its group. Both reach the member.
TEST(FieldSchema, OperationParametersAndSettingsReachTheirMembers) {
  const ParamSpec& k = findOperation("twist")->params.at(2);
  ASSERT_STREQ(k.key, "k");
  OpParams twist = TwistOp{};
  k.setNumber(twist, 0, 1.5);
  EXPECT_EQ(std::get<TwistOp>(twist).k, 1.5);
  EXPECT_EQ(k.number(twist), 1.5);

  const SettingSpec& gamma = flameSettingsTable().field("gamma");
  FlameSettings flame;
  gamma.setNumber(&flame, 3.0);
  EXPECT_EQ(flame.gamma, 3.0);
  EXPECT_EQ(gamma.number(&flame), 3.0);
}

// Text fields take their table's longest string when the entry names none: an expression for an
// operation, a name for a setting.
TEST(FieldSchema, TextLengthsDefaultByTable) {
  for (const ParamSpec& p : findOperation("calculator")->params) {
    if (p.type == ParamType::Expression) {
      EXPECT_EQ(p.maxLength, limits::kMaxExpressionLength) << p.key;
    }
  }
  EXPECT_EQ(flameSettingsTable().field("palette").maxLength, limits::kMaxNameLength);
}
