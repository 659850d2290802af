// `gridifs render` with the flame controls: --quality, --hue, --density-display, --supersample,
// the filter and estimator options, --motion-fade, and the project fields behind them.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>

#include "io/project_io.h"
#include "run_command.h"
#include "tests/cli/example_projects.h"

using namespace gridifs;
using namespace gridifs::test_support;

namespace {

std::string renderArgs(const std::string& project, const std::filesystem::path& out, const std::string& extra) {
  return "render " + quote(project) + " -o " + quote(out.string()) + " --width 96 --height 72 --threads 2 -q " + extra;
}

/// `source` with `change` applied, saved as `name` in `dir`.
std::string variant(const std::string& source, const std::filesystem::path& dir, const std::string& name,
                    const std::function<void(Project&)>& change) {
  Project p = loadProject(source);
  change(p);
  const auto file = dir / name;
  saveProject(p, file);
  return file.string();
}

}  // namespace

TEST(FlameControlsCli, QualityIsSamplesPerPixelFromTheOptionOrTheProject) {
  const ScratchDir dir("flame-controls-quality");
  const auto q = dir.path / "q.png", s = dir.path / "s.png", p = dir.path / "p.png";
  ASSERT_EQ(runGridifs(renderArgs(kTwisted, q, "--mode flame --quality 20")).exitCode, 0);
  ASSERT_EQ(runGridifs(renderArgs(kTwisted, s, "--mode flame --samples 138240")).exitCode, 0);  // 20 × 96 × 72
  EXPECT_EQ(slurp(q), slurp(s));
  // The project's quality follows the size asked for on the command line.
  const std::string withQuality =
      variant(kTwisted, dir.path, "quality.gridifs", [](Project& x) { x.render.quality = 20; });
  ASSERT_EQ(runGridifs(renderArgs(withQuality, p, "--mode flame")).exitCode, 0);
  EXPECT_EQ(slurp(p), slurp(s));
  const CommandResult both = runGridifs(renderArgs(kTwisted, dir.path / "x.png", "--quality 20 --samples 1000"));
  EXPECT_EQ(both.exitCode, 2) << both.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path / "x.png"));
}

TEST(FlameControlsCli, HueDisplayFilterAndEstimatorOptionsChangeThePicture) {
  const ScratchDir dir("flame-controls-options");
  const auto base = dir.path / "base.png";
  ASSERT_EQ(runGridifs(renderArgs(kTwisted, base, "--mode flame --samples 300000")).exitCode, 0);
  const std::string plain = slurp(base);
  int n = 0;
  for (const std::string& options :
       {std::string("--hue 0.5"), std::string("--density-display linear"), std::string("--density-display binary"),
        std::string("--supersample 2"), std::string("--filter-radius 1.5"), std::string("--estimator-radius 0"),
        std::string("--estimator-radius 4 --estimator-minimum 1 --estimator-curve 0.8")}) {
    const auto out = dir.path / ("o" + std::to_string(n++) + ".png");
    const CommandResult r = runGridifs(renderArgs(kTwisted, out, "--mode flame --samples 300000 " + options));
    ASSERT_EQ(r.exitCode, 0) << options << ": " << r.err;
    EXPECT_NE(slurp(out), plain) << options << " changed nothing";
  }
  // The same settings in the project draw the same picture as the options.
  const std::string hued = variant(kTwisted, dir.path, "hue.gridifs", [](Project& x) {
    x.render.flame.hue = 0.5;
    x.render.flame.density_display = "linear";
  });
  const auto a = dir.path / "a.png", b = dir.path / "b.png";
  ASSERT_EQ(runGridifs(renderArgs(hued, a, "--mode flame --samples 300000")).exitCode, 0);
  ASSERT_EQ(
      runGridifs(renderArgs(kTwisted, b, "--mode flame --samples 300000 --hue 0.5 --density-display linear")).exitCode,
      0);
  EXPECT_EQ(slurp(a), slurp(b));
}

TEST(FlameControlsCli, BadValuesAreBadInputAndWriteNothing) {
  const ScratchDir dir("flame-controls-bad");
  const auto out = dir.path / "x.png";
  for (const std::string& options :
       {std::string("--mode flame --hue 2"), std::string("--mode flame --density-display cubic"),
        std::string("--mode flame --supersample 9"), std::string("--mode flame --estimator-curve 0"),
        std::string("--mode flame --filter-radius -1"), std::string("--mode zbuffer --hue 0.3"),
        std::string("--mode flame --quality 0"), std::string("--motion-blur 2 --motion-fade -1")}) {
    const CommandResult r = runGridifs(renderArgs(kTwisted, out, options + " --samples 1000"));
    EXPECT_EQ(r.exitCode, 2) << options << ": " << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << options << ": one line expected: " << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << options;
  }
}

TEST(FlameControlsCli, DirectionalMotionBlurFromTheOptionOrTheProject) {
  const ScratchDir dir("flame-controls-motion");
  const auto uniform = dir.path / "u.png", faded = dir.path / "f.png", project = dir.path / "p.png";
  const std::string common = "--mode flame --samples 400000 --time 1 --motion-blur 4 ";
  ASSERT_EQ(runGridifs(renderArgs(kAnimated, uniform, common + "--motion-fade 0")).exitCode, 0);
  const CommandResult r = runGridifs(renderArgs(kAnimated, faded, common + "--motion-fade 3"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(slurp(uniform), slurp(faded));
  // animation.motion_blur and motion_fade in the project do what the options do.
  const std::string blurred = variant(kAnimated, dir.path, "blurred.gridifs", [](Project& x) {
    AnimationSettings a = x.animation.value_or(AnimationSettings{});
    a.motion_blur = 4;
    a.motion_fade = 3.0;
    x.animation = a;
  });
  ASSERT_EQ(runGridifs(renderArgs(blurred, project, "--mode flame --samples 400000 --time 1")).exitCode, 0);
  EXPECT_EQ(slurp(project), slurp(faded));
}
