// The shaded display: surfaces from the z-buffer, lights, shadow maps filled by the chaos game,
// ambient occlusion, depth of field and determinism, on scenes of flat squares.
#include <gtest/gtest.h>

#include <cmath>

#include "render/camera.h"
#include "shading_scenes.h"

using namespace gridifs;
using namespace gridifs::test;

namespace {

std::size_t pixelOf(const OrbitCamera& camera, const Vec3& world) {
  const ProjectedPoint q = camera.project(world);
  return std::size_t(int(q.y)) * std::size_t(camera.width()) + std::size_t(int(q.x));
}

double mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return v.empty() ? 0.0 : s / double(v.size());
}

double spread(const std::vector<double>& v) {
  const double m = mean(v);
  double s = 0;
  for (double x : v) s += (x - m) * (x - m);
  return v.empty() ? 0.0 : std::sqrt(s / double(v.size()));
}

}  // namespace

TEST(ShadedImage, AFlatPlaneShadesUniformlyWithItsNormal) {
  Project p = shadedBase(160, 3'000'000);
  addSquare(p, Vec3{0, 0, 0}, 1.0, 2, Vec3{0.8, 0.8, 0.8});
  p.camera.yaw = 30;
  p.camera.pitch = 50;
  p.camera.distance = 4.5;
  p.render.shading.lights = {ShadingLight{Vec3{0.3, -0.5, 1.0}, Vec3{1.0}, 1.0, true}};
  p.render.shading.ao.strength = 0.8;  // a plane occludes nothing
  p.render.shading.specular = 0.0;
  const ShadedImage img = renderShaded(p, 2);
  const OrbitCamera cam(p.camera, p.render.width, p.render.height);
  std::vector<double> red, nz, ao;
  for (double x = -0.7; x <= 0.7; x += 0.05)
    for (double y = -0.7; y <= 0.7; y += 0.05) {
      const std::size_t i = pixelOf(cam, Vec3{x, y, 0});
      ASSERT_EQ(img.rgba[i * 4 + 3], 255);
      red.push_back(img.rgba[i * 4 + 0]);
      nz.push_back(img.normals[i * 3 + 2]);
      ao.push_back(img.occlusion[i]);
      EXPECT_NEAR(img.normals[i * 3 + 0], 0.0, 0.1);
      EXPECT_NEAR(img.normals[i * 3 + 1], 0.0, 0.1);
      EXPECT_GT(img.shadow[i], 0.99f) << "a plane does not shadow itself";
    }
  EXPECT_GT(mean(nz), 0.98);
  EXPECT_GT(mean(ao), 0.97);
  // Lambert with the plane's normal: 0.2 ambient + cos between +z and the light.
  const double cosine = 1.0 / std::sqrt(0.09 + 0.25 + 1.0);
  const double expected = 255.0 * std::pow(0.6038 * (0.2 + cosine), 1.0 / 2.4) * 1.055 - 0.055 * 255.0;
  EXPECT_NEAR(mean(red), expected, 6.0);
  EXPECT_LT(spread(red), 4.0);
}

TEST(ShadedImage, ASquareAboveALargerOneCastsAShadowOfItsSizeStraightBelow) {
  Project p = shadedBase(200, 4'000'000);
  addSquare(p, Vec3{0, 0, -0.5}, 1.0, 2, Vec3{0.9, 0.9, 0.9});
  addSquare(p, Vec3{0, 0, 0.5}, 0.4, 2, Vec3{0.9, 0.2, 0.2});
  p.camera.yaw = 0;
  p.camera.pitch = 45;
  p.camera.distance = 4.0;
  p.camera.projection = CameraProjection::Orthographic;
  p.camera.fov = 45;
  p.render.shading.lights = {ShadingLight{Vec3{0, 0, 1}, Vec3{1.0}, 1.0, true}};
  const ShadedImage img = renderShaded(p, 2);
  const OrbitCamera cam(p.camera, p.render.width, p.render.height);
  int inside = 0, outside = 0;
  for (double x = -0.9; x <= 0.9; x += 0.05)
    for (double y = -0.9; y <= 0.9; y += 0.05) {
      const double m = std::max(std::abs(x), std::abs(y));
      if (m > 0.32 && m < 0.48) continue;  // the penumbra of the filtered lookup
      const std::size_t i = pixelOf(cam, Vec3{x, y, -0.5});
      ASSERT_EQ(img.rgba[i * 4 + 3], 255);
      if (m <= 0.32) {
        EXPECT_LT(img.shadow[i], 0.2f) << "(" << x << ", " << y << ") should be in the shadow";
        ++inside;
      } else {
        EXPECT_GT(img.shadow[i], 0.8f) << "(" << x << ", " << y << ") should be lit";
        ++outside;
      }
    }
  EXPECT_GT(inside, 100);
  EXPECT_GT(outside, 500);
  // The upper square itself is lit.
  EXPECT_GT(img.shadow[pixelOf(cam, Vec3{0, 0, 0.5})], 0.9f);
  // Without shadows the same place is lit: the darkness came from the light's depth buffer.
  p.render.shading.lights[0].shadows = false;
  const ShadedImage unshadowed = renderShaded(p, 2);
  const std::size_t below = pixelOf(cam, Vec3{0.1, 0.1, -0.5});
  EXPECT_GT(int(unshadowed.rgba[below * 4]), int(img.rgba[below * 4]) + 60);
}

