// The camera from the command line: EXRs carry OpenEXR's worldToCamera and worldToNDC and a
// world-position pass P that agree with the image, panoramic and stereo frames render, and
// unusable cameras are refused with exit 2 and one sentence.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "io/project_io.h"
#include "tests/cli/image_file_read.h"
#include "tests/cli/run_command.h"
#include "tests/core/renderer_scenes.h"

namespace gridifs {
namespace {

using namespace test_support;
namespace fs = std::filesystem;

/// A 4×4 attribute of the EXR in Imath's row-vector order; empty when absent.
std::vector<float> matrixAttribute(const fs::path& file, const char* name) {
  auto in = OIIO::ImageInput::open(file.string());
  if (!in) return {};
  const OIIO::ParamValue* p = in->spec().find_attribute(name, OIIO::TypeMatrix44);
  if (!p) return {};
  const float* m = static_cast<const float*>(p->data());
  return std::vector<float>(m, m + 16);
}

/// p · M (a row vector times Imath's matrix), with the homogeneous divide.
std::array<double, 3> times(const std::vector<float>& m, const std::array<double, 3>& p, bool divide) {
  std::array<double, 4> r{};
  for (int c = 0; c < 4; ++c) r[c] = p[0] * m[c] + p[1] * m[4 + c] + p[2] * m[8 + c] + m[12 + c];
  const double w = divide ? r[3] : 1.0;
  return {r[0] / w, r[1] / w, r[2] / w};
}

std::size_t channelOf(const ImageFile& image, const std::string& name) {
  const auto it = std::find(image.names.begin(), image.names.end(), name);
  EXPECT_NE(it, image.names.end()) << name;
  return std::size_t(it - image.names.begin());
}

fs::path writeWithCamera(const ScratchDir& dir, const std::string& name, const nlohmann::json& camera) {
  nlohmann::json project = nlohmann::json::parse(serializeProject(test::sierpinskiTetrahedron()));
  for (const auto& [key, value] : camera.items()) project["camera"][key] = value;
  const fs::path file = dir.path / name;
  std::ofstream(file) << project.dump(2);
  return file;
}

TEST(CameraCli, ExrMatricesAndThePositionPassAgreeWithTheImage) {
  ScratchDir dir("camera-exr");
  for (const char* mode : {"zbuffer", "shaded"}) {
    SCOPED_TRACE(mode);
    const fs::path project = writeWithCamera(dir, "flat.gridifs", {{"yaw", 25}, {"pitch", 30}});
    const fs::path exr = dir.path / (std::string(mode) + ".exr");
    const auto r = runGridifs("render " + quote(project.string()) + " -o " + quote(exr.string()) +
                              " --width 120 --height 90 --samples 300000 --threads 2 --device cpu -q --mode " + mode);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::vector<float> toCamera = matrixAttribute(exr, "worldToCamera"),
                             toNdc = matrixAttribute(exr, "worldToNDC");
    ASSERT_EQ(toCamera.size(), 16u);
    ASSERT_EQ(toNdc.size(), 16u);
    const ImageFile image = readImageFile(exr);
    const std::size_t a = channelOf(image, "A"), z = channelOf(image, "Z"), px = channelOf(image, "P.x"),
                      py = channelOf(image, "P.y"), pz = channelOf(image, "P.z");
    int checked = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        const float* v = &image.pixels[(std::size_t(y) * image.width + x) * image.channels];
        if (v[a] <= 0.0f) continue;
        const std::array<double, 3> p{v[px], v[py], v[pz]};
        // P seen through worldToNDC is the pixel's centre; its camera-space z is the depth Z.
        const std::array<double, 3> ndc = times(toNdc, p, true);
        ASSERT_NEAR(ndc[0] * image.width, x + 0.5, 1e-3) << x << ", " << y;
        ASSERT_NEAR(ndc[1] * image.height, y + 0.5, 1e-3) << x << ", " << y;
        ASSERT_NEAR(times(toCamera, p, false)[2], v[z], 1e-4 * v[z]);
        ++checked;
      }
    EXPECT_GT(checked, 500);
  }
}

TEST(CameraCli, PanoramicExrsCarryTheCameraButNoProjectionMatrix) {
  ScratchDir dir("camera-dome");
  const fs::path project =
      writeWithCamera(dir, "dome.gridifs", {{"projection", "fisheye"}, {"fov", 180}, {"distance", 2.5}});
  const fs::path exr = dir.path / "dome.exr";
  const auto r = runGridifs("render " + quote(project.string()) + " -o " + quote(exr.string()) +
                            " --width 128 --height 128 --samples 300000 --threads 2 --device cpu -q");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::vector<float> toCamera = matrixAttribute(exr, "worldToCamera");
  ASSERT_EQ(toCamera.size(), 16u);
  EXPECT_TRUE(matrixAttribute(exr, "worldToNDC").empty()) << "a fisheye has no projection matrix";
  const ImageFile image = readImageFile(exr);
  const std::size_t a = channelOf(image, "A"), z = channelOf(image, "Z"), px = channelOf(image, "P.x");
  int checked = 0;
  for (std::size_t i = 0; i < std::size_t(image.width) * image.height; ++i) {
    const float* v = &image.pixels[i * image.channels];
    if (v[a] <= 0.0f) continue;
    // A panoramic depth is the distance from the eye: |P in camera space| = Z.
    const std::array<double, 3> c = times(toCamera, {v[px], v[px + 1], v[px + 2]}, false);
    ASSERT_NEAR(std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]), v[z], 1e-4 * v[z]);
    // Inside the dome's circle.
    const double dx = double(i % image.width) + 0.5 - 64.0, dy = double(i / image.width) + 0.5 - 64.0;
    EXPECT_LE(std::hypot(dx, dy), 64.0 + 0.75);
    ++checked;
  }
  EXPECT_GT(checked, 300);
}

