// The panoramic projections and stereo eyes on the GPU (label `gpu`): points at known places land
// where the camera's formulas put them (render/camera.h), as they do on the CPU, and the GPU's
// image correlates with the CPU's.
#include <gtest/gtest.h>

#include <cmath>

#include "core/renderer_scenes.h"
#include "gpu/correlation.h"
#include "gpu/gpu_chaos_renderer.h"
#include "gpu_test_support.h"
#include "render/accumulation.h"
#include "render/compiled_ifs.h"

namespace gridifs {
namespace {

struct CameraCase {
  const char* name;
  CameraProjection projection;
  double fov;
  std::optional<StereoSettings> stereo;
  int width, height;
};

/// The two layers (a red square in front at x = 0.5, a blue one behind at x = −0.5) seen from
/// (2.5, 0, 0): every pixel the front square's points project to is red.
void expectLayersWhereTheFormulasSay(const RenderImage& image, const OrbitCamera& camera, const char* device) {
  int checked = 0;
  for (int eye = 0; eye < camera.eyes(); ++eye)
    for (double y = -0.4; y <= 0.4; y += 0.013)
      for (double z = -0.4; z <= 0.4; z += 0.013) {
        const ProjectedPoint q = camera.project({0.5, y, z}, eye);
        ASSERT_TRUE(q.inFront);
        const EyeRegion r = camera.eyeRegion(eye);
        // Away from pixel edges, where float and double could disagree about the pixel.
        if (std::abs(q.x - std::round(q.x)) < 0.05 || std::abs(q.y - std::round(q.y)) < 0.05) continue;
        ASSERT_GE(q.x, r.x);
        ASSERT_LT(q.x, r.x + r.width);
        const std::size_t i = std::size_t(q.y) * std::size_t(image.width) + std::size_t(q.x);
        EXPECT_EQ(image.rgba[i * 4 + 0], 255) << device << " eye " << eye << " at " << y << ", " << z;
        EXPECT_EQ(image.rgba[i * 4 + 2], 0) << device << " eye " << eye << " at " << y << ", " << z;
        // The nearest point the pixel saw: the square is seen at an angle, so a pixel's other
        // points may be up to a pixel's footprint nearer.
        EXPECT_NEAR(image.depth[i], q.depth, 0.02 * q.depth) << device;
        ++checked;
      }
  EXPECT_GT(checked, 100 * camera.eyes());
}

TEST(GpuCameras, PanoramicAndStereoPointsLandWhereTheFormulasSay) {
  const CameraCase cases[] = {
      {"fisheye 180", CameraProjection::Fisheye, 180.0, std::nullopt, 160, 160},
      {"fisheye 360", CameraProjection::Fisheye, 360.0, std::nullopt, 160, 160},
      {"equirectangular", CameraProjection::Equirectangular, 360.0, std::nullopt, 256, 128},
      {"equirectangular stereo", CameraProjection::Equirectangular, 360.0,
       StereoSettings{0.2, StereoLayout::TopBottom, 3.0}, 256, 256},
      {"fisheye stereo", CameraProjection::Fisheye, 200.0, StereoSettings{0.2, StereoLayout::SideBySide, 3.0}, 320,
       160},
      {"perspective stereo", CameraProjection::Perspective, 60.0, StereoSettings{0.3, StereoLayout::SideBySide, 3.0},
       320, 160},
  };
  gpu::GpuChaosRenderer gpu;
  for (const CameraCase& c : cases) {
    SCOPED_TRACE(c.name);
    Project p = test::twoLayers();
    p.camera.distance = 2.5;
    p.camera.projection = c.projection;
    p.camera.fov = c.fov;
    p.camera.stereo = c.stereo;
    p.render.width = c.width;
    p.render.height = c.height;
    p.render.samples = 3'000'000;
    const auto ifs = compileIfs(p);
    const RenderJob job = RenderJob::fromProject(p, 2);
    const DisplaySettings display = DisplaySettings::fromProject(p);
    const OrbitCamera camera(p.camera, c.width, c.height);
    const RenderImage cpu = renderToCompletion(ifs, job, display);
    gpu.restart(ifs, job);
    ASSERT_TRUE(gpu.waitUntilDone());
    RenderImage g;
    gpu.snapshot(g, display);
    expectLayersWhereTheFormulasSay(cpu, camera, "cpu");
    expectLayersWhereTheFormulasSay(g, camera, "gpu");
    EXPECT_NEAR(double(g.stats.plotted), double(cpu.stats.plotted), 0.02 * double(job.samples));
    EXPECT_GE(test::correlation(test::blockDensity(cpu), test::blockDensity(g)), 0.98);
  }
}

TEST(GpuCameras, LensBlurSpreadsAPointAsTheCpuDoes) {
  // The camera's lens blur (flam3's cam_dof) on the GPU: the same reach, the same uniform
  // distance (mean R/2, half the hits within R/2) as the CPU's (core's CameraProjections test).
  gpu::GpuChaosRenderer gpu;
  const Vec3 at(1.0, 0.1, -0.05);
  Project p = test::onePoint(at);
  p.camera.lens_blur = 3.0;
  const auto ifs = compileIfs(p);
  const RenderJob job = RenderJob::fromProject(p, 2);
  gpu.restart(ifs, job);
  ASSERT_TRUE(gpu.waitUntilDone());
  Accumulation a;
  gpu.accumulation(a);
  const OrbitCamera camera(p.camera, p.render.width, p.render.height);
  const ProjectedPoint centre = camera.project(glm::dvec3(at.x, at.y, at.z));
  const double reach = 0.1 * 3.0 * 1.0 * (p.render.height / 2.0) / (3.0 * std::tan(20.0 * M_PI / 180.0));
  test::expectUniformDistanceSpread(a.density, a.width, centre.x, centre.y, reach);
}

}  // namespace
}  // namespace gridifs
