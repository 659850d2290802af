// flam3's 3D camera, natively: genomes with cam_pitch, cam_yaw, cam_perspective and cam_zpos (and a
// centre and rotation, which a perspective camera turns into a lens shift) are imported with their
// variations, random ones included, and rendered by `gridifs render --mode flame`. flam3-render
// reads no cam_* attribute, so its reference is the same genome drawn flat with a final xform that
// carries the camera's projection of the plane (tests/data/flame/camera/make_camera_genomes.py
// derives it). The judge is flam3's seed-to-seed agreement, as in the variation cross-checks.
// Exporting the imported project writes the camera back, and importing that restores it.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>
#include <vector>

#include "flam3_compare.h"
#include "run_command.h"

using namespace gridifs::test_support;

namespace {

const std::filesystem::path kCameraData = std::filesystem::path(GRIDIFS_TEST_DATA) / "flame" / "camera";

std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

double attribute(const std::string& xml, const std::string& name) {
  std::smatch m;
  if (!std::regex_search(xml, m, std::regex(" " + name + "=\"([^\"]+)\""))) return std::nan("");
  return std::stod(m[1].str());
}

void crossCheckCamera(const std::string& name, const std::string& variation) {
  if (!haveFlam3()) GTEST_SKIP() << "flam3-render (flam3-utils) is not installed";
  const ScratchDir dir("flam3-camera-" + name);
  const auto genome = kCameraData / (name + ".flame"), reference = kCameraData / (name + "_reference.flame");
  const auto project = dir.path / (name + ".gridifs");
  const CommandResult imported =
      runGridifs("import-flame " + quote(genome.string()) + " -o " + quote(project.string()));
  ASSERT_EQ(imported.exitCode, 0) << imported.err;
  // Natively: no grid sampling, nothing left out.
  EXPECT_EQ(imported.err.find("warning"), std::string::npos) << imported.err;
  const std::string saved = readText(project);
  EXPECT_NE(saved.find("\"variations\""), std::string::npos);
  EXPECT_NE(saved.find("\"" + variation + "\""), std::string::npos)
      << "the " << variation << " variation is kept by name";
  const Flam3Agreement agreement = agreementWithFlam3(reference, project, dir.path);
  ASSERT_TRUE(agreement.error.empty()) << agreement.error;
  const AlphaComparison &self = agreement.self, &cross = agreement.cross;
  ASSERT_GT(self.coveredF, 2000) << "the genome should cover the view";
  std::printf("[camera %s] flam3 vs flam3: %s\n[camera %s] flam3 vs gridifs: %s\n", name.c_str(),
              self.summary().c_str(), name.c_str(), cross.summary().c_str());
  EXPECT_GE(cross.corrAlpha, self.corrAlpha - 0.005);
  EXPECT_GE(cross.corrLuma, self.corrLuma - 0.005);
}

}  // namespace

TEST(Flam3Camera, JuliaUnderAPitchedPerspectiveCamera) { crossCheckCamera("julia", "julia"); }
TEST(Flam3Camera, BlurUnderAPitchedPerspectiveCamera) { crossCheckCamera("blur", "blur"); }
TEST(Flam3Camera, SphericalUnderAPitchedPerspectiveCamera) { crossCheckCamera("spherical", "spherical"); }
TEST(Flam3Camera, JuliaUnderATurnedOrthographicCamera) { crossCheckCamera("julia_orthographic", "julia"); }
// cam_dof: a level camera keeps the flame's plane at a constant distance from the plane it keeps
// sharp, so flam3's reference draws the blur with its own `blur` variation.
TEST(Flam3Camera, JuliaThroughABlurringLens) { crossCheckCamera("julia_dof", "julia"); }

// Import, export, import: the flame camera comes back (the same attributes, to rounding), and so
// does the project camera.
TEST(Flam3Camera, ExportWritesTheCameraBack) {
  for (const std::string name : {"julia", "julia_dof"}) {
    SCOPED_TRACE(name);
    const bool blurred = name == "julia_dof";
    const ScratchDir dir("flam3-camera-export-" + name);
    const auto genome = kCameraData / (name + ".flame");
    const auto first = dir.path / "first.gridifs", flame = dir.path / "again.flame",
               second = dir.path / "second.gridifs";
    ASSERT_EQ(runGridifs("import-flame " + quote(genome.string()) + " -o " + quote(first.string())).exitCode, 0);
    const CommandResult exported = runGridifs("export-flame " + quote(first.string()) + " -o " + quote(flame.string()));
    ASSERT_EQ(exported.exitCode, 0) << exported.err;
    EXPECT_EQ(exported.err.find("warning"), std::string::npos) << exported.err;
    const std::string original = readText(genome), written = readText(flame);
    // A level camera (cam_pitch 0) looks straight down the flame's z axis, where yaw and rotate
    // both turn the picture: the export writes the turn as rotate alone, so only the rest is
    // compared by attribute (the project camera below compares the whole view).
    const std::vector<std::string> names =
        blurred ? std::vector<std::string>{"cam_pitch", "cam_perspective", "cam_zpos", "scale", "cam_dof"}
                : std::vector<std::string>{"cam_pitch", "cam_yaw", "cam_perspective", "cam_zpos", "rotate", "scale"};
    for (const std::string& n : names)
      EXPECT_NEAR(attribute(written, n), attribute(original, n), 1e-9) << n << "\n" << written;
    if (!blurred) {
      // The centre is two numbers.
      std::smatch a, b;
      ASSERT_TRUE(std::regex_search(original, a, std::regex(" center=\"([^ ]+) ([^\"]+)\"")));
      ASSERT_TRUE(std::regex_search(written, b, std::regex(" center=\"([^ ]+) ([^\"]+)\"")));
      EXPECT_NEAR(std::stod(b[1].str()), std::stod(a[1].str()), 1e-9);
      EXPECT_NEAR(std::stod(b[2].str()), std::stod(a[2].str()), 1e-9);
    }
    ASSERT_EQ(runGridifs("import-flame " + quote(flame.string()) + " -o " + quote(second.string())).exitCode, 0);
    const std::string p1 = readText(first), p2 = readText(second);
    std::vector<std::string> keys = {"yaw", "pitch", "distance", "fov", "roll", "shift_x", "shift_y"};
    if (blurred) keys.push_back("lens_blur");
    for (const std::string& key : keys) {
      std::smatch m1, m2;
      const std::regex field("\"" + key + "\": ([-0-9.e+]+)");
      // Roll and shift are written only when set: absent from both, or alike in both.
      const bool in1 = std::regex_search(p1, m1, field), in2 = std::regex_search(p2, m2, field);
      ASSERT_EQ(in1, in2) << key;
      if (!in1) continue;
      EXPECT_NEAR(std::stod(m2[1].str()), std::stod(m1[1].str()), 1e-7) << key;
    }
  }
}
