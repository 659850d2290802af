#pragma once
// A project names its flame palette by reference: a built-in name ("ember"), a palette of
// flam3's file ("flam3:27", "flam3:south-sea-bather") or a palette file ("file:PATH"). The model
// only checks the syntax; tone/palette.h resolves a reference into colors.
//
// Thread-safety: pure functions and immutable data.
#include <string>
#include <vector>

namespace gridifs {

/// Built-in palette names, in display order (the first is the default). tone/palette.cpp
/// holds their colors.
const std::vector<std::string>& builtinPaletteNames();

/// The default palette reference of a project ("ember").
inline constexpr const char* kDefaultPaletteRef = "ember";

/// Whether a reference is syntactically valid (a built-in name, "flam3:..." or "file:...");
/// used by project validation, which must not depend on files being present.
bool isPaletteReferenceSyntax(const std::string& reference);

}  // namespace gridifs
