#include "base/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>

#include "base/errors.h"

namespace gridifs {
namespace fs = std::filesystem;

namespace {

std::string errnoText(int error) { return std::strerror(error); }

// Flushes a file or folder to disk; returns 0 or the errno of the failure.
int syncPath(const fs::path& path, int flags) {
  const int fd = ::open(path.c_str(), flags | O_CLOEXEC);
  if (fd < 0) return errno;
  const int error = ::fsync(fd) == 0 ? 0 : errno;
  ::close(fd);
  return error;
}

}  // namespace

fs::path folderOf(const fs::path& file) { return file.has_parent_path() ? file.parent_path() : fs::path("."); }

namespace {

/// Removes the temporaries that earlier writers of `target` left behind when they were killed
/// (".STEM.tmp-PID-N.EXT" whose process PID no longer runs). A temporary of a writer that is
/// still running, here or in another process, is left alone.
void removeStaleTemporaries(const fs::path& target) {
  const std::string prefix = "." + target.stem().string() + ".tmp-", extension = target.extension().string();
  std::error_code ec;
  for (fs::directory_iterator it(folderOf(target), ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.size() <= prefix.size() + extension.size() || name.compare(0, prefix.size(), prefix) != 0 ||
        name.compare(name.size() - extension.size(), extension.size(), extension) != 0)
      continue;
    const std::string middle = name.substr(prefix.size(), name.size() - prefix.size() - extension.size());
    const std::size_t dash = middle.find('-');
    if (dash == 0 || dash == std::string::npos || middle.find_first_not_of("0123456789-") != std::string::npos ||
        middle.find('-', dash + 1) != std::string::npos)
      continue;
    const long pid = std::strtol(middle.c_str(), nullptr, 10);
    if (pid <= 0 || pid == long(::getpid()) || !(::kill(pid_t(pid), 0) != 0 && errno == ESRCH)) continue;
    std::error_code ignored;
    fs::remove(it->path(), ignored);
  }
}

}  // namespace

AtomicFile::AtomicFile(fs::path target) : target_(std::move(target)) {
  static std::atomic<unsigned> counter{0};
  const std::string name = "." + target_.stem().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                           std::to_string(counter++) + target_.extension().string();
  temporary_ = folderOf(target_) / name;
  removeStaleTemporaries(target_);
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  std::error_code ignored;
  fs::remove(temporary_, ignored);
}

void AtomicFile::commit() {
  auto fail = [&](const std::string& reason) {
    std::error_code ignored;
    fs::remove(temporary_, ignored);
    throw IoError("cannot write " + target_.string() + ": " + reason);
  };
  // Durable before it becomes visible under the final name.
  if (const int error = syncPath(temporary_, O_RDONLY); error != 0) fail(errnoText(error));
  std::error_code ec;
  fs::rename(temporary_, target_, ec);
  if (ec) fail(ec.message());
  committed_ = true;
  syncPath(folderOf(target_), O_RDONLY | O_DIRECTORY);  // best effort: the rename itself is done
}

void AtomicFile::write(std::string_view bytes) {
  const int fd = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw IoError("cannot write in " + folderOf(target_).string() + ": " + errnoText(errno));
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      const std::string reason = errnoText(errno);
      ::close(fd);
      throw IoError("cannot write " + target_.string() + ": " + reason);
    }
    written += std::size_t(n);
  }
  if (::close(fd) != 0) throw IoError("cannot write " + target_.string() + ": " + errnoText(errno));
}

void writeFileAtomically(const fs::path& target, std::string_view bytes) {
  AtomicFile file(target);
  file.write(bytes);
  file.commit();
}

}  // namespace gridifs
