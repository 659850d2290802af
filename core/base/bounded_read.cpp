#include "base/bounded_read.h"

#include <cerrno>
#include <cstring>
#include <fstream>

#include "base/errors.h"

namespace gridifs {

std::optional<std::string> readBoundedFile(const std::filesystem::path& file, std::size_t maxBytes,
                                           const std::string& kind) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) throw IoError("it is a folder, not a " + kind);
  std::ifstream in(file, std::ios::binary);
  if (!in) throw IoError(std::string("cannot open it: ") + std::strerror(errno));
  std::string text;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, std::size_t(in.gcount()));
    if (text.size() > maxBytes) return std::nullopt;
  }
  return text;
}

}  // namespace gridifs
