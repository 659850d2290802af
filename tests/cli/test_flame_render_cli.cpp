// `gridifs render --mode flame`: PNG 8/16-bit, EXR float/half with alpha, the project's
// render.mode, determinism, and clear errors for bad flame options.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <filesystem>

#include "run_command.h"
#include "tests/cli/example_projects.h"

using namespace gridifs::test_support;

namespace {

const std::string kSierpinski2dFlame = std::string(GRIDIFS_TEST_DATA) + "/flame/sierpinski2d.gridifs";  // mode flame

struct Info {
  int width = 0, channels = 0;
  OIIO::TypeDesc format;
  double maxValue = 0.0;
};

Info inspect(const std::filesystem::path& file) {
  Info info;
  auto in = OIIO::ImageInput::open(file.string());
  if (!in) return info;
  info.width = in->spec().width;
  info.channels = in->spec().nchannels;
  info.format = in->spec().format;
  std::vector<float> px(std::size_t(in->spec().width) * in->spec().height * info.channels);
  in->read_image(0, 0, 0, info.channels, OIIO::TypeDesc::FLOAT, px.data());
  for (float v : px) info.maxValue = std::max(info.maxValue, double(v));
  in->close();
  return info;
}

std::string smallRenderArgs(const std::string& project, const std::filesystem::path& out, const std::string& extra) {
  return "render " + quote(project) + " -o " + quote(out.string()) +
         " --width 96 --height 72 --samples 300000 --threads 2 -q " + extra;
}

}  // namespace

TEST(FlameRenderCli, WritesPng8And16AndExrWithAlpha) {
  const ScratchDir dir("flame-cli");
  struct Case {
    const char* name;
    const char* options;
    int channels;
    OIIO::TypeDesc format;
  };
  for (const Case& c : {Case{"a.png", "--mode flame", 3, OIIO::TypeDesc::UINT8},
                        Case{"b.png", "--mode flame --bit-depth 16 --transparent", 4, OIIO::TypeDesc::UINT16},
                        Case{"c.tif", "--mode flame --bit-depth 16", 3, OIIO::TypeDesc::UINT16},
                        Case{"d.exr", "--mode flame", 4, OIIO::TypeDesc::FLOAT},
                        Case{"e.exr", "--mode flame --bit-depth 16 --palette flam3:27", 4, OIIO::TypeDesc::HALF}}) {
    const auto out = dir.path / c.name;
    const CommandResult r = runGridifs(smallRenderArgs(kTwisted, out, c.options));
    ASSERT_EQ(r.exitCode, 0) << c.name << ": " << r.err;
    const Info info = inspect(out);
    EXPECT_EQ(info.width, 96) << c.name;
    EXPECT_EQ(info.channels, c.channels) << c.name;
    EXPECT_EQ(info.format, c.format) << c.name;
    EXPECT_GT(info.maxValue, 0.3) << c.name << " is (nearly) black";
  }
}

TEST(FlameRenderCli, FollowsTheProjectsModeAndIsDeterministic) {
  const ScratchDir dir("flame-cli-mode");
  const auto a = dir.path / "a.png", b = dir.path / "b.png", z = dir.path / "z.png";
  ASSERT_EQ(runGridifs(smallRenderArgs(kSierpinski2dFlame, a, "")).exitCode, 0);  // render.mode = flame in the file
  ASSERT_EQ(runGridifs(smallRenderArgs(kSierpinski2dFlame, b, "--mode flame")).exitCode, 0);
  ASSERT_EQ(runGridifs(smallRenderArgs(kSierpinski2dFlame, z, "--mode zbuffer")).exitCode, 0);
  EXPECT_EQ(slurp(a), slurp(b));  // same seed, samples and threads → the same bytes
  EXPECT_NE(slurp(a), slurp(z));
}

TEST(FlameRenderCli, BadFlameOptionsAreBadInputAndWriteNothing) {
  const ScratchDir dir("flame-cli-bad");
  const auto out = dir.path / "x.png";
  for (const std::string& options :
       {std::string("--mode density"), std::string("--mode flame --bit-depth 12"),
        std::string("--mode flame --palette no-such-palette"), std::string("--mode flame --palette flam3:999999"),
        std::string("--mode flame --palette file:/no/such.json"), std::string("--mode zbuffer --bit-depth 16")}) {
    const CommandResult r = runGridifs(smallRenderArgs(kTwisted, out, options));
    EXPECT_EQ(r.exitCode, 2) << options << ": " << r.err;
    EXPECT_FALSE(r.err.empty()) << options;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << options << ": one line expected: " << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << options;
  }
  const CommandResult exr = runGridifs(smallRenderArgs(kTwisted, dir.path / "x.exr", "--mode flame --bit-depth 8"));
  EXPECT_EQ(exr.exitCode, 2) << exr.err;
}
