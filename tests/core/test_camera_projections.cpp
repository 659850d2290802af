// The panoramic projections and stereo eyes of the camera (render/camera.h): pixel positions of
// points at known directions against the formulas of the file format's camera (equidistant
// fisheye, equirectangular longitude and latitude), the renderer's eight-at-a-time float
// projection against the camera's double one, rays through pixels as the inverse, the stereo
// parallax, and the refusals of unusable cameras.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <random>
#include <vector>

#include "core/flame_seed_checks.h"
#include "core/renderer_scenes.h"
#include "io/project_io.h"
#include "model/project.h"
#include "render/accumulation.h"
#include "render/camera.h"
#include "render/chaos_kernel.h"
#include "render/chaos_renderer.h"
#include "render/compiled_ifs.h"
#include "schema/validation.h"

namespace gridifs {
namespace {

constexpr double kDegree = M_PI / 180.0;

/// A camera at (4, 0, 0) looking at the origin: forward is −x, right is +y, up is +z.
Camera alongX(CameraProjection projection, double fov) {
  Camera c;
  c.yaw = 0.0;
  c.pitch = 0.0;
  c.distance = 4.0;
  c.fov = fov;
  c.projection = projection;
  return c;
}

/// The world point at `distance` from the eye of alongX in the direction `theta` from the view
/// axis with azimuth `phi` (from image right, counter-clockwise).
glm::dvec3 atAngles(double theta, double phi, double distance) {
  const glm::dvec3 eye(4.0, 0.0, 0.0), forward(-1.0, 0.0, 0.0), right(0.0, 1.0, 0.0), up(0.0, 0.0, 1.0);
  return eye + distance * (std::cos(theta) * forward + std::sin(theta) * (std::cos(phi) * right + std::sin(phi) * up));
}

TEST(CameraProjections, FisheyeIsEquidistantAsTheFormatSays) {
  for (double fov : {180.0, 220.0, 360.0}) {
    const int width = 900, height = 700;
    const OrbitCamera camera(alongX(CameraProjection::Fisheye, fov), width, height);
    for (double theta : {0.0, 10.0, 45.0, 89.0, 100.0})
      for (double phi : {0.0, 30.0, 90.0, 200.0, 315.0}) {
        if (theta > fov / 2) continue;
        const ProjectedPoint p = camera.project(atAngles(theta * kDegree, phi * kDegree, 2.5));
        // r = θ/(fov/2) · min(W, H)/2, image y down.
        const double r = theta / (fov / 2.0) * std::min(width, height) / 2.0;
        EXPECT_NEAR(p.x, width / 2.0 + r * std::cos(phi * kDegree), 1e-6) << fov << " " << theta << " " << phi;
        EXPECT_NEAR(p.y, height / 2.0 - r * std::sin(phi * kDegree), 1e-6) << fov << " " << theta << " " << phi;
        EXPECT_NEAR(p.depth, 2.5, 1e-9);
        EXPECT_TRUE(p.inFront);
      }
  }
  // A 180° dome master is the inscribed circle: a direction at 90° lands on its edge, and one
  // behind the eye is not drawn.
  const OrbitCamera dome(alongX(CameraProjection::Fisheye, 180.0), 800, 800);
  EXPECT_NEAR(dome.project(atAngles(90.0 * kDegree, 0.0, 1.0)).x, 800.0, 1e-6);
  EXPECT_FALSE(dome.project(atAngles(120.0 * kDegree, 0.0, 1.0)).inFront);
}

TEST(CameraProjections, EquirectangularMapsLongitudeAndLatitude) {
  const int width = 1200, height = 600;
  const double fov = 360.0, vfov = fov * height / width;
  const OrbitCamera camera(alongX(CameraProjection::Equirectangular, fov), width, height);
  const glm::dvec3 eye(4.0, 0.0, 0.0), forward(-1.0, 0.0, 0.0), right(0.0, 1.0, 0.0), up(0.0, 0.0, 1.0);
  for (double longitude : {-170.0, -90.0, 0.0, 33.0, 120.0, 179.0})
    for (double latitude : {-80.0, -20.0, 0.0, 45.0, 85.0}) {
      const double lambda = longitude * kDegree, beta = latitude * kDegree;
      const glm::dvec3 point = eye + 3.0 * (std::cos(beta) * std::sin(lambda) * right + std::sin(beta) * up +
                                            std::cos(beta) * std::cos(lambda) * forward);
      const ProjectedPoint p = camera.project(point);
      EXPECT_NEAR(p.x, width / 2.0 * (1.0 + longitude / (fov / 2.0)), 1e-6) << longitude << " " << latitude;
      EXPECT_NEAR(p.y, height / 2.0 * (1.0 - latitude / (vfov / 2.0)), 1e-6) << longitude << " " << latitude;
      EXPECT_NEAR(p.depth, 3.0, 1e-9);
    }
}

/// Cameras of every kind, mono and stereo, at an angle to the axes.
std::vector<Camera> cameras() {
  std::vector<Camera> out;
  for (CameraProjection projection : {CameraProjection::Perspective, CameraProjection::Orthographic,
                                      CameraProjection::Fisheye, CameraProjection::Equirectangular})
    for (int stereo = 0; stereo < 3; ++stereo) {
      if (stereo && projection == CameraProjection::Orthographic) continue;
      Camera c;
      c.yaw = 37.0;
      c.pitch = -24.0;
      c.distance = 3.0;
      c.target = Vec3(0.2, -0.1, 0.3);
      c.projection = projection;
      c.fov = projection == CameraProjection::Fisheye           ? 200.0
              : projection == CameraProjection::Equirectangular ? 240.0
                                                                : 50.0;
      if (stereo) c.stereo = StereoSettings{0.3, stereo == 1 ? StereoLayout::TopBottom : StereoLayout::SideBySide, 2.5};
      out.push_back(c);
      // Rolled; flat ones shifted too; one looking straight down.
      c.roll = 33.0;
      if (!c.panoramic()) {
        c.shift_x = 0.21;
        c.shift_y = -0.13;
      }
      out.push_back(c);
      c.pitch = 90.0;
      out.push_back(c);
    }
  // Fisheyes within a hemisphere (a 180° dome master, a 130° lens) take the renderer's shorter
  // path (half-angle tangents instead of an arctangent's octants).
  const std::size_t all = out.size();
  for (std::size_t i = 0; i < all; ++i)
    if (out[i].projection == CameraProjection::Fisheye)
      for (double fov : {180.0, 130.0}) {
        Camera c = out[i];
        c.fov = fov;
        out.push_back(c);
      }
  return out;
}

TEST(CameraProjections, RaysThroughPixelsInvertTheProjection) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const Camera& c : cameras()) {
    const OrbitCamera camera(c, 640, 480);
    int checked = 0;
    for (int i = 0; i < 400; ++i) {
      const double x = unit(rng) * 640, y = unit(rng) * 480, depth = 0.5 + 4.0 * unit(rng);
      const PixelRay ray = camera.rayThrough(x, y);
      if (!ray.valid) continue;
      const glm::dvec3 point = ray.origin + ray.step * depth;
      int eye = 0;
      if (camera.eyes() == 2 && x >= camera.eyeRegion(1).x && y >= camera.eyeRegion(1).y) eye = 1;
      const ProjectedPoint p = camera.project(point, eye);
      ASSERT_NEAR(p.x, x, 1e-6) << projectionName(c.projection) << " stereo " << bool(c.stereo);
      ASSERT_NEAR(p.y, y, 1e-6) << projectionName(c.projection) << " stereo " << bool(c.stereo);
      ASSERT_NEAR(p.depth, depth, 1e-6) << projectionName(c.projection);
      ++checked;
    }
    // A 200° fisheye's circle covers about half of a 4:3 frame (a third of a stereo eye's, less
    // for narrower ones); a side-by-side equirectangular eye taller than 180° has rays beyond the
    // poles.
    EXPECT_GT(checked, c.panoramic() ? 80 : 250) << projectionName(c.projection) << " " << c.fov;
  }
}

