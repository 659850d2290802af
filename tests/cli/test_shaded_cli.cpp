// gridifs render --mode shaded on real files: PNG and EXR with the compositing channels, the
// project's render.mode, determinism, and bad shading input (exit 2, one sentence with the path).
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "io/project_io.h"
#include "tests/cli/run_command.h"
#include "tests/core/shading_scenes.h"

namespace gridifs {
namespace {

using namespace test_support;
namespace fs = std::filesystem;

/// A small square above a larger one, lit from above; render.mode as given.
Project squares(DisplayMode mode) {
  Project p = test::shadedBase(96, 500'000);
  test::addSquare(p, Vec3{0, 0, -0.5}, 1.0, 2, Vec3{0.9, 0.9, 0.9});
  test::addSquare(p, Vec3{0, 0, 0.5}, 0.4, 2, Vec3{0.9, 0.3, 0.2});
  p.camera.pitch = 45;
  p.render.mode = mode;
  p.render.shading.ao.strength = 0.8;
  test::separateSquares(p);
  return p;
}

TEST(ShadedCli, ExrCarriesNormalsOcclusionAndShadowChannels) {
  ScratchDir dir("shaded-exr");
  const fs::path project = dir.path / "squares.gridifs";
  saveProject(squares(DisplayMode::ZBuffer), project);
  const fs::path exr = dir.path / "out.exr";
  const auto r =
      runGridifs("render " + quote(project.string()) + " -o " + quote(exr.string()) + " --mode shaded --threads 2 -q");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto in = OIIO::ImageInput::open(exr.string());
  ASSERT_TRUE(in);
  const OIIO::ImageSpec spec = in->spec();
  // EXR keeps channels sorted by name; find each one by its name.
  ASSERT_EQ(spec.nchannels, 13);
  auto channel = [&](const std::string& name) {
    const auto it = std::find(spec.channelnames.begin(), spec.channelnames.end(), name);
    EXPECT_NE(it, spec.channelnames.end()) << name;
    return std::size_t(it - spec.channelnames.begin());
  };
  const std::size_t a = channel("A"), nx = channel("N.x"), ny = channel("N.y"), nz = channel("N.z"), ao = channel("AO"),
                    shadow = channel("shadow");
  channel("Z");
  std::vector<float> px(std::size_t(spec.width) * std::size_t(spec.height) * 10);
  ASSERT_TRUE(in->read_image(0, 0, 0, 10, OIIO::TypeDesc::FLOAT, px.data()));
  int covered = 0, shadowed = 0;
  for (std::size_t i = 0; i < px.size() / 10; ++i) {
    const float* p = &px[i * 10];
    if (p[a] == 0.0f) continue;
    ++covered;
    const float n2 = p[nx] * p[nx] + p[ny] * p[ny] + p[nz] * p[nz];
    EXPECT_NEAR(n2, 1.0f, 1e-3f);
    EXPECT_GE(p[ao], 0.0f);
    EXPECT_LE(p[ao], 1.0f);
    shadowed += p[shadow] < 0.5f;
  }
  EXPECT_GT(covered, 1000);
  EXPECT_GT(shadowed, 50) << "the upper square shadows the lower one";
}

TEST(ShadedCli, TheProjectsModeIsUsedAndRendersAreDeterministic) {
  ScratchDir dir("shaded-png");
  const fs::path project = dir.path / "squares.gridifs";
  saveProject(squares(DisplayMode::Shaded), project);
  const fs::path a = dir.path / "a.png", b = dir.path / "b.png", z = dir.path / "z.png";
  ASSERT_EQ(runGridifs("render " + quote(project.string()) + " -o " + quote(a.string()) + " --threads 2 -q").exitCode,
            0);
  ASSERT_EQ(runGridifs("render " + quote(project.string()) + " -o " + quote(b.string()) + " --threads 2 -q").exitCode,
            0);
  ASSERT_EQ(
      runGridifs("render " + quote(project.string()) + " -o " + quote(z.string()) + " --threads 2 --mode zbuffer -q")
          .exitCode,
      0);
  EXPECT_EQ(test_support::slurp(a), test_support::slurp(b));
  EXPECT_NE(test_support::slurp(a), test_support::slurp(z));
}

TEST(ShadedCli, BadShadingIsRefusedWithTheJsonPath) {
  ScratchDir dir("shaded-bad");
  const std::string head = R"({"format": "gridifs", "version": 1, "render": {"mode": "shaded", "shading": )";
  const std::string tail = R"(}, "functions": [{"name": "f1"}]})";
  const std::string light = R"({"direction": [0, 0, 1]})";
  const std::pair<std::string, std::string> cases[] = {
      {"[" + light + "," + light + "," + light + "," + light + "]", "render.shading.lights"},
      {R"([{"direction": [0, 0, 0]}])", "render.shading.lights[0].direction"},
  };
  for (const auto& [lights, path] : cases) {
    const fs::path file = dir.path / "bad.gridifs";
    std::ofstream(file) << head << R"({"lights": )" << lights << "}" << tail;
    const fs::path out = dir.path / "out.png";
    const auto r = runGridifs("render " + quote(file.string()) + " -o " + quote(out.string()) + " -q");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find(path), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
  for (const auto& [shading, path] :
       {std::pair<std::string, std::string>{R"({"ao": {"radius": -3}})", "render.shading.ao.radius"},
        {R"({"ao": {"strength": -1}})", "render.shading.ao.strength"},
        {R"({"dof": {"aperture": 0.2}})", "render.shading.dof.focus"}}) {
    const fs::path file = dir.path / "bad2.gridifs";
    std::ofstream(file) << head << shading << tail;
    const auto r = runGridifs("render " + quote(file.string()) + " -o " + quote((dir.path / "o.png").string()) + " -q");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find(path), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one sentence: " << r.err;
  }
  const fs::path good = dir.path / "good.gridifs";
  saveProject(squares(DisplayMode::ZBuffer), good);
  const auto r =
      runGridifs("render " + quote(good.string()) + " -o " + quote((dir.path / "o.png").string()) + " --mode lit -q");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("shaded"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace gridifs