TEST(ShadedImage, OcclusionDarkensTheInsideCornerOfTwoPerpendicularPlanes) {
  Project p = shadedBase(200, 4'000'000);
  addSquare(p, Vec3{0, 0, -1}, 1.0, 2, Vec3{0.8, 0.8, 0.8});  // floor
  addSquare(p, Vec3{-1, 0, 0}, 1.0, 0, Vec3{0.8, 0.8, 0.8});  // wall
  p.camera.yaw = 10;
  p.camera.pitch = 35;
  p.camera.distance = 5.0;
  p.render.shading.lights.clear();
  p.render.shading.ambient = 1.0;
  p.render.shading.ao = AmbientOcclusionSettings{16.0, 1.0, 8};
  const ShadedImage img = renderShaded(p, 2);
  const OrbitCamera cam(p.camera, p.render.width, p.render.height);
  std::vector<double> corner, open, wallCorner;
  for (double y = -0.5; y <= 0.5; y += 0.05) {
    corner.push_back(img.occlusion[pixelOf(cam, Vec3{-0.96, y, -1})]);
    wallCorner.push_back(img.occlusion[pixelOf(cam, Vec3{-1, y, -0.96})]);
    open.push_back(img.occlusion[pixelOf(cam, Vec3{0.5, y, -1})]);
  }
  EXPECT_GT(mean(open), 0.95);
  EXPECT_LT(mean(corner), mean(open) - 0.15);
  EXPECT_LT(mean(wallCorner), mean(open) - 0.15);
  // The colour follows: ambient light only, so darker in the corner.
  EXPECT_LT(img.rgba[pixelOf(cam, Vec3{-0.96, 0, -1}) * 4], img.rgba[pixelOf(cam, Vec3{0.5, 0, -1}) * 4]);
}

TEST(ShadedImage, DepthOfFieldBlursOnlyWhatIsAwayFromTheFocus) {
  // Seen along -x: a small red square at depth 3.5 in front of a large blue one at depth 4.5.
  Project p = shadedBase(128, 3'000'000);
  addSquare(p, Vec3{0.5, 0, 0}, 0.25, 0, Vec3{1, 0, 0});
  addSquare(p, Vec3{-0.5, 0, 0}, 1.0, 0, Vec3{0, 0, 1}, 4.0);
  p.camera.yaw = 0;
  p.camera.pitch = 0;
  p.camera.distance = 4.0;
  p.camera.projection = CameraProjection::Orthographic;
  p.camera.fov = 35;
  p.render.shading.lights = {ShadingLight{Vec3{1, 0, 0}, Vec3{1.0}, 1.0, false}};
  const OrbitCamera cam(p.camera, p.render.width, p.render.height);
  const double pxPerUnit = p.render.height / (2.0 * 4.0 * std::tan(17.5 * M_PI / 180.0));
  // Pixels of each colour farther than 1.5 pixels outside its square's projection.
  auto strays = [&](const RenderImage& snap) {
    int red = 0, blue = 0;
    const ProjectedPoint c = cam.project(Vec3{0, 0, 0});
    for (int y = 0; y < snap.height; ++y)
      for (int x = 0; x < snap.width; ++x) {
        const std::uint8_t* px = &snap.rgba[(std::size_t(y) * std::size_t(snap.width) + std::size_t(x)) * 4];
        if (!px[3]) continue;
        const double m = std::max(std::abs(x + 0.5 - c.x), std::abs(y + 0.5 - c.y)) / pxPerUnit;
        if (px[0] > 128 && m > 0.25 + 1.5 / pxPerUnit) ++red;
        if (px[2] > 128 && m > 1.0 + 1.5 / pxPerUnit) ++blue;
      }
    return std::pair{red, blue};
  };
  RenderImage sharp, blurred;
  renderShaded(p, 2, &sharp);
  p.render.shading.dof = DepthOfFieldSettings{0.1, 3.5};  // radius 0.1 · 1 unit = 3.6 px at the back
  renderShaded(p, 2, &blurred);
  const auto [sharpRed, sharpBlue] = strays(sharp);
  const auto [blurRed, blurBlue] = strays(blurred);
  EXPECT_EQ(sharpRed, 0);
  EXPECT_EQ(sharpBlue, 0);
  EXPECT_EQ(blurRed, 0) << "the square in focus stays sharp";
  EXPECT_GT(blurBlue, 100) << "the square 1 unit behind the focus is blurred";
}

