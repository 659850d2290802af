#include "base/plugin_library.h"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <vector>

namespace gridifs {
namespace {

std::vector<std::string> candidates(const std::string& fileName, const char* variable, const std::string& buildDir) {
  if (const char* named = std::getenv(variable); named && *named) return {named};
  std::vector<std::string> paths;
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) paths.push_back((self.parent_path() / fileName).string());
  // Beside the shared object this code is linked into, when that is not the executable: the
  // Python module keeps its plugins beside it.
  Dl_info info{};
  if (dladdr(reinterpret_cast<const void*>(&candidates), &info) && info.dli_fname) {
    const std::filesystem::path object = std::filesystem::absolute(info.dli_fname, error);
    if (!error && object != self) paths.push_back((object.parent_path() / fileName).string());
  }
  paths.push_back(buildDir + "/" + fileName);
  paths.push_back(fileName);
  return paths;
}

// Loads the plugin's libraries, listed at build time beside it in load order
// (cmake/list_dependencies.cmake), in reverse: deepest first. Why: the loader resolves each
// symbol by walking the scope of the object being loaded, and in a plugin's scope the heaviest
// dependencies can sit deep (OpenImageIO brings GDAL, with ~48,000 symbol relocations, about 130
// libraries in), so one dlopen of the plugin spent ~0.2 CPU-seconds walking that list. A library
// loaded on its own heads its own scope, and the dependencies it needs are already in place. Lazy
// binding where a library allows it defers the rest to first use. A library that cannot be loaded
// alone is skipped: the plugin's own dlopen loads it as before, so the list is only a speed-up.
void preloadDependencies(const std::string& plugin) {
  const std::size_t dot = plugin.rfind(".so");
  if (dot == std::string::npos) return;
  std::ifstream list(plugin.substr(0, dot) + ".deps");
  std::vector<std::string> libraries;
  constexpr std::size_t kMaxLibraries = 4096;  // a bound for a damaged list
  for (std::string line; libraries.size() < kMaxLibraries && std::getline(list, line);)
    if (!line.empty() && line.front() == '/') libraries.push_back(line);
  for (auto it = libraries.rbegin(); it != libraries.rend(); ++it) dlopen(it->c_str(), RTLD_LAZY | RTLD_LOCAL);
}

}  // namespace

void* PluginLibrary::symbol(const char* name) const { return handle ? dlsym(handle, name) : nullptr; }

PluginLibrary loadPluginLibrary(const std::string& fileName, const char* variable, const std::string& buildDir,
                                const char* versionSymbol, int version, const std::string& what) {
  using VersionFunction = int (*)();
  std::string firstError;
  for (const std::string& path : candidates(fileName, variable, buildDir)) {
    if (path.find('/') != std::string::npos && !std::filesystem::exists(path)) {
      if (firstError.empty()) firstError = path + " does not exist";
      continue;
    }
    preloadDependencies(path);
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      if (firstError.empty()) firstError = dlerror();
      continue;
    }
    const auto versionOf = reinterpret_cast<VersionFunction>(dlsym(handle, versionSymbol));
    if (versionOf && versionOf() == version) return {handle, {}};
    if (firstError.empty()) firstError = path + " is from another version of GridIFS";
    dlclose(handle);
  }
  return {nullptr,
          what + " (" + fileName + ") could not be loaded" + (firstError.empty() ? std::string() : ": " + firstError)};
}

}  // namespace gridifs
