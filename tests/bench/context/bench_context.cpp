// Linked into every benchmark program: the report names the CPU model (machines of one kind differ,
// so a figure without its CPU means little), and the program prints its peak memory (maximum
// resident set) and CPU seconds when it exits, beside the benchmarks' own times.
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

namespace {

std::string cpuModel() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      const std::size_t colon = line.find(':');
      return colon == std::string::npos ? line : line.substr(colon + 2);
    }
  return "unknown";
}

bool hasAvx512() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("flags", 0) == 0) return line.find(" avx512f") != std::string::npos;
  return false;
}

void reportResources() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const double cpu = double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                     1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  std::fprintf(stderr, "process: %.2f CPU seconds (%.2f user + %.2f system), peak memory %.0f MB, CPU %s%s\n", cpu,
               double(usage.ru_utime.tv_sec) + 1e-6 * double(usage.ru_utime.tv_usec),
               double(usage.ru_stime.tv_sec) + 1e-6 * double(usage.ru_stime.tv_usec), double(usage.ru_maxrss) / 1024.0,
               cpuModel().c_str(), hasAvx512() ? " (AVX-512)" : "");
}

const bool kRegistered = [] {
  benchmark::AddCustomContext("cpu_model", cpuModel() + (hasAvx512() ? " (AVX-512)" : ""));
  std::atexit(reportResources);
  return true;
}();

}  // namespace
