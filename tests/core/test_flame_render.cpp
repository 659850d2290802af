// The flame display over the chaos game: per-sample palette colors in the renderer's
// sums, exposure from the camera, developing a snapshot, writing PNG 8/16-bit and EXR with alpha.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <filesystem>

#include "render/compiled_ifs.h"
#include "render/flame_render.h"

using namespace gridifs;

namespace {
/// The Sierpinski triangle in the z = 0 plane, seen from straight above with an ortho camera.
Project sierpinskiFlame(int size) {
  Project p;
  p.functions.clear();
  const Vec3 corners[3] = {{-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0.0, 0.5, 0}};
  for (int i = 0; i < 3; ++i) {
    Function f;
    f.name = "f" + std::to_string(i + 1);
    f.resolution = {2, 2, 2};
    f.placement.scale = {0.5, 0.5, 0.0};
    f.placement.translate = corners[i] * 0.5 + Vec3{0.0, 0.0, 0.0};
    f.palette_index = i / 2.0;
    p.functions.push_back(f);
  }
  p.camera.pitch = 90.0;
  p.camera.yaw = -90.0;
  p.camera.projection = CameraProjection::Orthographic;
  p.camera.distance = 2.0;
  p.camera.fov = 45.0;
  p.render.width = p.render.height = size;
  p.render.samples = 200000;
  p.render.mode = DisplayMode::Flame;
  return p;
}
}  // namespace

TEST(FlameRender, PixelsPerUnitFollowTheOrbitCamera) {
  Camera c;
  c.distance = 4.0;
  c.fov = 35.0;
  EXPECT_NEAR(flamePixelsPerUnit(c, 768), 768.0 / (2.0 * 4.0 * std::tan(17.5 * M_PI / 180.0)), 1e-9);
}

TEST(FlameRender, RendererSumsThePaletteColorOfEverySample) {
  const Project p = sierpinskiFlame(64);
  auto palette = std::make_shared<Palette>();
  for (int i = 0; i < 256; ++i) palette->colors[i] = {0.2f, 0.4f, i < 128 ? 0.6f : 1.0f};
  const RenderJob job = flameRenderJob(p, palette, 2);
  EXPECT_TRUE(job.accumulateColor);
  const int g = flameGutter(p.render.flame), side = 64 + 2 * g;  // the job covers a gutter too
  ASSERT_EQ(job.width, side);
  const RenderImage snap = renderToCompletion(compileIfs(p), job, DisplaySettings::fromProject(p));
  ASSERT_EQ(snap.colorSums.size(), std::size_t(side * side * 4));
  std::int64_t hits = 0;
  for (std::size_t i = 0; i < std::size_t(side * side); ++i) {
    const double n = snap.density[i];
    hits += snap.density[i];
    EXPECT_NEAR(snap.colorSums[i * 4 + 0], 0.2 * n, 1e-3 * n + 1e-4);
    EXPECT_NEAR(snap.colorSums[i * 4 + 1], 0.4 * n, 1e-3 * n + 1e-4);
    EXPECT_GE(snap.colorSums[i * 4 + 2], 0.6 * n - 1e-3 * n - 1e-4);
    EXPECT_LE(snap.colorSums[i * 4 + 2], 1.0 * n + 1e-3 * n + 1e-4);
  }
  EXPECT_GT(hits, 100000);
  // Structural coloring: the bottom-left corner (function 0, c → 0) takes the palette's first
  // half, the top corner (function 2, c → 1) its second half.
  auto meanBlue = [&](int x, int y) {
    double b = 0, n = 0;
    for (int j = y - 2 + g; j <= y + 2 + g; ++j)
      for (int i = x - 2 + g; i <= x + 2 + g; ++i) {
        b += snap.colorSums[(std::size_t(j) * side + i) * 4 + 2];
        n += snap.density[std::size_t(j) * side + i];
      }
    return n > 0 ? b / n : -1.0;
  };
  EXPECT_NEAR(meanBlue(20, 44), 0.6, 0.1);  // y down: bottom-left
  EXPECT_NEAR(meanBlue(32, 20), 1.0, 0.1);  // top
}

TEST(FlameRender, DevelopsASupersampledSnapshotAndWritesImages) {
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