TEST(CameraProjections, TheRenderersFloatProjectionFollowsTheCamera) {
  // The plotter projects in float (sample k of every eight goes to eye k mod 2 in stereo); each
  // sample plotted alone, after k NaN samples, must land in the pixel of the double projection
  // (but where that lies within a thousandth of a pixel edge).
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  const int width = 320, height = 240;
  for (const Camera& c : cameras()) {
    const OrbitCamera camera(c, width, height);
    std::vector<kernel::PixelCell> cells(std::size_t(width) * height);
    kernel::ZBufferPlot<false> plot(kernel::makeHotCamera(camera), cells.data(), nullptr);
    int landed = 0, compared = 0;
    for (int i = 0; i < 1600; ++i) {
      const kernel::v4f q{unit(rng) * 1.5f, unit(rng) * 1.5f, unit(rng) * 1.5f, 0.0f};
      const int lane = i % 8, eye = camera.eyes() == 2 ? lane % 2 : 0;
      const ProjectedPoint p = camera.project(glm::dvec3(q[0], q[1], q[2]), eye);
      const EyeRegion r = camera.eyeRegion(eye);
      const bool expected = p.inFront && p.x >= r.x && p.x < r.x + r.width && p.y >= r.y && p.y < r.y + r.height;
      const double edge = std::min({std::abs(p.x - std::round(p.x)), std::abs(p.y - std::round(p.y))});
      if (edge < 1e-3) continue;
      ++compared;
      const std::size_t pixel = expected ? std::size_t(int(p.y)) * width + std::size_t(int(p.x)) : 0;
      const std::uint32_t before = cells[pixel].density;
      for (int k = 0; k < lane; ++k) plot(kernel::v4f{} + NAN, kernel::v4f{});
      plot(q, kernel::v4f{0.5f, 0.5f, 0.5f, 0.5f});
      plot.flush();
      ASSERT_EQ(plot.takePlotted(), expected ? 1 : 0)
          << projectionName(c.projection) << " stereo " << bool(c.stereo) << " lane " << lane;
      if (!expected) continue;
      ++landed;
      ASSERT_EQ(cells[pixel].density, before + 1) << projectionName(c.projection) << " stereo " << bool(c.stereo);
      const float depth = std::bit_cast<float>(std::uint32_t(cells[pixel].key >> 32));
      EXPECT_LE(depth, p.depth * (1.0 + 1e-4));
    }
    EXPECT_GT(landed, 200) << projectionName(c.projection);
    EXPECT_GT(compared, 1500);
  }
}