/// The mean column of the lit pixels of rows [y0, y1).
double litCentroid(const ImageFile& image, int y0, int y1) {
  double sum = 0.0, count = 0.0;
  for (int y = y0; y < y1; ++y)
    for (int x = 0; x < image.width; ++x)
      if (image.pixels[(std::size_t(y) * image.width + x) * image.channels] > 0.02f) {
        sum += x;
        count += 1.0;
      }
  return count > 0 ? sum / count : -1.0;
}

TEST(CameraCli, StereoHalvesShowTheParallax) {
  ScratchDir dir("camera-stereo");
  // The tetrahedron 4.5 from the eye, the convergence at 12: nearer than the screen, so the left
  // eye (the top half) sees it further right than the right eye does.
  for (const char* projection : {"equirectangular", "perspective"}) {
    SCOPED_TRACE(projection);
    const bool panoramic = std::string(projection) == "equirectangular";
    const fs::path project =
        writeWithCamera(dir, "stereo.gridifs",
                        {{"projection", projection},
                         {"fov", panoramic ? 180 : 60},
                         {"stereo", {{"eye_separation", 0.5}, {"layout", "top-bottom"}, {"convergence", 12}}}});
    const fs::path png = dir.path / "stereo.png";
    const auto r = runGridifs("render " + quote(project.string()) + " -o " + quote(png.string()) +
                              " --width 200 --height 200 --samples 400000 --threads 2 --device cpu -q");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const ImageFile image = readImageFile(png);
    const double left = litCentroid(image, 0, 100), right = litCentroid(image, 100, 200);
    ASSERT_GT(left, 0.0);
    ASSERT_GT(right, 0.0);
    EXPECT_GT(left - right, 2.0) << "left " << left << " right " << right;
  }
}

/// A small .usda reader for the tests: the camera's vertical and horizontal apertures, focal
/// length and camera-to-world matrix (USD's row-vector order) at `frame`.
struct UsdCamera {
  double focal = 0, vertical = 0, horizontal = 0;
  double m[4][4] = {};
};

std::string sampledValue(const std::string& text, const std::string& attribute, double frame) {
  const std::size_t at = text.find(attribute);
  EXPECT_NE(at, std::string::npos) << attribute;
  if (at == std::string::npos) return "";
  const std::size_t lineEnd = text.find('\n', at);
  const std::string line = text.substr(at, lineEnd - at);
  if (line.find(".timeSamples") == std::string::npos) return line.substr(line.find('=') + 1);
  char key[32];
  std::snprintf(key, sizeof key, "\n        %g: ", frame);
  const std::size_t sample = text.find(key, at);
  EXPECT_NE(sample, std::string::npos) << attribute << " at " << frame;
  const std::size_t start = sample + std::strlen(key), end = text.find(",\n", start);
  return text.substr(start, end - start);
}

UsdCamera readUsdCamera(const fs::path& file, double frame) {
  const std::string text = slurp(file);
  UsdCamera c;
  c.focal = std::stod(sampledValue(text, "float focalLength", frame));
  c.vertical = std::stod(sampledValue(text, "float verticalAperture", frame));
  c.horizontal = std::stod(sampledValue(text, "float horizontalAperture", frame));
  std::string matrix = sampledValue(text, "matrix4d xformOp:transform", frame);
  for (char& ch : matrix)
    if (ch == '(' || ch == ')' || ch == ',') ch = ' ';
  std::istringstream in(matrix);
  for (auto& row : c.m)
    for (double& v : row) in >> v;
  EXPECT_TRUE(bool(in)) << matrix;
  return c;
}

