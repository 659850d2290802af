#include "schema/palette_reference.h"

#include <algorithm>

namespace gridifs {

const std::vector<std::string>& builtinPaletteNames() {
  static const std::vector<std::string> kNames = {"ember", "ice", "aurora", "sunset", "spectrum", "gray"};
  return kNames;
}

bool isPaletteReferenceSyntax(const std::string& reference) {
  if (reference.rfind("flam3:", 0) == 0) return reference.size() > 6;
  if (reference.rfind("file:", 0) == 0) return reference.size() > 5;
  const auto& names = builtinPaletteNames();
  return std::find(names.begin(), names.end(), reference) != names.end();
}

}  // namespace gridifs
