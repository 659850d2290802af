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

// The value of /proc/cpuinfo's first line whose key is `key` ("" when there is none).
std::string cpuinfoValue(const std::string& key) {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    std::string name = line.substr(0, colon);
    while (!name.empty() && (name.back() == ' ' || name.back() == '\t')) name.pop_back();
    if (name == key) return colon + 2 <= line.size() ? line.substr(colon + 2) : std::string();
  }
  return "";
}

// The model name, and its family and model numbers: a hypervisor may show every generation of a
// vendor's server CPUs under one name ("AMD EPYC"), and they differ in speed.
std::string cpuModel() {
  const std::string name = cpuinfoValue("model name");
  const std::string family = cpuinfoValue("cpu family");
  const std::string model = cpuinfoValue("model");
  std::string described = name.empty() ? "unknown" : name;
  if (!family.empty() && !model.empty()) described += " (family " + family + " model " + model + ")";
  return described;
}

bool hasAvx512() { return (" " + cpuinfoValue("flags") + " ").find(" avx512f ") != std::string::npos; }

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
