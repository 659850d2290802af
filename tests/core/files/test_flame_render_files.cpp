// The flame display written to files, read back with OpenImageIO: PNG 8/16-bit and EXR with
// alpha, the EXR's linear light against the PNG's sRGB, and the bad bit depths and formats.
#include <gtest/gtest.h>
#include <unistd.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <filesystem>

#include "render/compiled_ifs.h"
#include "render/flame_render.h"
#include "tests/core/flame_scenes.h"

using namespace gridifs;
using test_support::sierpinskiFlame;

TEST(FlameRenderFiles, DevelopsASupersampledSnapshotAndWritesImages) {
  Project p = sierpinskiFlame(48);
  p.render.flame.supersample = 2;
  const auto palette = std::make_shared<const Palette>(builtinPalette("ember"));
  const RenderJob job = flameRenderJob(p, palette, 1);
  EXPECT_EQ(job.width, (48 + 2 * flameGutter(p.render.flame)) * 2);
  // The widened view keeps the pixels per unit: the frame is the centre of the job.
  EXPECT_NEAR(flamePixelsPerUnit(job.camera, job.height / 2), flamePixelsPerUnit(p.camera, 48), 1e-9);
  const RenderImage snap = renderToCompletion(compileIfs(p), job, DisplaySettings::fromProject(p));
  const FlameImage image = developFlameSnapshot(snap, p.render.flame, p.camera, 48, 48, Vec3{0.0}, true, 2);
  ASSERT_EQ(image.width, 48);
  int covered = 0;
  for (std::size_t i = 3; i < image.rgba.size(); i += 4) covered += image.rgba[i] > 0.05f;
  EXPECT_GT(covered, 200);
  EXPECT_LT(covered, 48 * 48 * 3 / 4);  // the triangle's holes stay empty
  EXPECT_THROW(developFlameSnapshot(snap, p.render.flame, p.camera, 50, 48, Vec3{0.0}, true), std::invalid_argument);
  // The GUI's job without gutter develops to the same frame.
  const RenderJob noGutter = flameRenderJob(RenderJob::fromProject(p, 1), p.render.flame, palette, false);
  EXPECT_EQ(noGutter.width, 96);
  const RenderImage small = renderToCompletion(compileIfs(p), noGutter, DisplaySettings::fromProject(p));
  const FlameImage framed = developFlameSnapshot(small, p.render.flame, p.camera, 48, 48, Vec3{0.0}, true, 1);
  EXPECT_EQ(framed.width, 48);
  double sumGutter = 0, sumFramed = 0;
  for (std::size_t i = 3; i < image.rgba.size(); i += 4) sumGutter += image.rgba[i], sumFramed += framed.rgba[i];
  EXPECT_NEAR(sumFramed / sumGutter, 1.0, 0.05);  // the attractor is inside the frame: same picture
  std::vector<std::uint8_t> texture;
  flameImageToRgba8(image, texture);
  ASSERT_EQ(texture.size(), std::size_t(48 * 48 * 4));
  EXPECT_EQ(texture[3], std::uint8_t(std::lround(image.rgba[3] * 255.0f)));

  const auto folder = std::filesystem::temp_directory_path() / ("gridifs_flame_" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  struct Case {
    const char* name;
    int bits;
    bool alpha;
    OIIO::TypeDesc format;
    int channels;
  };
  for (const Case& c :
       {Case{"a.png", 8, false, OIIO::TypeDesc::UINT8, 3}, Case{"b.png", 16, true, OIIO::TypeDesc::UINT16, 4},
        Case{"c.exr", 32, true, OIIO::TypeDesc::FLOAT, 4}, Case{"d.exr", 16, true, OIIO::TypeDesc::HALF, 4}}) {
    const auto file = folder / c.name;
    writeFlameImage(image, file, c.bits, c.alpha);
    auto in = OIIO::ImageInput::open(file.string());
    ASSERT_TRUE(in) << c.name;
    const OIIO::ImageSpec& spec = in->spec();
    EXPECT_EQ(spec.width, 48);
    EXPECT_EQ(spec.nchannels, c.channels) << c.name;
    EXPECT_EQ(spec.format, c.format) << c.name;
    in->close();
  }
  // EXR holds linear light: its straight color is the PNG's sRGB-decoded color.
  auto readFloats = [](const std::filesystem::path& f) {
    auto in = OIIO::ImageInput::open(f.string());
    std::vector<float> px(std::size_t(in->spec().width) * in->spec().height * 4);
    in->read_image(0, 0, 0, 4, OIIO::TypeDesc::FLOAT, px.data());
    return px;
  };
  const auto png = readFloats(folder / "b.png"), exr = readFloats(folder / "c.exr");
  int compared = 0;
  for (std::size_t i = 0; i < png.size(); i += 4) {
    if (png[i + 3] < 0.5f) continue;
    ++compared;
    EXPECT_NEAR(exr[i + 3], png[i + 3], 1e-4);
    for (int c = 0; c < 3; ++c) {
      const double s = png[i + c];  // OIIO premultiplies the (unassociated) PNG on reading
      const double straight = s / png[i + 3];
      const double linear = straight <= 0.04045 ? straight / 12.92 : std::pow((straight + 0.055) / 1.055, 2.4);
      EXPECT_NEAR(exr[i + c] / exr[i + 3], linear, 2e-3);
    }
  }
  EXPECT_GT(compared, 50);
  EXPECT_THROW(writeFlameImage(image, folder / "x.jpg", 8, false), IoError);
  EXPECT_THROW(writeFlameImage(image, folder / "x.png", 12, false), IoError);
  EXPECT_THROW(writeFlameImage(image, "/nonexistent-folder/x.png", 8, false), IoError);
  std::filesystem::remove_all(folder);
}
