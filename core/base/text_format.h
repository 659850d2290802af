#pragma once
// Small text helpers for messages and file names shared by the CLI, the modeller and the core.
//
// Thread-safety: pure functions.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace gridifs {

/// 1234567 → "1,234,567": face, vertex and point counts in messages.
std::string withThousands(std::uint64_t n);

/// `text` in lower case (ASCII letters only): a label inside a sentence ("Field " + "octaves").
std::string lowercase(std::string text);

/// The extension of `path` in lower case without the dot ("Out.PNG" → "png"; "" when none).
std::string lowerExtension(const std::filesystem::path& path);

/// What is wrong with the name pattern of an image sequence, or nothing: it needs exactly one
/// printf integer conversion (%d, %4d, %04d; at most two width digits) and no other % but "%%".
/// The answer completes "the output name PATTERN …" ("has no frame number: …").
std::optional<std::string> framePatternProblem(const std::string& pattern);

/// The file name of frame `frame`: a pattern that has no problem, printf-formatted with it.
std::string frameFileName(const std::string& pattern, std::int64_t frame);

}  // namespace gridifs
