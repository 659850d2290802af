#include "model/field_schema.h"

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

}  // namespace gridifs
