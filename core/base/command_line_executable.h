#pragma once
// The gridifs executable that other processes run for this one (the farm's batch scripts, the
// modeller's animation renders).
#include <filesystem>
#include <system_error>

namespace gridifs {

/// The running executable, or, in gridifs-modeller, the command line `gridifs` beside it when
/// that exists: it runs the same verbs without loading the window's libraries (app/CMakeLists.txt).
/// Empty with `error` set where /proc/self/exe cannot be read.
std::filesystem::path commandLineExecutable(std::error_code& error);

}  // namespace gridifs