TEST(ShadedImage, TheShadedPipelineIsDeterministicForASeed) {
  Project p = shadedBase(96, 600'000);
  addSquare(p, Vec3{0, 0, -0.5}, 1.0, 2, Vec3{0.9, 0.9, 0.9});
  addSquare(p, Vec3{0, 0, 0.5}, 0.4, 2, Vec3{0.9, 0.2, 0.2});
  p.render.shading.lights = {ShadingLight{Vec3{0.3, -0.5, 1}, Vec3{1.0}, 1.0, true},
                             ShadingLight{Vec3{-1, 0.2, 0.5}, Vec3{0.5, 0.6, 1.0}, 0.5, true}};
  p.render.shading.ao.strength = 0.8;
  p.render.shading.specular = 0.3;
  p.render.shading.fog = FogSettings{Vec3{0.1, 0.1, 0.2}, 0.05};
  p.render.shading.dof = DepthOfFieldSettings{0.02, 4.0};
  const ShadedImage a = renderShaded(p, 2), b = renderShaded(p, 2);
  EXPECT_EQ(a.rgba, b.rgba);
  EXPECT_EQ(a.normals, b.normals);
  EXPECT_EQ(a.shadow, b.shadow);
  p.render.seed = 8;
  EXPECT_NE(renderShaded(p, 2).rgba, a.rgba);
}

TEST(ShadedImage, ChangingALightNeedsNoRerender) {
  Project p = shadedBase(96, 600'000);
  addSquare(p, Vec3{0, 0, 0}, 1.0, 2, Vec3{0.8, 0.8, 0.8});
  p.render.shading.lights[0].shadows = false;
  RenderImage snapshot;
  const ShadedImage before = renderShaded(p, 1, &snapshot);
  ShadingSettings brighter = p.render.shading;
  brighter.lights[0].intensity = 2.0;
  brighter.lights[0].direction = Vec3{0, 0, 1};
  ShadedImage after;
  developShaded(snapshot, brighter, p.camera, p.render.background, 1, after);
  const OrbitCamera cam(p.camera, p.render.width, p.render.height);
  const std::size_t i = pixelOf(cam, Vec3{0, 0, 0});
  EXPECT_GT(int(after.rgba[i * 4]), int(before.rgba[i * 4]) + 20);
}

TEST(ShadedImage, AttractorBoundsHoldTheSquares) {
  Project p = shadedBase(32, 1000);
  addSquare(p, Vec3{0, 0, -0.5}, 1.0, 2, Vec3{1.0});
  addSquare(p, Vec3{0, 0, 0.5}, 0.4, 2, Vec3{1.0});
  const BoundingSphere s = attractorBounds(*compileIfs(p));
  for (const Vec3 corner : {Vec3{1, 1, -0.5}, Vec3{-1, -1, -0.5}, Vec3{0.4, -0.4, 0.5}})
    EXPECT_LE(glm::length(corner - s.center), s.radius);
  EXPECT_LT(s.radius, 2.0);
  EXPECT_THROW(LightView(Vec3{0.0}, s, 256), ModelError);
}
