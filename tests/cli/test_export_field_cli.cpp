// gridifs export-field --image on real files: a field operation and the volume's field layers as
// colour-mapped pictures (Colonna, "Animation of fractal objects", figs. 2, 3 and 6), raw EXR
// values, layer sheets as meshes, and bad input.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <fstream>

#include "io/project_io.h"
#include "schema/field_layer.h"
#include "tests/cli/image_file_read.h"
#include "tests/cli/run_command.h"

namespace gridifs {
namespace {

using namespace test_support;
namespace fs = std::filesystem;

const char* kScene = R"({
  "format": "gridifs", "version": 1,
  "functions": [
    {"name": "a", "resolution": [3, 3, 3],
     "ops": [{"type": "field", "amplitude": [0.1, 0.1, 0.2], "octaves": 5, "seed": 3, "wind": [0.2, 0, 0]}]}],
  "volume": {"resolution": 32, "samples": 20000,
    "field": [
      {"role": "terrain", "height": -0.5, "strength": 0.6, "octaves": 5, "seed": 1},
      {"role": "cloud", "height": 0.5, "thickness": 0.3, "strength": 3, "octaves": 4, "seed": 7},
      {"strength": 0.5, "octaves": 4, "seed": 4,
       "shape": {"primitive": "sphere", "center": [0, 0, 0], "radius": 0.5}, "blend": 0.7}]}
})";

fs::path writeScene(const fs::path& folder) {
  const fs::path file = folder / "scene.gridifs";
  std::ofstream(file) << kScene;
  return file;
}

std::string exportField(const fs::path& project, const std::string& args) {
  return "export-field " + quote(project.string()) + " " + args;
}

}  // namespace

TEST(ExportFieldImage, AFieldOperationBecomesAColourMappedImage) {
  ScratchDir dir("field-image-op");
  const fs::path project = writeScene(dir.path);
  const fs::path png = dir.path / "field.png";
  const auto r = runGridifs(exportField(
      project, "--op 'functions[0].ops[0]' --image " + quote(png.string()) + " --size 40 --palette ember --time 0.5"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const ImageFile image = readImageFile(png);
  ASSERT_EQ(image.width, 40);
  ASSERT_EQ(image.height, 40);
  ASSERT_EQ(image.channels, 3);
  // The palette's whole range is used: its first colour at the lowest value, its last at the highest.
  float lo = 1.0f, hi = 0.0f;
  for (std::size_t i = 0; i < image.pixels.size(); i += 3) {
    lo = std::min(lo, image.pixels[i]);
    hi = std::max(hi, image.pixels[i]);
  }
  EXPECT_LT(lo, 0.5f);
  EXPECT_GT(hi, 0.9f);
  // Deterministic, and the time moves the field.
  const fs::path again = dir.path / "again.png", later = dir.path / "later.png";
  ASSERT_EQ(runGridifs(exportField(project, "--op 'functions[0].ops[0]' --image " + quote(again.string()) +
                                                " --size 40 --palette ember --time 0.5"))
                .exitCode,
            0);
  ASSERT_EQ(runGridifs(exportField(project, "--op 'functions[0].ops[0]' --image " + quote(later.string()) +
                                                " --size 40 --palette ember --time 2"))
                .exitCode,
            0);
  EXPECT_EQ(slurp(png), slurp(again));
  EXPECT_NE(slurp(png), slurp(later));
}

TEST(ExportFieldImage, ExrKeepsTheRawValuesOfEveryLayer) {
  ScratchDir dir("field-image-exr");
  const fs::path project = writeScene(dir.path);
  const fs::path exr = dir.path / "layers.exr";
  const auto r = runGridifs(exportField(project, "--op volume.field --image " + quote(exr.string()) + " --size 16"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const ImageFile image = readImageFile(exr);
  ASSERT_EQ(image.channels, 3);
  EXPECT_EQ(image.names, (std::vector<std::string>{"layer00_terrain", "layer01_cloud", "layer02_density"}));
  // Pixel (i, j) of the top row is y = 1 − 1/16: the layer's value there, as the core computes it.
  const Project p = parseProject(kScene);
  const std::vector<const VolumeDensityField*> layers = fieldLayers(*p.volume);
  for (int c = 0; c < 3; ++c)
    for (int i : {0, 7, 15}) {
      const Vec3 at{-1.0 + (2.0 * i + 1.0) / 16.0, 1.0 - 1.0 / 16.0, fieldLayerPlaneHeight(*layers[c])};
      EXPECT_NEAR(image.pixels[std::size_t(i) * 3 + std::size_t(c)], fieldLayerValue(*layers[c], at, 0.0), 1e-5);
    }
  // One layer: one channel.
  const fs::path one = dir.path / "one.exr";
  ASSERT_EQ(
      runGridifs(exportField(project, "--op 'volume.field[2]' --image " + quote(one.string()) + " --size 8")).exitCode,
      0);
  EXPECT_EQ(readImageFile(one).names, std::vector<std::string>{"Y"});
}

TEST(ExportFieldImage, LayersWriteAMeshAndAnImageTogether) {
  ScratchDir dir("field-image-both");
  const fs::path project = writeScene(dir.path);
  const fs::path ply = dir.path / "sheets.ply", png = dir.path / "scene.png";
  // Without --op: the volume's layers.
  const auto r = runGridifs(
      exportField(project, "-o " + quote(ply.string()) + " --ascii --size 9 --image " + quote(png.string())));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string mesh = slurp(ply);
  EXPECT_NE(mesh.find("element vertex 243"), std::string::npos);  // three sheets of 9×9
  EXPECT_NE(mesh.find("element face 192"), std::string::npos);
  EXPECT_EQ(readImageFile(png).width, 9);
}

TEST(ExportFieldImage, BadInputExitsTwoAndWritesNothing) {
  ScratchDir dir("field-image-bad");
  const fs::path project = writeScene(dir.path);
  const fs::path out = dir.path / "x.png";
  for (const std::string& args :
       {std::string("--image ") + quote(out.string()) + " --palette nosuchpalette",
        std::string("--image ") + quote((dir.path / "x.bmpx").string()),
        std::string("--image ") + quote((dir.path / "missing" / "x.png").string()),
        std::string("--op 'volume.field[3]' --image ") + quote(out.string()),
        std::string("--op volume.fields --image ") + quote(out.string()),
        std::string("--image ") + quote(out.string()) + " --size 1", std::string("--size 8")}) {
    const auto r = runGridifs(exportField(project, args));
    EXPECT_EQ(r.exitCode, 2) << args << ": " << r.err;
    EXPECT_FALSE(r.err.empty()) << args;
    EXPECT_FALSE(fs::exists(out)) << args;
  }
  const fs::path bad = dir.path / "bad.gridifs";
  std::ofstream(bad) << R"({"format": "gridifs", "version": 1, "functions": [{"name": "a", "resolution": [2, 2, 2]}],
                          "volume": {"field": [{"role": "wind"}]}})";
  const auto r = runGridifs(exportField(bad, "--image " + quote(out.string())));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("volume.field[0].role"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace gridifs
