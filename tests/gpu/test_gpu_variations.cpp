// Flame variations on the GPU (label `gpu`, llvmpipe on CI): every variation of the table through
// the shader's own map against the CPU's (deterministic ones point by point at float tolerance,
// random ones by their distributions), and a render with several variations, pre_blur and post
// maps against the CPU's picture and density volume.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "gpu/chaos_compute.h"
#include "gpu/correlation.h"
#include "gpu/gpu_chaos_renderer.h"
#include "gpu/headless_gl_context.h"
#include "gpu/render_device.h"
#include "gpu_test_support.h"
#include "render/compiled_ifs.h"
#include "variations/flame_variations.h"
#include "volume/measure_attractor.h"

namespace gridifs {
namespace {

using Point = std::array<float, 3>;

/// Parameters that make each variation do something (flam3's defaults leave several degenerate:
/// perspective_dist 0, pdj all 0, julian_power 1).
double testParameter(const std::string& attribute, double fallback, std::size_t k) {
  static const std::map<std::string, double> chosen = {
      {"perspective_angle", 0.3}, {"perspective_dist", 2.0}, {"julian_power", 3.0},      {"julian_dist", 1.2},
      {"juliascope_power", -3.0}, {"juliascope_dist", 0.8},  {"wedge_julia_power", 2.0}, {"wedge_julia_count", 2.0},
      {"wedge_count", 2.0},       {"wedge_sph_count", 3.0},  {"cpow_power", 3.0},        {"curl_c2", 0.2},
      {"super_shape_m", 4.0},     {"super_shape_n1", 2.0},   {"radial_blur_angle", 0.5}, {"pie_slices", 6.0},
      {"ngon_sides", 5.0},        {"cell_size", 0.6},        {"rectangles_x", 0.4},      {"rectangles_y", 0.7},
      {"conic_eccentricity", 0.7}};
  if (const auto it = chosen.find(attribute); it != chosen.end()) return it->second;
  return fallback != 0.0 ? fallback : 0.35 + 0.1 * double(k);
}

/// One function per variation of the table, in table order: an affine grid (so the dependent
/// variations read coefficients that are not 0), the variation at weight 0.8 (pre_blur with linear
/// at 1, since alone it adds nothing) and a post map.
Project everyVariationProject() {
  Project project;
  const auto& table = flameVariations();
  for (const FlameVariation& v : table) {
    Function f;
    f.name = v.name;
    f.resolution = {2, 2, 2};
    f.placement.translate = {0.3, -0.2, 0.1};
    f.placement.rotate = {0.0, 0.0, 20.0};
    f.placement.scale = {0.9, 1.1, 1.0};
    f.variations[v.name] = 0.8;
    if (v.pre) f.variations["linear"] = 1.0;
    for (std::size_t k = 0; k < v.params.size(); ++k)
      f.variation_params[v.params[k].first] = testParameter(v.params[k].first, v.params[k].second, k);
    PostTransform post;
    post.placement.rotate = {0.0, 10.0, 15.0};
    post.placement.translate = {0.1, 0.0, -0.05};
    f.post = post;
    project.functions.push_back(f);
  }
  return project;
}

bool finite3(const Point& p) {
  return std::all_of(p.begin(), p.end(), [](float v) { return std::isfinite(v) && std::fabs(v) < 1e6f; });
}

/// The Lévy distance test between two samples of one coordinate: for every t, F_a(t) ≤ F_b(t + δ) + ε
/// and the other way round, δ relative to |t|. Unlike a mean and variance it holds for heavy
/// tails (rays, arch) and for atoms that float moves slightly (julia's two roots).
double levyExcess(std::vector<float> a, std::vector<float> b, double delta) {
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  double worst = 0.0;
  auto cdf = [](const std::vector<float>& s, double t) {
    return double(std::upper_bound(s.begin(), s.end(), t) - s.begin()) / double(s.size());
  };
  for (int side = 0; side < 2; ++side) {
    const std::vector<float>& x = side ? b : a;
    const std::vector<float>& y = side ? a : b;
    for (float t : x) worst = std::max(worst, cdf(x, t) - cdf(y, t + delta * (1.0 + std::fabs(t))));
  }
  return worst;
}

struct GpuVariationMaps : ::testing::Test {
  static void SetUpTestSuite() {
    context = gpu::HeadlessGlContext::create();
    const auto start = std::chrono::steady_clock::now();
    compute = std::make_unique<gpu::ChaosCompute>(context->info(), gpu::ChaosOutput::Maps, false, false);
    // Drivers may compile at the first dispatch (llvmpipe does): one point through the program
    // that has every variation (Mesa's shader cache may hold it from an earlier run).
    compute->evaluateMaps(*compileIfs(everyVariationProject()), {0}, {Point{0.1f, 0.2f, 0.3f}}, 1);
    compileSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  static void TearDownTestSuite() {
    compute.reset();  // its GL objects need the context
    context.reset();
  }
  static inline std::unique_ptr<gpu::HeadlessGlContext> context;
  static inline std::unique_ptr<gpu::ChaosCompute> compute;
  static inline double compileSeconds = 0.0;
};

TEST_F(GpuVariationMaps, EveryDeterministicVariationMatchesTheCpuTable) {
  RecordProperty("variation_program_compile_seconds", std::to_string(compileSeconds));
  std::printf("variation program: compiled and linked in %.2f s\n", compileSeconds);
  const auto ifs = compileIfs(everyVariationProject());
  const auto& table = flameVariations();
  ASSERT_EQ(ifs->functions.size(), table.size());
  // Inside X and beyond it (the grid map extrapolates there).
  const std::vector<Point> inputs = {
      {0.31f, -0.45f, 0.2f}, {-0.7f, 0.15f, -0.35f}, {0.55f, 0.62f, 0.8f}, {-0.23f, -0.81f, 0.1f}, {1.6f, -1.3f, 0.4f}};
  std::vector<std::uint32_t> functions;
  std::vector<Point> points;
  for (std::uint32_t i = 0; i < table.size(); ++i)
    if (!table[i].random)
      for (const Point& p : inputs) functions.push_back(i), points.push_back(p);
  const std::vector<Point> gpu = compute->evaluateMaps(*ifs, functions, points, 7);
  ASSERT_EQ(gpu.size(), points.size());
  std::vector<int> compared(table.size(), 0);
  for (std::size_t n = 0; n < points.size(); ++n) {
    const CompiledFunction& f = ifs->functions[functions[n]];
    std::uint64_t unused = 1;
    const Point cpu = f.evaluateMap(points[n], unused);
    if (!finite3(cpu)) continue;  // a pole of the variation: nothing to compare
    ++compared[functions[n]];
    SCOPED_TRACE(std::string(table[functions[n]].name) + " at input " + std::to_string(n % inputs.size()));
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(gpu[n][d], cpu[d], 2e-4 * (1.0 + std::fabs(cpu[d])));
  }
  for (std::size_t i = 0; i < table.size(); ++i)
    if (!table[i].random) {
      EXPECT_GE(compared[i], 4) << table[i].name << " was compared at too few points";
    }
}

TEST_F(GpuVariationMaps, EveryRandomVariationDrawsTheCpuDistribution) {
  const auto ifs = compileIfs(everyVariationProject());
  const auto& table = flameVariations();
  constexpr std::size_t kDraws = 4096;
  const Point input{0.31f, -0.45f, 0.2f};
  std::vector<std::uint32_t> functions;
  for (std::uint32_t i = 0; i < table.size(); ++i)
    if (table[i].random) functions.insert(functions.end(), kDraws, i);
  ASSERT_GT(functions.size(), 0u);
  const std::vector<Point> gpu =
      compute->evaluateMaps(*ifs, functions, std::vector<Point>(functions.size(), input), 11);
  std::uint64_t stream = 12345;
  for (std::size_t start = 0; start < functions.size(); start += kDraws) {
    const std::uint32_t id = functions[start];
    SCOPED_TRACE(table[id].name);
    std::vector<float> g[3], c[3];
    for (std::size_t k = 0; k < kDraws; ++k) {
      const Point cpu = ifs->functions[id].evaluateMap(input, stream);
      const Point& q = gpu[start + k];
      for (int d = 0; d < 3; ++d) {
        if (finite3(cpu)) c[d].push_back(cpu[d]);
        if (finite3(q)) g[d].push_back(q[d]);
      }
    }
    ASSERT_GT(c[0].size(), kDraws / 2);
    EXPECT_NEAR(double(g[0].size()) / kDraws, double(c[0].size()) / kDraws, 0.02);
    for (int d = 0; d < 3; ++d) EXPECT_LE(levyExcess(g[d], c[d], 1e-3), 0.05) << "coordinate " << d;
  }
}

/// Three functions with a random (julia), a dependent (popcorn) and a parametric random (julian)
/// variation, spherical with pre_blur, and post maps, in the loop and in the final function: the
/// flame vocabulary on affine grids.
Project variationScene() {
  Project p;
  p.camera.distance = 3.2;
  p.camera.target = {-0.13, 0.19, -0.5};  // the middle of the attractor's box
  auto grid = [](Vec3 scale, Vec3 rotate, Vec3 translate, Vec3 color) {
    Function f;
    f.resolution = {2, 2, 2};
    f.placement.scale = scale;
    f.placement.rotate = rotate;
    f.placement.translate = translate;
    f.color = color;
    return f;
  };
  Function a = grid({0.5, 0.5, 0.5}, {0, 0, 0}, {-0.3, 0.2, 0.1}, {1.0, 0.3, 0.2});
  a.variations = {{"linear", 0.6}, {"julia", 0.4}};
  Function b = grid({0.6, 0.6, 0.6}, {0, 0, 40}, {0.3, -0.1, -0.1}, {0.2, 0.8, 0.3});
  b.variations = {{"popcorn", 0.3}, {"julian", 0.7}};
  b.variation_params = {{"julian_power", 3.0}, {"julian_dist", 1.0}};
  Function c = grid({0.5, 0.5, 0.5}, {0, 0, 0}, {0.0, 0.4, -0.2}, {0.3, 0.4, 1.0});
  c.variations = {{"spherical", 0.4}, {"linear", 0.5}, {"pre_blur", 0.05}};
  PostTransform post;
  post.placement.rotate = {0.0, 20.0, 30.0};
  post.placement.scale = {0.9, 0.9, 0.9};
  post.placement.translate = {0.05, 0.0, 0.0};
  c.post = post;
  p.functions = {a, b, c};
  // A final function with a variation stage too (its own swirl and post map).
  Function last = grid({1.0, 1.0, 1.0}, {0, 0, 0}, {0, 0, 0}, {1.0, 1.0, 1.0});
  last.variations = {{"linear", 0.9}, {"swirl", 0.1}};
  last.post = PostTransform{};
  last.post->placement.rotate = {0.0, 0.0, 10.0};
  p.final_function = last;
  return p;
}

RenderImage renderGenomeGpu(gpu::GpuChaosRenderer& renderer, std::shared_ptr<const CompiledIfs> ifs,
                            const RenderJob& job) {
  renderer.restart(std::move(ifs), job);
  EXPECT_TRUE(renderer.waitUntilDone());
  RenderImage image;
  renderer.snapshot(image, DisplaySettings{});
  return image;
}

RenderJob sceneJob(const Project& p, std::uint64_t seed) {
  RenderJob job = RenderJob::fromProject(p, 2);
  job.width = 96;
  job.height = 72;
  job.samples = 2'000'000;
  job.seed = seed;
  return job;
}

TEST(GpuVariations, RenderMatchesTheCpuPicture) {
  const Project p = variationScene();
  const auto ifs = compileIfs(p);
  ASSERT_TRUE(ifs->hasVariations);
  const RenderJob job = sceneJob(p, 3);
  const RenderImage cpu = renderToCompletion(ifs, job, DisplaySettings{});
  gpu::GpuChaosRenderer renderer;
  const auto start = std::chrono::steady_clock::now();
  const RenderImage g = renderGenomeGpu(renderer, ifs, job);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(g.stats.samples, job.samples);
  EXPECT_TRUE(g.stats.done);
  // Most points land in the picture on both, and both replace bad points as often.
  EXPECT_GT(cpu.stats.plotted, job.samples / 2);
  EXPECT_NEAR(double(g.stats.plotted) / double(job.samples), double(cpu.stats.plotted) / double(job.samples), 0.02);
  EXPECT_NEAR(double(g.stats.badSamples) / double(job.samples), double(cpu.stats.badSamples) / double(job.samples),
              0.002);
  const double density = test::correlation(test::blockDensity(cpu), test::blockDensity(g));
  EXPECT_GE(density, 0.99);
  EXPECT_NEAR(double(g.hitPixels), double(cpu.hitPixels), 0.03 * double(cpu.hitPixels) + 8);
  RecordProperty("density_correlation", std::to_string(density));
  RecordProperty("gpu_seconds", std::to_string(seconds));
  std::printf("density correlation %.5f, hit pixels gpu %lld cpu %lld, gpu render %.2f s (with the first compile)\n",
              density, (long long)g.hitPixels, (long long)cpu.hitPixels, seconds);
}

TEST(GpuVariations, SameSeedSameBytesOtherSeedOtherImage) {
  const Project p = variationScene();
  const auto ifs = compileIfs(p);
  RenderJob job = sceneJob(p, 5);
  job.samples = 500'000;
  job.accumulateColor = true;
  gpu::GpuChaosRenderer one;
  gpu::GpuChaosRenderer::Options other;
  other.sliceSeconds = 0.0005;  // other slices: the image must not depend on them
  gpu::GpuChaosRenderer two(other);
  const RenderImage a = renderGenomeGpu(one, ifs, job);
  const RenderImage b = renderGenomeGpu(two, ifs, job);
  EXPECT_EQ(a.rgba, b.rgba);
  EXPECT_EQ(a.density, b.density);
  EXPECT_EQ(a.colorSums, b.colorSums);
  job.seed = 6;
  const RenderImage c = renderGenomeGpu(one, ifs, job);
  EXPECT_NE(a.density, c.density);
}

TEST(GpuVariations, DensityVolumeMatchesTheCpuVolume) {
  // The voxel-binning program with variations: the same measure over X as the CPU's binning.
  const Project p = variationScene();
  VolumeSettings settings;
  settings.resolution = 32;
  settings.samples = 1'000'000;
  VolumeJob cpuJob;
  cpuJob.settings = settings;
  cpuJob.threads = 2;
  const VolumeJob gpuJob = test::gpuVolumeJob(settings);
  const DensityVolume cpu = computeDensityVolume(p, cpuJob);
  const DensityVolume g = computeDensityVolume(p, gpuJob);
  ASSERT_EQ(g.density.size(), cpu.density.size());
  EXPECT_NEAR(g.totalMass / cpu.totalMass, 1.0, 0.03);               // the same share of points lands in X
  const double density = test::correlation(cpu.density, g.density);  // per voxel
  EXPECT_GE(density, 0.99);
  RecordProperty("volume_density_correlation", std::to_string(density));
}

}  // namespace
}  // namespace gridifs
