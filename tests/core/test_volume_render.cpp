// The volume ray march shared by `gridifs render --mode volume` and the Volume preview
// (render/volume_raymarch.h), "render.volume" and "view" in the project file, their named edits,
// and the preview mode a project opens in.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "edit/document.h"
#include "edit/project_edit.h"
#include "io/project_io.h"
#include "render/camera.h"
#include "render/volume_raymarch.h"
#include "schema/settings_tables.h"

namespace gridifs {
namespace {

/// A ball of density 1 (radius r around c) in an n³ volume.
VolumeSource ballSource(int n, const Vec3& c, double r) {
  VolumeSource s;
  s.n = n;
  s.density.assign(std::size_t(n) * n * n, 0.0f);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const Vec3 p(-1.0 + (2 * i + 1.0) / n, -1.0 + (2 * j + 1.0) / n, -1.0 + (2 * k + 1.0) / n);
        if (glm::length(p - c) <= r)
          s.density[std::size_t(i) + std::size_t(n) * (std::size_t(j) + std::size_t(n) * k)] = 1.0f;
      }
  return s;
}

Camera frontCamera() {
  Camera c;
  c.yaw = 0.0;  // looking from +x towards the origin
  c.pitch = 0.0;
  c.distance = 4.0;
  return c;
}

float alphaAt(const VolumeImage& image, int x, int y) {
  return image.rgba[4 * (std::size_t(y) * image.width + std::size_t(x)) + 3];
}

float redAt(const VolumeImage& image, int x, int y) {
  return image.rgba[4 * (std::size_t(y) * image.width + std::size_t(x))];
}

TEST(VolumeRaymarch, ABallIsOpaqueInTheMiddleAndEmptyAtTheCorners) {
  VolumeLook look;
  const VolumeImage image = renderVolumeImage(ballSource(32, Vec3(0.0), 0.5), look, frontCamera(), 64, 48, 2);
  ASSERT_EQ(image.rgba.size(), std::size_t(64 * 48 * 4));
  EXPECT_GT(alphaAt(image, 32, 24), 0.99f);
  EXPECT_EQ(alphaAt(image, 0, 0), 0.0f);
  EXPECT_EQ(alphaAt(image, 63, 47), 0.0f);
  EXPECT_EQ(image.depth[0], kEmptyVolumeDepth);
  // The ball's front is about 3.5 from the eye (distance 4, radius 0.5).
  EXPECT_NEAR(image.depth[24 * 64 + 32], 3.5, 0.15);
}

TEST(VolumeRaymarch, TheSideTowardsTheLightIsBrighterThanTheShadowedSide) {
  VolumeLook look;
  look.towardLight = Vec3(0.0, 1.0, 0.0);  // light from +y
  look.ambient = 0.05;
  const Camera camera = frontCamera();
  const VolumeImage image = renderVolumeImage(ballSource(48, Vec3(0.0), 0.6), look, camera, 96, 64, 2);
  const OrbitCamera cam(camera, 96, 64);
  const auto lit = cam.project(glm::dvec3(0.0, 0.45, 0.0)), dark = cam.project(glm::dvec3(0.0, -0.45, 0.0));
  EXPECT_GT(redAt(image, int(lit.x), int(lit.y)), 2.0f * redAt(image, int(dark.x), int(dark.y)) + 0.05f);
}

TEST(VolumeRaymarch, TheImageDoesNotDependOnTheThreadCountAndTheStagesAreTheWhole) {
  VolumeLook look;
  look.settings.transfer = {{0.0, Vec3(0.2, 0.4, 1.0), 0.0}, {1.0, Vec3(1.0, 0.5, 0.1), 0.8}};
  const VolumeSource source = ballSource(32, Vec3(0.2, -0.1, 0.0), 0.5);
  const VolumeImage one = renderVolumeImage(source, look, frontCamera(), 50, 40, 1);
  const VolumeImage two = renderVolumeImage(source, look, frontCamera(), 50, 40, 2);
  EXPECT_EQ(one.rgba, two.rgba);
  EXPECT_EQ(one.depth, two.depth);
  const ShadedVolume shaded = shadeVolume(classifyVolume(source, look, 2), look, 2);
  const VolumeImage staged = marchVolume(shaded, look, frontCamera(), 50, 40, 2);
  EXPECT_EQ(staged.rgba, one.rgba);
}

TEST(VolumeRaymarch, XrayIsGreySummedDensityAndATransparentTransferShowsNothing) {
  VolumeLook look;
  look.settings.display = VolumeDisplay::Xray;
  look.settings.density_scale = 2.0;
  const VolumeImage x = renderVolumeImage(ballSource(32, Vec3(0.0), 0.5), look, frontCamera(), 40, 40, 2);
  double sum = 0.0;
  for (std::size_t p = 0; p < x.rgba.size() / 4; ++p) {
    EXPECT_NEAR(x.rgba[4 * p], x.rgba[4 * p + 3], 1e-5);  // grey: white weighted by the opacity
    EXPECT_NEAR(x.rgba[4 * p + 1], x.rgba[4 * p + 3], 1e-5);
    sum += x.rgba[4 * p + 3];
  }
  EXPECT_GT(sum, 10.0);
  // Summed density: the centre sees the longest path, 1 - exp(-σ·1) for a diameter of 1.
  EXPECT_NEAR(alphaAt(x, 20, 20), 1.0 - std::exp(-2.0), 0.05);
  EXPECT_GT(alphaAt(x, 20, 20), alphaAt(x, 26, 20));

  look.settings.transfer = {{0.0, Vec3(1.0), 0.0}, {1.0, Vec3(1.0), 0.0}};
  const VolumeImage none = renderVolumeImage(ballSource(32, Vec3(0.0), 0.5), look, frontCamera(), 40, 40, 2);
  EXPECT_EQ(*std::max_element(none.rgba.begin(), none.rgba.end()), 0.0f);
}

TEST(VolumeRenderIo, RoundTripsAndNamesTheJsonPathOfBadValues) {
  Project p = defaultNewProject();
  VolumeRenderSettings v;
  v.resolution = 96;
  v.density_scale = 12.5;
  v.display = VolumeDisplay::Xray;
  v.transfer = {{0.0, Vec3(0.0), 0.0}, {0.4, Vec3(0.9, 0.5, 0.1), 0.3}, {1.0, Vec3(1.0), 1.0}};
  p.render.volume = v;
  p.preview_mode = StoredPreviewMode::Volume;
  const std::string text = serializeProject(p);
  EXPECT_NE(text.find("\"preview_mode\": \"volume\""), std::string::npos);
  EXPECT_EQ(parseProject(text), p);

  const auto error = [&](const std::string& render) -> std::string {
    try {
      parseProject(R"({"format": "gridifs", "version": 1, "functions": [{"name": "f"}], )" + render + "}");
    } catch (const ModelError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(error(R"("render": {"volume": {"display": "glow"}})").find("render.volume.display"), std::string::npos);
  EXPECT_NE(error(R"("render": {"volume": {"resolution": 100000}})").find("render.volume.resolution"),
            std::string::npos);
  EXPECT_NE(error(R"("render": {"volume": {"transfer": [{"density": 0, "opacity": 2}]}})")
                .find("render.volume.transfer[0].opacity"),
            std::string::npos);
  EXPECT_NE(error(R"("render": {"volume": {"transfer": [{"density": 0.5}, {"density": 0.2}]}})")
                .find("render.volume.transfer[1].density"),
            std::string::npos);
  EXPECT_NE(error(R"("view": {"preview_mode": "hologram"})").find("view.preview_mode"), std::string::npos);
  EXPECT_EQ(error(R"("render": {"volume": {"density_scale": 3}}, "view": {"preview_mode": "mesh"})"), "");
}

TEST(VolumeRenderEdits, TransferFunctionDisplayAndScaleAreUndoSteps) {
  Document document(defaultNewProject());
  document.apply(SetTransferFunction{defaultTransferStops()});
  document.apply(SetVolumeDisplay{VolumeDisplay::Xray});
  // The slider names its undo step by the table's label.
  document.apply(SetParameter{"render.volume.density_scale", 5.0, volumeRenderTable().field("density_scale").label});
  ASSERT_TRUE(document.project().render.volume);
  EXPECT_EQ(document.project().render.volume->transfer.size(), 2u);
  EXPECT_EQ(document.project().render.volume->display, VolumeDisplay::Xray);
  EXPECT_EQ(document.undoLabel(), "Volume density scale");
  document.undo();
  document.undo();
  EXPECT_EQ(document.project().render.volume->display, VolumeDisplay::Lit);
  // Out of order: refused, the document unchanged.
  EXPECT_THROW(document.apply(SetTransferFunction{{{0.6, Vec3(1.0), 1.0}, {0.2, Vec3(1.0), 1.0}}}), ModelError);
  EXPECT_EQ(document.project().render.volume->transfer, defaultTransferStops());
  // The preview mode is recorded without an undo step.
  const std::string before = document.undoLabel();
  document.applyUnrecorded(SetPreviewMode{StoredPreviewMode::Mesh});
  EXPECT_EQ(document.project().preview_mode, StoredPreviewMode::Mesh);
  EXPECT_EQ(document.undoLabel(), before);
}

TEST(PreviewModeOnOpen, SetsOnlyOpenInVolumeAStoredModeWins) {
  const Project cloud = loadProject(std::filesystem::path(GRIDIFS_ASSETS) / "volumes" / "cloud_creature.gridifs");
  EXPECT_EQ(previewModeOnOpen(cloud), StoredPreviewMode::Volume);
  Project stored = cloud;
  stored.preview_mode = StoredPreviewMode::Mesh;
  EXPECT_EQ(previewModeOnOpen(stored), StoredPreviewMode::Mesh);
  Project grid = defaultNewProject();
  EXPECT_EQ(previewModeOnOpen(grid), StoredPreviewMode::ZBuffer);
  grid.render.mode = DisplayMode::Flame;
  EXPECT_EQ(previewModeOnOpen(grid), StoredPreviewMode::Flame);
}

}  // namespace
}  // namespace gridifs
