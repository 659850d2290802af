#pragma once
// Reading a whole input file with a size bound, for the project and .flame readers: a hostile
// file is refused by its size before it is all in memory.
//
// Thread-safety: a pure function of the file system.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

namespace gridifs {

/// The bytes of `file`, or nullopt as soon as it holds more than `maxBytes`. Throws IoError
/// ("it is a folder, not a `kind`", "cannot open it: ...") when it cannot be read.
std::optional<std::string> readBoundedFile(const std::filesystem::path& file, std::size_t maxBytes,
                                           const std::string& kind);

}  // namespace gridifs