/// Where the USD camera puts world point p in a width × height image (pixels, y down).
std::array<double, 2> usdPixel(const UsdCamera& c, const std::array<double, 3>& p, int width, int height) {
  // Camera-to-world is rotation R (rows 0-2) and translation t (row 3): p = q · R + t, so
  // q = (p − t) · Rᵀ for the orthonormal R.
  double d[3], q[3];
  for (int k = 0; k < 3; ++k) d[k] = p[k] - c.m[3][k];
  for (int r = 0; r < 3; ++r) q[r] = d[0] * c.m[r][0] + d[1] * c.m[r][1] + d[2] * c.m[r][2];
  // Looking down −z: the image plane at the focal length.
  const double x = c.focal * q[0] / -q[2], y = c.focal * q[1] / -q[2];
  return {(x / c.horizontal + 0.5) * width, (0.5 - y / c.vertical) * height};
}

TEST(CameraCli, ExportedUsdCameraPutsAPointWhereTheRenderDid) {
  ScratchDir dir("camera-usd");
  // One function that maps everything to one point: the attractor is that point. The camera turns
  // and rises over the frames.
  nlohmann::json project = nlohmann::json::parse(serializeProject(test::sierpinskiTetrahedron()));
  const std::array<double, 3> point{0.31, -0.22, 0.17};
  project["functions"] =
      nlohmann::json::array({{{"resolution", {2, 2, 2}},
                              {"ops", nlohmann::json::array()},
                              {"placement", {{"scale", {0, 0, 0}}, {"translate", {point[0], point[1], point[2]}}}}}});
  project["camera"] = {{"yaw", 10}, {"pitch", 15}, {"distance", 3}, {"target", {0, 0, 0}}, {"fov", 40}};
  project["render"]["depth_cue"] = 0;
  project["animation"] = {{"fps", 10}, {"start", 0}, {"end", 1}};
  project["tracks"] = {{"camera.yaw", {{{"t", 0}, {"v", 10}}, {{"t", 1}, {"v", 70}}}},
                       {"camera.pitch", {{{"t", 0}, {"v", 15}}, {{"t", 1}, {"v", -25}}}},
                       {"camera.fov", {{{"t", 0}, {"v", 40}}, {{"t", 1}, {"v", 25}}}}};
  const fs::path file = dir.path / "point.gridifs";
  std::ofstream(file) << project.dump(2);
  const fs::path usda = dir.path / "camera.usda", chan = dir.path / "camera.chan";
  auto r = runGridifs("export-camera " + quote(file.string()) + " -o " + quote(usda.string()) + " --frames 0:10");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  r = runGridifs("export-camera " + quote(file.string()) + " -o " + quote(chan.string()) + " --frames 0:10");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string lines = slurp(chan);
  EXPECT_EQ(std::count(lines.begin(), lines.end(), '\n'), 11) << "a line per frame";
  const int width = 160, height = 120;
  for (int frame : {0, 4, 10}) {
    SCOPED_TRACE(frame);
    const fs::path png = dir.path / "frame.png";
    r = runGridifs("render " + quote(file.string()) + " -o " + quote(png.string()) + " --width 160 --height 120" +
                   " --samples 20000 --threads 1 --device cpu -q --time " + std::to_string(frame / 10.0));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const ImageFile image = readImageFile(png);
    double sumX = 0, sumY = 0, lit = 0;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        if (image.pixels[(std::size_t(y) * width + x) * image.channels + 1] > 0.1f) {
          sumX += x + 0.5;
          sumY += y + 0.5;
          lit += 1;
        }
    ASSERT_GE(lit, 1.0);
    ASSERT_LE(lit, 2.0) << "one point";
    const std::array<double, 2> expected = usdPixel(readUsdCamera(usda, frame), point, width, height);
    EXPECT_NEAR(sumX / lit, expected[0], 1.0);
    EXPECT_NEAR(sumY / lit, expected[1], 1.0);
  }
}

TEST(CameraCli, UnusableCamerasAreRefusedWithOneSentence) {
  ScratchDir dir("camera-refusals");
  const struct {
    nlohmann::json camera;
    const char* says;
  } cases[] = {
      {{{"fov", 0}}, "camera.fov"},
      {{{"projection", "fisheye"}, {"fov", 361}}, "camera.fov"},
      {{{"fov", 200}}, "at most 170 degrees"},
      {{{"projection", "cylinder"}}, "camera.projection"},
      {{{"ortho", true}, {"stereo", {{"eye_separation", 0.1}}}}, "no stereo parallax"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.camera.dump());
    const fs::path project = writeWithCamera(dir, "bad.gridifs", c.camera);
    const fs::path png = dir.path / "bad.png";
    const auto r = runGridifs("render " + quote(project.string()) + " -o " + quote(png.string()) + " -q");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(png));
  }
}

}  // namespace
}  // namespace gridifs