TEST(CameraProjections, SixteenLanesProjectExactlyAsEightDo) {
  // Where the CPU has AVX-512 the plotters project a panoramic camera's samples sixteen at a
  // time; every other CPU eight at a time. Both must give the same bits: the same pixel, the
  // same depth, the same verdict, for every kind of point (NaN, infinite, the eye itself,
  // straight behind it, far away).
#if GRIDIFS_SIXTEEN_LANES
  if (!__builtin_cpu_supports("x86-64-v4")) GTEST_SKIP() << "this CPU has no AVX-512 (x86-64-v4)";
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  constexpr int kCount = 256;
  for (const Camera& c : cameras()) {
    if (!c.panoramic()) continue;
    const OrbitCamera camera(c, 320, 240);
    const kernel::ProjectionLanes lanes = kernel::projectionLanes(kernel::makeHotCamera(camera));
    std::vector<kernel::v4f> points(kCount);
    for (kernel::v4f& p : points) p = kernel::v4f{unit(rng) * 2.5f, unit(rng) * 2.5f, unit(rng) * 2.5f, 0.0f};
    const glm::dvec3 eye = camera.eye(), forward = glm::normalize(glm::dvec3(c.target.x, c.target.y, c.target.z) - eye);
    const glm::dvec3 behind = eye - 2.0 * forward;
    points[3] = kernel::v4f{} + NAN;
    points[7] = kernel::v4f{INFINITY, 0.0f, 0.0f, 0.0f};
    points[11] = kernel::v4f{float(eye.x), float(eye.y), float(eye.z), 0.0f};
    points[12] = kernel::v4f{float(behind.x), float(behind.y), float(behind.z), 0.0f};
    points[13] = kernel::v4f{1e30f, -1e30f, 1e30f, 0.0f};
    std::vector<std::uint32_t> pixel8(kCount), pixel16(kCount);
    std::vector<float> depth8(kCount), depth16(kCount);
    std::vector<std::int32_t> inside8(kCount), inside16(kCount);
    kernel::eight_lanes::projectChunk(lanes, points.data(), kCount, pixel8.data(), depth8.data(), inside8.data());
    kernel::sixteen_lanes::projectChunk(lanes, points.data(), kCount, pixel16.data(), depth16.data(), inside16.data());
    int landed = 0;
    for (int i = 0; i < kCount; ++i) {
      ASSERT_EQ(inside8[i], inside16[i]) << projectionName(c.projection) << " stereo " << bool(c.stereo) << " " << i;
      ASSERT_EQ(pixel8[i], pixel16[i]) << projectionName(c.projection) << " " << i;
      ASSERT_EQ(std::bit_cast<std::uint32_t>(depth8[i]), std::bit_cast<std::uint32_t>(depth16[i]))
          << projectionName(c.projection) << " " << i;
      landed += inside8[i] != 0;
    }
    EXPECT_GT(landed, 60) << projectionName(c.projection) << " " << c.fov;
    EXPECT_EQ(inside8[3], 0);
    EXPECT_EQ(inside8[7], 0);
  }
#else
  GTEST_SKIP() << "built without the sixteen-lane projections (GCC's kernel clones only)";
#endif
}

