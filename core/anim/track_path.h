#pragma once
// The address of a keyframed number: its path in the project file ("functions[0].ops[1].k",
// "render.flame.gamma", "camera.target[2]"). Parsing checks the syntax alone — names joined by
// dots, each followed by any number of [index] — and splits the path into tokens, one per level
// of the file's JSON, as a JSON pointer does; schema/project_parameter.h looks them up in a
// project. Tracks were first resolved through JSON pointers, and saved files may rely on what
// those read, so a name also splits at '/' and "~0" and "~1" stand for '~' and '/'
// ("camera/yaw" is camera.yaw), and a name of digits indexes a list ("functions.0.weight").
//
// The tokens are kept inside the object (a path has at most 256 characters), so parsing one
// allocates nothing: tracks are resolved on every edit and every time change.
//
// Thread-safety: plain values.
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace gridifs {

class TrackPath {
 public:
  static constexpr std::size_t kMaxLength = 256;

  /// The tokens of `path`, or std::nullopt when it is not a path: empty, longer than 256
  /// characters, an empty name, an index that is empty, not a number or of more than 6 digits,
  /// a stray or trailing dot, or a '~' that is not "~0" or "~1".
  static std::optional<TrackPath> parse(std::string_view path);

  std::size_t size() const { return count_; }
  std::string_view operator[](std::size_t i) const {
    const std::size_t begin = i == 0 ? 0 : ends_[i - 1];
    return std::string_view(tokens_.data() + begin, ends_[i] - begin);
  }

 private:
  // Filled as far as count_ says; the rest is never read.
  std::array<char, kMaxLength> tokens_;             // the tokens back to back, no longer than the path
  std::array<std::uint16_t, kMaxLength + 1> ends_;  // where each token ends
  std::size_t count_ = 0;
};

}  // namespace gridifs
