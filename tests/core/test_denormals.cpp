// The running colour of the chaos game (Draves & Reckase, §5: c <- c + (c_i - c)·speed) must not
// settle on denormal floats: with a channel that is 0 in every function it decays towards 0, and
// without flushing it sticks on the smallest denormal, where every colour operation is slow.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <vector>

#include "render/chaos_kernel.h"
#include "render/compiled_ifs.h"
#include "tests/core/renderer_scenes.h"

namespace gridifs {
namespace {

bool zeroOrNormal(float v) { return v == 0.0f || std::fabs(v) >= FLT_MIN; }

/// The colour step the kernel takes, kept out of the optimiser's reach.
float colourStep(float c, float target, float speed) {
  volatile float v = c + (target - c) * speed;
  return v;
}

TEST(Denormals, TheColourStepNeverProducesADenormalInsideTheScopeAndTheModeIsRestored) {
  float stuck = FLT_MIN;
  for (int i = 0; i < 200; ++i) stuck = colourStep(stuck, 0.0f, 0.5f);
  EXPECT_GT(stuck, 0.0f) << "without flushing, c + (0 - c)/2 should stick on the smallest denormal";
  EXPECT_LT(stuck, FLT_MIN);
  {
    const kernel::DenormalsAreZero flush;
    float c = FLT_MIN;
    for (int i = 0; i < 200; ++i) {
      c = colourStep(c, 0.0f, 0.5f);
      ASSERT_TRUE(zeroOrNormal(c)) << "step " << i << " gave the denormal " << c;
    }
  }
  float after = FLT_MIN;
  for (int i = 0; i < 200; ++i) after = colourStep(after, 0.0f, 0.5f);
  EXPECT_EQ(after, stuck) << "the previous floating-point mode was not restored";
}

TEST(Denormals, ChainColoursStayZeroOrNormalWithEveryPaletteIndexZero) {
  Project p = test::sierpinskiTetrahedron();
  for (Function& f : p.functions) {
    f.palette_index = 0.0;
    f.color = Vec3{1.0, 0.0, 0.0};  // green and blue 0 everywhere as well
  }
  const auto ifs = compileIfs(p);
  std::vector<kernel::HotFunction> hot;
  for (const auto& f : ifs->functions) hot.push_back(kernel::makeHot(f));
  kernel::HotIfs hotIfs;
  hotIfs.functions = hot.data();
  hotIfs.alias = ifs->alias.data();
  hotIfs.count = std::uint32_t(hot.size());
  hotIfs.skip = 0;
  struct CountingPlot {
    std::int64_t plotted = 0;
    bool operator()(const kernel::v4f&, const kernel::v4f&) {
      ++plotted;
      return true;
    }
  } plot;
  const kernel::DenormalsAreZero flush;
  kernel::ChainState chain = kernel::ChainState::start(1, 0, 0);
  kernel::ChainCounters counters;
  kernel::runChain(chain, hotIfs, 1 << 16, plot, counters);
  for (int lane = 0; lane < kernel::kLanes; ++lane)
    for (int channel = 0; channel < 4; ++channel)
      EXPECT_TRUE(zeroOrNormal(chain.color[lane][channel])) << "lane " << lane << " channel " << channel;
  EXPECT_LT(chain.color[0][3], 1e-30f) << "palette index 0 in every function drives c towards 0";
}

}  // namespace
}  // namespace gridifs
