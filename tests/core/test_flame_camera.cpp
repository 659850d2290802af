// flam3's 3D camera as a project camera (io/flame_camera.h): for random genome cameras, the
// project camera puts points of the flame's space (mirrored into X = (x, y, −z)) at the pixels the
// flame camera's own formula gives, c = M(pitch, yaw)·(p − (0, 0, zpos)), (c_x, c_y)/(1 −
// perspective·c_z), then R(rotate)·(· − centre)·pixels per unit about the image centre; and
// turning the project camera back gives the genome's camera.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "io/flame_camera.h"
#include "io/flame_genome.h"
#include "render/camera.h"

namespace gridifs {
namespace {

constexpr int kCameraWidth = 320, kCameraHeight = 240;

/// The flame camera's picture of `p` (flame space), pixels with y down.
glm::dvec2 flamePixel(const FlameCamera& f, const glm::dvec3& p) {
  const auto m = flameCameraRows(f.pitch, f.yaw);
  const glm::dvec3 v(p.x, p.y, p.z - f.zpos);
  double c[3];
  for (int i = 0; i < 3; ++i)
    c[i] = m[std::size_t(i)][0] * v.x + m[std::size_t(i)][1] * v.y + m[std::size_t(i)][2] * v.z;
  const double zr = 1.0 - f.perspective * c[2];
  const double x = c[0] / zr - f.centerX, y = c[1] / zr - f.centerY;
  const double t = f.rotate * M_PI / 180.0;
  return {0.5 * kCameraWidth + (std::cos(t) * x - std::sin(t) * y) * f.pixelsPerUnit,
          0.5 * kCameraHeight + (std::sin(t) * x + std::cos(t) * y) * f.pixelsPerUnit};
}

FlameCamera randomFlameCamera(std::mt19937& rng, bool perspective) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  FlameCamera f;
  f.centerX = 0.4 * unit(rng);
  f.centerY = 0.4 * unit(rng);
  f.pixelsPerUnit = 80.0 + 30.0 * unit(rng);
  f.rotate = 180.0 * unit(rng);
  f.pitch = 1.4 * unit(rng);
  f.yaw = 3.0 * unit(rng);
  f.perspective = perspective ? 0.2 + 0.1 * unit(rng) : 0.0;
  f.zpos = 0.5 * unit(rng);
  return f;
}

TEST(FlameCamera, TheProjectCameraDrawsWhatTheFlameCameraDraws) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 40; ++trial) {
    const FlameCamera f = randomFlameCamera(rng, trial % 2 == 0);
    const OrbitCamera camera(cameraFromFlame(f, kCameraHeight, 2.0), kCameraWidth, kCameraHeight);
    for (int i = 0; i < 20; ++i) {
      const glm::dvec3 p(unit(rng), unit(rng), 0.5 * unit(rng));
      const glm::dvec2 want = flamePixel(f, p);
      const ProjectedPoint got = camera.project({p.x, p.y, -p.z});
      ASSERT_TRUE(got.inFront);
      ASSERT_NEAR(got.x, want.x, 1e-7) << "trial " << trial;
      ASSERT_NEAR(got.y, want.y, 1e-7) << "trial " << trial;
    }
  }
}

TEST(FlameCamera, ALevelCameraAndOneLookingStraightAtThePlaneWork) {
  for (const double pitch : {0.0, 1e-14, M_PI / 2.0})
    for (const double perspective : {0.0, 0.3}) {
      FlameCamera f;
      f.pitch = pitch;
      f.yaw = 0.6;
      f.rotate = 15.0;
      f.perspective = perspective;
      f.centerX = 0.2;
      f.pixelsPerUnit = 90.0;
      const OrbitCamera camera(cameraFromFlame(f, kCameraHeight, 2.0), kCameraWidth, kCameraHeight);
      for (const glm::dvec3 p : {glm::dvec3(0.3, -0.2, 0.1), glm::dvec3(-0.5, 0.4, -0.2)}) {
        const glm::dvec2 want = flamePixel(f, p);
        const ProjectedPoint got = camera.project({p.x, p.y, -p.z});
        EXPECT_NEAR(got.x, want.x, 1e-7) << pitch << " " << perspective;
        EXPECT_NEAR(got.y, want.y, 1e-7) << pitch << " " << perspective;
      }
    }
}

TEST(FlameCamera, TurningTheProjectCameraBackGivesTheGenomesCamera) {
  std::mt19937 rng(8);
  for (int trial = 0; trial < 40; ++trial) {
    const FlameCamera f = randomFlameCamera(rng, trial % 2 == 0);
    const FlameCameraExport back = flameCameraFromProject(cameraFromFlame(f, kCameraHeight, 2.0), kCameraHeight);
    const FlameCamera& g = back.camera;
    // The same picture: every point lands where it did (the angles may be another triple for
    // the same turn, and an orthographic camera's pivot may slide along its axis).
    std::mt19937 points(trial);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < 10; ++i) {
      const glm::dvec3 p(unit(points), unit(points), 0.5 * unit(points));
      const glm::dvec3 moved(p.x + back.moveX, p.y + back.moveY, p.z);
      const glm::dvec2 a = flamePixel(f, p), b = flamePixel(g, moved);
      ASSERT_NEAR(a.x, b.x, 1e-7) << "trial " << trial;
      ASSERT_NEAR(a.y, b.y, 1e-7) << "trial " << trial;
    }
    // An imported camera's eye orbits the flame's z axis: nothing moves.
    EXPECT_NEAR(back.moveX, 0.0, 1e-12);
    EXPECT_NEAR(back.moveY, 0.0, 1e-12);
    EXPECT_NEAR(g.perspective, f.perspective, 1e-12);
    EXPECT_NEAR(g.pixelsPerUnit, f.pixelsPerUnit, 1e-9);
  }
}

TEST(FlameCamera, AnEyeOffTheAxisMovesTheGenomeAndPanoramicCamerasAreRefused) {
  Camera c;
  c.target = Vec3(0.3, -0.2, 0.1);
  const FlameCameraExport e = flameCameraFromProject(c, kCameraHeight);
  EXPECT_NEAR(e.moveX, -0.3, 1e-12);
  EXPECT_NEAR(e.moveY, 0.2, 1e-12);
  const OrbitCamera camera(c, kCameraWidth, kCameraHeight);
  const glm::dvec3 p(0.2, 0.5, -0.3);  // X
  const ProjectedPoint want = camera.project(p);
  const glm::dvec2 got = flamePixel(e.camera, {p.x + e.moveX, p.y + e.moveY, -p.z});
  EXPECT_NEAR(got.x, want.x, 1e-7);
  EXPECT_NEAR(got.y, want.y, 1e-7);
  c.projection = CameraProjection::Fisheye;
  EXPECT_THROW(flameCameraFromProject(c, kCameraHeight), FlameError);
  FlameCamera behind;
  behind.perspective = -0.2;
  EXPECT_THROW(cameraFromFlame(behind, kCameraHeight, 1.0), FlameError);
}

}  // namespace
}  // namespace gridifs