TEST(CameraProjections, StereoEyesSeeParallaxThatVanishesAtTheConvergenceDistance) {
  for (CameraProjection projection :
       {CameraProjection::Perspective, CameraProjection::Fisheye, CameraProjection::Equirectangular}) {
    for (StereoLayout layout : {StereoLayout::TopBottom, StereoLayout::SideBySide}) {
      Camera c = alongX(projection, projection == CameraProjection::Perspective ? 60.0 : 180.0);
      c.stereo = StereoSettings{0.2, layout, 3.0};
      const OrbitCamera camera(c, 800, 800);
      const EyeRegion left = camera.eyeRegion(0), right = camera.eyeRegion(1);
      EXPECT_EQ(left.x, 0);
      EXPECT_EQ(left.y, 0);
      EXPECT_EQ(layout == StereoLayout::TopBottom ? right.y : right.x, 400);
      auto offsetIn = [&](const glm::dvec3& point, int eye) {
        const ProjectedPoint p = camera.project(point, eye);
        const EyeRegion r = camera.eyeRegion(eye);
        return p.x - r.x;
      };
      // Straight ahead: at the convergence distance both eyes agree; nearer, the left eye sees
      // the point further right (crossed parallax); farther, further left.
      const glm::dvec3 eye(4.0, 0.0, 0.0), forward(-1.0, 0.0, 0.0);
      EXPECT_NEAR(offsetIn(eye + 3.0 * forward, 0), offsetIn(eye + 3.0 * forward, 1), 1e-6);
      EXPECT_GT(offsetIn(eye + 1.0 * forward, 0), offsetIn(eye + 1.0 * forward, 1) + 5.0);
      EXPECT_LT(offsetIn(eye + 8.0 * forward, 0), offsetIn(eye + 8.0 * forward, 1) - 1.0);
    }
  }
}

Project withCamera(const std::string& cameraJson) {
  return parseProject(R"({"format": "gridifs", "version": 1, "camera": )" + cameraJson +
                      R"(, "functions": [{"resolution": [2, 2, 2], "ops": []}]})");
}

std::string refusal(const std::string& cameraJson) {
  try {
    withCamera(cameraJson);
  } catch (const ModelError& e) {
    return e.what();
  }
  return "";
}

