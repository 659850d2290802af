#pragma once
// GridIFS's plugins: the code linked to a heavy library (OpenImageIO for image files, OpenVDB for
// volumes) lives in a module loaded with dlopen when first needed, so a process that never writes
// an image or a volume never pays for loading those libraries (see image_io/ and vdb_io/).
//
// Thread-safety: loadPluginLibrary may run on any thread; callers load each plugin once.
#include <string>

namespace gridifs {

struct PluginLibrary {
  void* handle = nullptr;  // null when it could not be loaded
  std::string problem;     // why not, in words
  /// The address of `name` in the plugin (null when missing or not loaded).
  void* symbol(const char* name) const;
};

/// Loads plugin `fileName` (e.g. "libgridifs_image_io.so"): only where environment variable
/// `variable` names it, when set; else beside the running executable, in `buildDir` (for test and
/// benchmark binaries), or on the loader's search path. A candidate whose `versionSymbol` does not
/// return `version` (a stale plugin from another build) is refused. `what` names the plugin in the
/// problem ("the image library").
PluginLibrary loadPluginLibrary(const std::string& fileName, const char* variable, const std::string& buildDir,
                                const char* versionSymbol, int version, const std::string& what);

}  // namespace gridifs
