#pragma once
// GridIFS's two executables, built side by side (app/CMakeLists.txt): `gridifs`, the command line,
// and `gridifs-modeller`, which adds the window's libraries; and the one other processes run for
// this one (the farm's batch scripts, the modeller's animation renders).
#include <filesystem>
#include <string>
#include <system_error>

namespace gridifs {

inline constexpr const char* kCommandLineFileName = "gridifs";
inline constexpr const char* kModellerFileName = "gridifs-modeller";

/// `fileName` in the running executable's folder. Empty with `error` set where /proc/self/exe
/// cannot be read.
std::filesystem::path besideThisExecutable(const std::string& fileName, std::error_code& error);

/// The running executable, or, in gridifs-modeller, the command line beside it when that exists:
/// it runs the same verbs without loading the window's libraries. Empty with `error` set where
/// /proc/self/exe cannot be read.
std::filesystem::path commandLineExecutable(std::error_code& error);

}  // namespace gridifs
