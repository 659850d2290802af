#include "render/image_file.h"

#include <dlfcn.h>

#include <cstdlib>
#include <fstream>
#include <future>
#include <mutex>

#include "base/atomic_file.h"
#include "base/errors.h"
#include "image_writer_abi.h"

namespace gridifs {
namespace {

constexpr const char* kPluginFile = "libgridifs_image_io.so";

using WriteFunction = int (*)(const GridifsImageRequest*, char*, size_t);
using VersionFunction = int (*)();

struct ImageWriter {
  WriteFunction write = nullptr;
  std::string problem;  // why it could not be loaded
};

// Where the plugin may be: only where GRIDIFS_IMAGE_IO names it, when it is set; else beside the
// running executable (the gridifs binary), in the build tree it was built in (test and benchmark
// binaries), or on the loader's search path.
std::vector<std::string> candidates() {
  std::vector<std::string> paths;
  if (const char* named = std::getenv("GRIDIFS_IMAGE_IO"); named && *named) return {named};
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) paths.push_back((self.parent_path() / kPluginFile).string());
  paths.push_back(std::string(GRIDIFS_IMAGE_IO_BUILD_DIR) + "/" + kPluginFile);
  paths.emplace_back(kPluginFile);
  return paths;
}

// Loads the plugin's libraries, listed at build time beside it in load order
// (image_io/list_dependencies.cmake), in reverse: deepest first. Why: the loader resolves each
// symbol by walking the scope of the object being loaded, and in the plugin's scope OpenImageIO's
// heaviest dependencies sit deep (GDAL, with ~48,000 symbol relocations, comes about 130 libraries
// in), so one dlopen of the plugin spends ~0.2 CPU-seconds walking that list. A library loaded on
// its own heads its own scope, and the dependencies it needs are already in place. Lazy binding
// where a library allows it defers the rest to first use. A library that cannot be loaded alone is
// skipped: the plugin's own dlopen loads it as before, so the list is only a speed-up.
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

ImageWriter load() {
  std::string firstError;
  for (const std::string& path : candidates()) {
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
    const auto version = reinterpret_cast<VersionFunction>(dlsym(handle, "gridifs_image_io_abi_version"));
    const auto write = reinterpret_cast<WriteFunction>(dlsym(handle, "gridifs_image_io_write"));
    if (version && write && version() == GRIDIFS_IMAGE_IO_ABI_VERSION) return {write, {}};
    if (firstError.empty()) firstError = path + " is from another version of GridIFS";
    dlclose(handle);
  }
  return {nullptr, "the image library (" + std::string(kPluginFile) + ") could not be loaded" +
                       (firstError.empty() ? std::string() : ": " + firstError)};
}

struct Loading {
  std::once_flag started;
  std::shared_future<ImageWriter> writer;
};

Loading& loading() {
  static Loading state;
  return state;
}

// Starts loading once: on a helper thread when asked ahead of time, else on first use.
const ImageWriter& writer(std::launch how) {
  Loading& state = loading();
  std::call_once(state.started, [&] { state.writer = std::async(how, load).share(); });
  return state.writer.get();
}

int storedCode(StoredSample s) {
  switch (s) {
    case StoredSample::UInt8:
      return GRIDIFS_STORED_UINT8;
    case StoredSample::UInt16:
      return GRIDIFS_STORED_UINT16;
    case StoredSample::Half:
      return GRIDIFS_STORED_HALF;
    case StoredSample::Float:
      return GRIDIFS_STORED_FLOAT;
  }
  return GRIDIFS_STORED_UINT8;
}

void write(const std::filesystem::path& file, const ImageFileLayout& layout, bool isFloat, const void* pixels) {
  const ImageWriter& plugin = writer(std::launch::deferred);
  if (!plugin.write) throw IoError("cannot write " + file.string() + ": " + plugin.problem);
  std::vector<const char*> names;
  for (const std::string& name : layout.channels) names.push_back(name.c_str());
  AtomicFile atomic(file);
  const std::string temporary = atomic.temporaryPath().string();
  const GridifsImageRequest request{temporary.c_str(), layout.width,     layout.height,     int(names.size()),
                                    names.data(),      layout.alphaChannel, layout.zChannel, storedCode(layout.stored),
                                    isFloat ? 1 : 0,   pixels,           layout.description.c_str()};
  char message[1024] = {};
  if (!plugin.write(&request, message, sizeof message)) throw IoError("cannot write " + file.string() + ": " + message);
  atomic.commit();
}

}  // namespace

void startLoadingImageWriter() {
  Loading& state = loading();
  std::call_once(state.started, [&] { state.writer = std::async(std::launch::async, load).share(); });
}

void writeImageFile(const std::filesystem::path& file, const ImageFileLayout& layout, const std::uint8_t* pixels) {
  write(file, layout, false, pixels);
}

void writeImageFile(const std::filesystem::path& file, const ImageFileLayout& layout, const float* pixels) {
  write(file, layout, true, pixels);
}

}  // namespace gridifs
