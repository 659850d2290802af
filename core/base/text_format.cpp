#include "base/text_format.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <vector>

namespace gridifs {

std::string withThousands(std::uint64_t n) {
  const std::string digits = std::to_string(n);
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return text;
}

std::string lowerExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  if (!ext.empty() && ext[0] == '.') ext.erase(0, 1);
  return lowercase(ext);
}

std::optional<std::string> framePatternProblem(const std::string& pattern) {
  int conversions = 0;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '%') continue;
    if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j])) && j - i <= 2) ++j;
    if (j >= pattern.size() || pattern[j] != 'd')
      return "has a % that is not a frame number like %04d (write %% for a percent sign)";
    ++conversions;
    i = j;
  }
  if (conversions == 0) return "has no frame number: a sequence needs a pattern such as out_%04d.png";
  if (conversions > 1) return "has more than one frame number; use one such as %04d";
  return std::nullopt;
}

std::string frameFileName(const std::string& pattern, std::int64_t frame) {
  // The pattern has one %Nd conversion, widened here to a 64-bit one.
  std::string format;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    format += pattern[i];
    if (pattern[i] != '%') continue;
    if (pattern[i + 1] == '%') {
      format += pattern[++i];
      continue;
    }
    while (pattern[i + 1] != 'd') format += pattern[++i];
    format += "ll";
  }
  std::vector<char> name(pattern.size() + 32);
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wformat-nonliteral"
  std::snprintf(name.data(), name.size(), format.c_str(), static_cast<long long>(frame));
#pragma GCC diagnostic pop
  return name.data();
}

}  // namespace gridifs
