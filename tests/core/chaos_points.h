#pragma once
// The chaos game's points of a project, for the tests that check where its attractor lies.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "model/project.h"
#include "render/chaos_renderer.h"
#include "render/compiled_ifs.h"

namespace gridifs::test_support {

/// `samples` points of `p`'s chaos game, generated on two threads.
inline std::vector<Vec3> chaosPoints(const Project& p, std::int64_t samples) {
  RenderJob job = RenderJob::fromProject(p, 2);
  job.samples = samples;
  std::vector<Vec3> out;
  generatePoints(*compileIfs(p), job, [&](const PointBatch& b, const RenderStats&) {
    for (std::size_t i = 0; i < b.count; ++i) out.emplace_back(b.xyz[3 * i], b.xyz[3 * i + 1], b.xyz[3 * i + 2]);
    return true;
  });
  return out;
}

}  // namespace gridifs::test_support
