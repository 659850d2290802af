#include "base/system_memory.h"

#include <cstdio>
#include <fstream>
#include <sstream>

namespace gridifs {

std::optional<std::uint64_t> availableMemoryBytes() {
  std::ifstream in("/proc/meminfo");
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string key, unit;
    std::uint64_t value = 0;
    if (words >> key >> value >> unit && key == "MemAvailable:") return value * 1024;  // reported in kB
  }
  return std::nullopt;
}

std::string describeBytes(std::uint64_t bytes) {
  char text[32];
  const double mib = double(bytes) / double(1 << 20);
  if (mib >= 1024.0)
    std::snprintf(text, sizeof text, "%.1f GiB", mib / 1024.0);
  else
    std::snprintf(text, sizeof text, "%.0f MiB", mib);
  return text;
}

}  // namespace gridifs