TEST(CameraProjections, RollTurnsThePictureAndShiftSlidesIt) {
  // A point's pixel relative to the frame's centre: roll turns it clockwise by roll about the
  // centre (the camera turns counter-clockwise); a shift moves every pixel by −shift · height
  // (right and up are positive, image y goes down), for orthographic and perspective cameras.
  for (CameraProjection projection : {CameraProjection::Perspective, CameraProjection::Orthographic}) {
    Camera plain = alongX(projection, 50.0);
    Camera turned = plain, slid = plain;
    turned.roll = 30.0;
    slid.shift_x = 0.25;
    slid.shift_y = 0.1;
    const OrbitCamera a(plain, 400, 300), b(turned, 400, 300), c(slid, 400, 300);
    for (const glm::dvec3 point :
         {glm::dvec3(0.5, 0.7, 0.2), glm::dvec3(-1.0, -0.3, 0.6), glm::dvec3(0.0, 0.4, -0.5)}) {
      const ProjectedPoint p = a.project(point), q = b.project(point), s = c.project(point);
      const double dx = p.x - 200.0, dy = p.y - 150.0, t = 30.0 * kDegree;
      // Clockwise on the screen (y down) is counter-clockwise in (x, y-down) coordinates' sense of −t.
      EXPECT_NEAR(q.x - 200.0, std::cos(t) * dx - std::sin(t) * dy, 1e-9) << projectionName(projection);
      EXPECT_NEAR(q.y - 150.0, std::sin(t) * dx + std::cos(t) * dy, 1e-9) << projectionName(projection);
      EXPECT_NEAR(s.x, p.x - 0.25 * 300.0, 1e-9) << projectionName(projection);
      EXPECT_NEAR(s.y, p.y + 0.1 * 300.0, 1e-9) << projectionName(projection);
      EXPECT_NEAR(q.depth, p.depth, 1e-12);
      EXPECT_NEAR(s.depth, p.depth, 1e-12);
    }
  }
  // Straight down is exact, and yaw turns the picture there.
  Camera down = alongX(CameraProjection::Orthographic, 50.0);
  down.pitch = 90.0;
  down.yaw = 0.0;
  const OrbitCamera top(down, 300, 300);
  const ProjectedPoint east = top.project({0.0, 1.0, 0.0}), north = top.project({-1.0, 0.0, 0.0});
  EXPECT_NEAR(east.x - 150.0, 150.0 / 4.0 / std::tan(25.0 * kDegree), 1e-9);  // +y is to the right at yaw 0
  EXPECT_NEAR(east.y, 150.0, 1e-9);
  EXPECT_NEAR(north.y - 150.0, -(150.0 / 4.0 / std::tan(25.0 * kDegree)), 1e-9);
  EXPECT_NEAR(north.x, 150.0, 1e-9);
  EXPECT_NE(refusal(R"({"projection": "fisheye", "fov": 180, "shift_x": 0.1})").find("lens shift needs"),
            std::string::npos);
  const Project shifted = withCamera(R"({"roll": 12, "shift_x": 0.1, "shift_y": -0.2})");
  EXPECT_EQ(shifted.camera.roll, 12.0);
  EXPECT_EQ(parseProject(serializeProject(shifted)).camera, shifted.camera);
  // A camera without them saves without them.
  EXPECT_EQ(serializeProject(withCamera("{}")).find("roll"), std::string::npos);
}

