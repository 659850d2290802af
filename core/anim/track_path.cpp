#include "anim/track_path.h"

namespace gridifs {
namespace {

constexpr std::size_t kMaxIndexDigits = 6;

}  // namespace

// One pass over the characters, with no look-ups: tracks are resolved on every edit.
std::optional<TrackPath> TrackPath::parse(std::string_view path) {
  if (path.empty() || path.size() > kMaxLength) return std::nullopt;
  std::optional<TrackPath> result(std::in_place);
  TrackPath& parsed = *result;
  const std::size_t n = path.size();
  std::size_t length = 0, i = 0;
  auto endToken = [&] { parsed.ends_[parsed.count_++] = std::uint16_t(length); };
  while (i < n) {
    // A name, up to a dot or an index: one JSON pointer segment or more.
    const std::size_t name = i;
    for (; i < n && path[i] != '.' && path[i] != '['; ++i) {
      if (path[i] == '/') {
        endToken();
      } else if (path[i] == '~') {
        if (i + 1 == n || (path[i + 1] != '0' && path[i + 1] != '1')) return std::nullopt;
        parsed.tokens_[length++] = path[++i] == '0' ? '~' : '/';
      } else {
        parsed.tokens_[length++] = path[i];
      }
    }
    if (i == name) return std::nullopt;  // an empty name
    endToken();
    while (i < n && path[i] == '[') {
      const std::size_t digits = ++i;
      for (; i < n && path[i] >= '0' && path[i] <= '9'; ++i) parsed.tokens_[length++] = path[i];
      if (i == n || path[i] != ']' || i == digits || i - digits > kMaxIndexDigits) return std::nullopt;
      endToken();
      ++i;
    }
    if (i < n) {
      if (path[i] != '.') return std::nullopt;
      if (++i == n) return std::nullopt;  // a trailing dot
    }
  }
  return result;
}

}  // namespace gridifs
