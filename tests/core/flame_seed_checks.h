#pragma once
// A flame render as a function of its seed alone: the same histogram for one thread and three,
// another for the next seed.
#include <gtest/gtest.h>

#include <cstdint>
#include <memory>

#include "render/accumulation.h"
#include "render/chaos_renderer.h"
#include "render/compiled_ifs.h"
#include "tone/palette.h"

namespace gridifs::test {

/// Renders `project` with colour sums (`samples` samples) on one thread and on three, and with
/// the next seed; expects the first two identical and the third not.
inline void expectAFunctionOfTheSeedForAnyThreadCount(const Project& project, std::int64_t samples) {
  const auto ifs = compileIfs(project);
  RenderJob job = RenderJob::fromProject(project, 1);
  job.samples = samples;
  job.accumulateColor = true;
  job.palette = std::make_shared<const Palette>(builtinPalette("ember"));
  const Accumulation one = accumulateToCompletion(ifs, job);
  job.threads = 3;
  const Accumulation three = accumulateToCompletion(ifs, job);
  EXPECT_TRUE(one.density == three.density);
  EXPECT_TRUE(one.colorSums == three.colorSums);
  EXPECT_GT(one.plotted, samples / 3);
  job.seed += 1;
  const Accumulation other = accumulateToCompletion(ifs, job);
  EXPECT_FALSE(one.density == other.density);
}

}  // namespace gridifs::test
