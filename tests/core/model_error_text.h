#pragma once
// The text of the ModelError that `check` throws ("functions[1].ops[0].k: expected ..."), or ""
// when it throws none: error-message tests compare strings instead of repeating try/catch.
#include <string>

#include "base/errors.h"

namespace gridifs::test_support {

template <class Check>
std::string modelErrorText(Check&& check) {
  try {
    check();
  } catch (const ModelError& e) {
    return e.what();
  }
  return "";
}

}  // namespace gridifs::test_support
