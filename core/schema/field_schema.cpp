#include "schema/field_schema.h"

#include <cmath>
#include <stdexcept>

namespace gridifs {

double FieldSchema::number(const void* owner, int c) const {
  switch (type) {
    case FieldType::Number:
      return value<double>(owner);
    case FieldType::Integer:
      return double(value<int>(owner));
    case FieldType::Count:
      return double(value<std::int64_t>(owner));
    case FieldType::OptionalNumber:
      return value<std::optional<double>>(owner).value_or(0.0);
    case FieldType::Vector:
      return static_cast<const double*>(locate(const_cast<void*>(owner)))[c];
    default:
      return 0.0;
  }
}

void FieldSchema::setNumber(void* owner, int c, double v) const {
  switch (type) {
    case FieldType::Number:
      value<double>(owner) = v;
      break;
    case FieldType::Integer:
      value<int>(owner) = int(std::lround(v));
      break;
    case FieldType::Count:
      value<std::int64_t>(owner) = std::llround(v);
      break;
    case FieldType::OptionalNumber:
      value<std::optional<double>>(owner) = v;
      break;
    case FieldType::Vector:
      static_cast<double*>(locate(owner))[c] = v;
      break;
    default:
      throw std::logic_error(std::string("field ") + key + " is not a number");
  }
}

std::string listWithOr(const std::vector<std::string>& items) {
  std::string text;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i > 0) text += i + 1 == items.size() ? " or " : ", ";
    text += items[i];
  }
  return text;
}

std::string choiceList(const ChoiceNames& choices) {
  std::vector<std::string> names;
  for (const char* name : choices.names) names.push_back(std::string("\"") + name + "\"");
  return listWithOr(names);
}

int choiceIndex(const ChoiceNames& choices, std::string_view name) {
  for (std::size_t i = 0; i < choices.names.size(); ++i)
    if (name == choices.names[i]) return int(i);
  return -1;
}

}  // namespace gridifs
