#pragma once
// The points `gridifs export-points` writes, read back from its binary PLY (x, y, z as floats,
// then r, g, b bytes: 15 bytes a vertex).
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "base/types.h"
#include "run_command.h"

namespace gridifs::test_support {

/// The points of a binary PLY written by export-points (empty when it has no header).
inline std::vector<Vec3> readPly(const std::filesystem::path& file) {
  const std::string data = slurp(file);
  const std::size_t end = data.find("end_header\n");
  std::vector<Vec3> out;
  if (end == std::string::npos) return out;
  for (std::size_t at = end + 11; at + 15 <= data.size(); at += 15) {
    float xyz[3];
    std::memcpy(xyz, data.data() + at, 12);
    out.emplace_back(xyz[0], xyz[1], xyz[2]);
  }
  return out;
}

/// `samples` chaos-game points of `project` on the CPU, through the real executable.
inline std::vector<Vec3> exportPoints(const std::filesystem::path& project, const std::filesystem::path& ply,
                                      int samples) {
  const CommandResult r = runGridifs("export-points " + quote(project.string()) + " -o " + quote(ply.string()) +
                                     " --samples " + std::to_string(samples) + " --device cpu");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return readPly(ply);
}

}  // namespace gridifs::test_support