TEST(CameraProjections, LensBlurSpreadsAPointAsFlam3sCamDofDoes) {
  // flam3's cam_dof (Apophysis 7X's 3D camera): a point at distance Δ from the plane the camera
  // keeps sharp moves across the picture, at a uniform angle, by a uniform distance up to
  // 0.1 · cam_dof · Δ. Seen at depth D by a camera of vertical field fov over H pixels, that reach
  // is R = 0.1 · cam_dof · Δ · (H/2) / (D · tan(fov/2)) pixels; a uniform distance gives a mean
  // distance of R/2 and half the hits within R/2 (a uniform point of the disc would give 2R/3 and
  // a quarter).
  for (const bool flame : {false, true}) {
    for (const double delta : {1.0, -0.8}) {
      SCOPED_TRACE((flame ? "flame, delta " : "zbuffer, delta ") + std::to_string(delta));
      Project p = test::onePoint(Vec3(delta, 0.1, -0.05));  // the eye at x = 4: depth 4 − Δ
      p.camera.lens_blur = 3.0;
      p.render.mode = flame ? DisplayMode::Flame : DisplayMode::ZBuffer;
      RenderJob job = RenderJob::fromProject(p, 2);
      job.accumulateColor = flame;
      const Accumulation a = accumulateToCompletion(compileIfs(p), job);
      const OrbitCamera camera(p.camera, p.render.width, p.render.height);
      const ProjectedPoint centre = camera.project(glm::dvec3(delta, 0.1, -0.05));
      const double reach =
          0.1 * 3.0 * std::abs(delta) * (p.render.height / 2.0) / ((4.0 - delta) * std::tan(20.0 * kDegree));
      ASSERT_GT(reach, 10.0);
      test::expectUniformDistanceSpread(a.density, a.width, centre.x, centre.y, reach);
    }
  }
  // On the plane through the target nothing moves; without the blur nothing moves anywhere.
  for (const double blur : {1.5, 0.0}) {
    const Vec3 at = blur > 0.0 ? Vec3(0.0, 0.3, 0.2) : Vec3(1.0, 0.3, 0.2);
    Project p = test::onePoint(at);
    p.camera.lens_blur = blur;
    const Accumulation a = accumulateToCompletion(compileIfs(p), RenderJob::fromProject(p, 2));
    int lit = 0;
    for (std::uint32_t d : a.density) lit += d > 0;
    EXPECT_EQ(lit, 1) << blur;
  }
  // A free-form IFS (its own chaos loop) goes through the same lens: the blurred points cover
  // more pixels.
  {
    Project freeForm = loadProject(std::string(GRIDIFS_ASSETS) + "/freeform/fig5_4_fractal_gasket.gridifs");
    ASSERT_FALSE(freeForm.camera.panoramic());
    auto litPixels = [](const Project& p) {
      RenderJob job = RenderJob::fromProject(p, 2);
      job.samples = 300'000;
      int lit = 0;
      for (std::uint32_t d : accumulateToCompletion(compileIfs(p), job).density) lit += d > 0;
      return lit;
    };
    const int sharp = litPixels(freeForm);
    freeForm.camera.lens_blur = 2.0;
    EXPECT_GT(litPixels(freeForm), sharp * 11 / 10) << sharp;
  }
  // A function of the seed alone, for any thread count: the lens draws from its own stream,
  // seeded per chunk as the chains are.
  Project tetra = test::sierpinskiTetrahedron();
  tetra.camera.lens_blur = 2.0;
  test::expectAFunctionOfTheSeedForAnyThreadCount(tetra, 300'000);
  // The blur needs a flat picture plane; the file refuses it on a panoramic camera.
  Project dome = test::onePoint(Vec3(0.0));
  dome.camera.projection = CameraProjection::Fisheye;
  dome.camera.fov = 180.0;
  dome.camera.lens_blur = 0.5;
  try {
    validateProject(dome);
    ADD_FAILURE() << "a lens blur on a fisheye camera was accepted";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("a lens blur needs a perspective or orthographic camera"), std::string::npos)
        << e.what();
  }
}

TEST(CameraProjections, TheFileNamesProjectionsAndRefusesUnusableOnes) {
  EXPECT_EQ(withCamera(R"({"ortho": true})").camera.projection, CameraProjection::Orthographic);
  EXPECT_EQ(withCamera(R"({"ortho": false})").camera.projection, CameraProjection::Perspective);
  const Project dome = withCamera(R"({"projection": "fisheye", "fov": 360})");
  EXPECT_EQ(dome.camera.projection, CameraProjection::Fisheye);
  EXPECT_EQ(dome.camera.fov, 360.0);
  const Project vr = withCamera(
      R"({"projection": "equirectangular", "fov": 360, "stereo": {"eye_separation": 0.1, "layout": "side-by-side"}})");
  ASSERT_TRUE(vr.camera.stereo);
  EXPECT_EQ(vr.camera.stereo->layout, StereoLayout::SideBySide);
  EXPECT_EQ(parseProject(serializeProject(vr)).camera, vr.camera);
  EXPECT_EQ(parseProject(serializeProject(dome)).camera, dome.camera);

  EXPECT_NE(refusal(R"({"fov": 0})").find("camera.fov"), std::string::npos);
  EXPECT_NE(refusal(R"({"projection": "fisheye", "fov": 361})").find("camera.fov"), std::string::npos);
  EXPECT_NE(refusal(R"({"fov": 200})").find("at most 170"), std::string::npos);
  EXPECT_NE(refusal(R"({"projection": "cylinder"})")
                .find(R"(expected "perspective", "orthographic", "fisheye" or "equirectangular")"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"ortho": true, "stereo": {}})").find("orthographic camera has no stereo"), std::string::npos);
  EXPECT_NE(refusal(R"({"stereo": {"layout": "diagonal"}})").find("camera.stereo.layout"), std::string::npos);
  EXPECT_NE(refusal(R"({"stereo": {"eye_separation": -1}})").find("camera.stereo.eye_separation"), std::string::npos);
}

}  // namespace
}  // namespace gridifs
