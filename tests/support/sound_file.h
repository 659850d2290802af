#pragma once
// Synthetic sounds for the live tests, written as 16-bit PCM WAV files (the format every sound
// library reads), so a test's sound is exactly what its code says.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <vector>

namespace gridifs::test_support {

/// `samples` (interleaved when channels > 1, in [-1, 1]) as a 16-bit PCM WAV file.
inline void writeWav(const std::filesystem::path& file, const std::vector<float>& samples, int sampleRate,
                     int channels = 1) {
  std::ofstream out(file, std::ios::binary);
  auto u32 = [&](std::uint32_t v) { out.write(reinterpret_cast<const char*>(&v), 4); };
  auto u16 = [&](std::uint16_t v) { out.write(reinterpret_cast<const char*>(&v), 2); };
  const auto bytes = std::uint32_t(samples.size() * 2);
  out.write("RIFF", 4);
  u32(36 + bytes);
  out.write("WAVEfmt ", 8);
  u32(16);
  u16(1);  // PCM
  u16(std::uint16_t(channels));
  u32(std::uint32_t(sampleRate));
  u32(std::uint32_t(sampleRate * channels * 2));
  u16(std::uint16_t(channels * 2));
  u16(16);
  out.write("data", 4);
  u32(bytes);
  for (const float s : samples) {
    const auto v = std::int16_t(std::lround(std::clamp(s, -1.0f, 1.0f) * 32767.0f));
    out.write(reinterpret_cast<const char*>(&v), 2);
  }
}

/// `seconds` of silence, then `seconds` of a sine at `hertz` (amplitude 0.5).
inline std::vector<float> silenceThenTone(double seconds, double hertz, int sampleRate) {
  std::vector<float> s(std::size_t(2 * seconds * sampleRate), 0.0f);
  for (std::size_t i = s.size() / 2; i < s.size(); ++i)
    s[i] = float(0.5 * std::sin(2.0 * M_PI * hertz * double(i) / sampleRate));
  return s;
}

}  // namespace gridifs::test_support
