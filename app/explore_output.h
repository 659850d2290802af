#pragma once
// What `gridifs random` and `gridifs mutate` share: the output pattern ("world_%02d.gridifs" with
// --count), its check before anything is drawn, and writing each result atomically.
#include <cstdint>
#include <string>

#include "explore/explore.h"

namespace gridifs::cli {

/// Checks -o and --count before anything is drawn: a .gridifs name in a writable folder, with
/// one %d-style field when more than one project is written. Throws CliError(2).
void checkExploreOutput(const std::string& pattern, int count, int maxCount);

/// The file of result `index` (the pattern formatted with it, or the plain name).
std::string exploreOutputFile(const std::string& pattern, int count, int index);

/// Saves `result` to `file` and prints one line about it on stdout. Throws CliError(1).
void writeExploreResult(const ExploreResult& result, const std::string& file, const std::string& what);

}  // namespace gridifs::cli
