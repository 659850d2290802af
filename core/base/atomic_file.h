#pragma once
// Writing a file so that readers see either the old file or the whole new one, never a torn
// one: write a temporary file in the same folder, flush it to disk, rename it over the target.
// Every writer of the project (project, mesh, point cloud and image files, the GUI's files)
// goes through here.
//
// Thread-safety: an AtomicFile is used by one thread; distinct AtomicFiles are independent
// (temporary names include the process id and a process-wide counter).
#include <filesystem>
#include <string_view>

namespace gridifs {

/// A temporary file next to `target` (same folder and extension, a hidden name containing
/// ".tmp"), renamed over `target` by commit(). Writers that need a path (OpenMesh, OpenImageIO,
/// stdio) write temporaryPath(); the destructor removes the temporary unless it was committed.
/// The constructor removes the temporaries of `target` that killed writers left behind (those
/// whose process no longer runs), so a crash leaves nothing behind for longer than one write.
class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path target);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::filesystem::path& target() const { return target_; }
  const std::filesystem::path& temporaryPath() const { return temporary_; }

  /// Writes `bytes` as the whole temporary file. Throws IoError naming the target (or its folder
  /// when no file can be created there).
  void write(std::string_view bytes);

  /// Flushes the temporary to disk, renames it over the target and syncs the folder, so that the
  /// new file survives a crash. Throws IoError("cannot write TARGET: reason"); the old target is
  /// then intact and the temporary removed.
  void commit();

 private:
  std::filesystem::path target_, temporary_;
  bool committed_ = false;
};

/// Writes `bytes` to `target` through an AtomicFile. Throws IoError naming the target.
void writeFileAtomically(const std::filesystem::path& target, std::string_view bytes);

/// The folder a path lives in ("." for a bare file name).
std::filesystem::path folderOf(const std::filesystem::path& file);

}  // namespace gridifs
