#pragma once
// Small text helpers for messages and file names shared by the CLI, the modeller and the core.
//
// Thread-safety: pure functions.
#include <cstdint>
#include <filesystem>
#include <string>

namespace gridifs {

/// 1234567 → "1,234,567": face, vertex and point counts in messages.
std::string withThousands(std::uint64_t n);

/// The extension of `path` in lower case without the dot ("Out.PNG" → "png"; "" when none).
std::string lowerExtension(const std::filesystem::path& path);

}  // namespace gridifs
