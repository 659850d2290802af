// The inclusion chain of Thollot, Zair, Tosan & Vandorpe 1997, §4.4 (their figure 4.3), on
// rendered coverage: A(H̃1) and A(H̃2) ⊂ A(H̃1 ◇ H̃2) ⊂ A(H̃1 ∪ H̃2) ⊂ A(H̃1 ⊗ H̃2), each attractor
// taken over all its states. The example projects of assets/matrices are planar (z = 0): their
// chaos-game points are binned on a pixel grid over the square [-1, 1]², and each set must lie in
// the next one grown by a pixel.
#include <gtest/gtest.h>

#include "construction/ifs_combination.h"
#include "io/project_io.h"
#include "render/chaos_renderer.h"
#include "render/compiled_ifs.h"

using namespace gridifs;

namespace {

constexpr int kPixels = 96;

const std::string kMatrices = std::string(GRIDIFS_ASSETS) + "/matrices/";

using Coverage = std::vector<char>;

Coverage coverage(const Project& p, std::int64_t samples) {
  RenderJob job = RenderJob::fromProject(p, 2);
  job.samples = samples;
  Coverage hit(kPixels * kPixels, 0);
  generatePoints(*compileIfs(p), job, [&](const PointBatch& b, const RenderStats&) {
    for (std::size_t i = 0; i < b.count; ++i) {
      const int x = int((b.xyz[3 * i] + 1.0f) * 0.5f * kPixels), y = int((b.xyz[3 * i + 1] + 1.0f) * 0.5f * kPixels);
      if (x >= 0 && x < kPixels && y >= 0 && y < kPixels) hit[std::size_t(y * kPixels + x)] = 1;
    }
    return true;
  });
  return hit;
}

Coverage grown(const Coverage& c) {
  Coverage out(c.size(), 0);
  for (int y = 0; y < kPixels; ++y)
    for (int x = 0; x < kPixels; ++x)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int u = x + dx, v = y + dy;
          if (u >= 0 && u < kPixels && v >= 0 && v < kPixels && c[std::size_t(v * kPixels + u)])
            out[std::size_t(y * kPixels + x)] = 1;
        }
  return out;
}

/// Pixels of `small` outside `large` grown by one pixel.
int outside(const Coverage& small, const Coverage& large) {
  const Coverage g = grown(large);
  int n = 0;
  for (std::size_t i = 0; i < small.size(); ++i) n += small[i] && !g[i];
  return n;
}

int count(const Coverage& c) { return int(std::count(c.begin(), c.end(), 1)); }

}  // namespace

TEST(MatrixInclusion, FigureFourThreeChainOnRenderedCoverage) {
  const Project h1 = loadProject(kMatrices + "h1_triangle_states.gridifs");
  const Project h2 = loadProject(kMatrices + "h2_dust_states.gridifs");
  // `combine concat A B` continues A's chains into B's maps: B's words come first, H̃_B ◇ H̃_A.
  const Project concat = combineProjects(h2, h1, CombineOp::Concat);
  const Project matrixUnion = combineProjects(h1, h2, CombineOp::MatrixUnion);
  const Project tensor = combineProjects(h1, h2, CombineOp::Product);
  constexpr std::int64_t kSamples = 400000;
  const Coverage c1 = coverage(h1, kSamples), c2 = coverage(h2, kSamples), cc = coverage(concat, kSamples),
                 cu = coverage(matrixUnion, kSamples), ct = coverage(tensor, kSamples);
  for (const Coverage* c : {&c1, &c2, &cc, &cu, &ct}) EXPECT_GT(count(*c), 100);
  // Each set inside the next (a few stray pixels allowed: finitely many samples near edges).
  EXPECT_LE(outside(c1, cc), count(c1) / 100);
  EXPECT_LE(outside(c2, cc), count(c2) / 100);
  EXPECT_LE(outside(cc, cu), count(cc) / 100);
  EXPECT_LE(outside(cu, ct), count(cu) / 100);
  // And the inclusions are strict on this example.
  EXPECT_GT(outside(cu, cc), count(cu) / 20);
  EXPECT_GT(outside(ct, cu), count(ct) / 100);
  EXPECT_GT(outside(cc, c1), count(cc) / 20);
}
