// 3D genomes as JWildfire, Fractorium and Apophysis 7X write them: the 3D affine parts and z
// variations against hand-written closed forms; the native import (variations kept, in
// X = (x, y, −z)) against the genome's own map and camera; the sampled import (--grids): exact
// affine grids in 3D and the flame camera (pitch, yaw, perspective, zpos, rotate) against
// GridIFS's orbit camera; and flam3's palette hue rotation.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "io/flame_export.h"
#include "io/flame_genome.h"
#include "io/flame_import.h"
#include "model/stack_evaluator.h"
#include "render/camera.h"
#include "render/compiled_ifs.h"
#include "tone/palette.h"
#include "tone/palette_gradient.h"

using namespace gridifs;

namespace {

const std::filesystem::path kData = std::filesystem::path(GRIDIFS_TEST_DATA) / "flame";

/// Where the flame renderer puts a point of its space, in pixels (x right, rows down), and its
/// camera depth: the camera of JWildfire's FlameRendererView written out independently.
struct FlamePixel {
  double x, y, depth;
};
FlamePixel genomePixel(const FlameGenome& g, FlamePoint p) {
  const double yaw = -g.camYaw, pitch = g.camPitch;
  const double z = p.z - g.camZpos;
  const double cx = std::cos(yaw) * p.x - std::sin(yaw) * p.y;
  const double cy = std::cos(pitch) * std::sin(yaw) * p.x + std::cos(pitch) * std::cos(yaw) * p.y - std::sin(pitch) * z;
  const double cz = std::sin(pitch) * std::sin(yaw) * p.x + std::sin(pitch) * std::cos(yaw) * p.y + std::cos(pitch) * z;
  const double zr = 1.0 - g.camPerspective * cz;
  const double qx = cx / zr - g.centerX, qy = cy / zr - g.centerY;
  const double t = g.rotate * M_PI / 180.0, ppu = g.pixelsPerUnit();
  return {0.5 * g.width + ppu * (std::cos(t) * qx - std::sin(t) * qy),
          0.5 * g.height + ppu * (std::sin(t) * qx + std::cos(t) * qy), -cz};
}

}  // namespace

TEST(FlameImport3D, AffinePartsAndZVariationsFollowJWildfire) {
  const auto genomes = loadFlameFile(kData / "tetrahedron3d.flame");
  ASSERT_EQ(genomes.size(), 2u);
  const FlameGenome& g = genomes[0];
  EXPECT_TRUE(g.threeD);
  EXPECT_DOUBLE_EQ(g.camPitch, 0.6);
  EXPECT_DOUBLE_EQ(g.camYaw, 0.4);
  EXPECT_DOUBLE_EQ(g.camPerspective, 0.25);
  EXPECT_DOUBLE_EQ(g.camZpos, 0.1);
  EXPECT_DOUBLE_EQ(g.pixelsPerUnit(), 35 * 1.2);
  const FlamePoint p{0.3, -0.7, 0.9};
  // zscale −0.5 and ztranslate 0.5 on top of linear (which carries z).
  const FlamePoint a = g.xforms[0].apply(p);
  EXPECT_NEAR(a.x, 0.5 * 0.3 + 0.5, 1e-15);
  EXPECT_NEAR(a.y, 0.5 * -0.7 + 0.5, 1e-15);
  EXPECT_NEAR(a.z, 0.5 * 0.9 + 0.5, 1e-15);
  // yzCoefs "1 0 0 0.5 0 -0.5": z' = 0.5 z − 0.5, y unchanged.
  const FlamePoint b = g.xforms[1].apply(p);
  EXPECT_NEAR(b.x, 0.5 * 0.3 + 0.5, 1e-15);
  EXPECT_NEAR(b.y, 0.5 * -0.7 - 0.5, 1e-15);
  EXPECT_NEAR(b.z, 0.5 * 0.9 - 0.5, 1e-15);
  // zxCoefs "1 0 0 0.5 0 -0.5" with linear3D.
  const FlamePoint c = g.xforms[2].apply(p);
  EXPECT_NEAR(c.x, 0.5 * 0.3 - 0.5, 1e-15);
  EXPECT_NEAR(c.z, 0.5 * 0.9 - 0.5, 1e-15);
  for (const FlameXform& x : g.xforms) {
    EXPECT_TRUE(x.isAffine());
    EXPECT_FALSE(x.xyDependsOnZ());
  }
  for (const std::string& w : g.warnings) EXPECT_EQ(w.find("2D"), std::string::npos) << w;
  // cam_dof is read (a sampled import leaves it out with a warning: FlameCli's test).
  EXPECT_GT(g.camDof, 0.0);

  // A yz part that turns y into z: y' = 0.8 y − 0.6 z, z' = 0.6 y + 0.8 z + 0.2; then swirl
  // (which preserve_z makes carry 0.3 z') and linear 0.6.
  const FlameGenome& h = genomes[1];
  EXPECT_TRUE(h.xforms[0].xyDependsOnZ());
  EXPECT_FALSE(h.xforms[1].xyDependsOnZ());
  const FlamePoint q = h.xforms[0].apply(p);
  const double x1 = 0.6 * 0.3 + 0.3, y1 = 0.8 * (0.6 * -0.7) - 0.6 * 0.9, z1 = 0.6 * (0.6 * -0.7) + 0.8 * 0.9 + 0.2;
  const double r2 = x1 * x1 + y1 * y1;
  EXPECT_NEAR(q.x, 0.6 * x1 + 0.3 * (std::sin(r2) * x1 - std::cos(r2) * y1), 1e-14);
  EXPECT_NEAR(q.y, 0.6 * y1 + 0.3 * (std::cos(r2) * x1 + std::sin(r2) * y1), 1e-14);
  EXPECT_NEAR(q.z, 0.6 * z1 + 0.3 * z1, 1e-14);
  // flatten clears z whatever zcone added.
  EXPECT_EQ(h.xforms[1].apply(p).z, 0.0);
  bool blurWarned = false;
  for (const std::string& w : h.warnings) blurWarned |= w.find("blur3D") != std::string::npos;
  EXPECT_TRUE(blurWarned);
}

TEST(FlameImport3D, GenomesThatLeaveThePlaneKeepTheirVariationsNatively) {
  // z variations, 3D affine parts before and after, a planar non-linear variation (whose z the
  // genome drops: no preserve_z), a random one, and a final xform.
  const auto genomes = parseFlameFile(
      R"(<flame size="200 150" scale="40" rotate="15" cam_pitch="0.7" cam_yaw="-0.3" cam_persp="0.2" cam_zpos="0.2">
      <xform weight="1" color="0" linear="0.8" zscale="-0.4" ztranslate="0.3" swirl="0.2" coefs="0.5 0.1 -0.1 0.5 0.4 0.3"/>
      <xform weight="1" color="0.5" sinusoidal="0.7" zcone="0.4" yzCoefs="0.8 0.6 -0.6 0.8 0 0.2" zxCoefs="0.9 0.1 -0.1 0.9 0.1 0" coefs="0.6 0 0 0.6 -0.3 0"/>
      <xform weight="1" color="1" linear3D="0.9" yzPost="1 0.3 0 0.7 0 0.1" post="0.8 0.1 -0.1 0.8 0 0.2" coefs="0.5 0 0 0.5 0 -0.4"/>
      <xform weight="0.5" color="0.2" blur="0.3" pre_blur="0.1" linear="0.5" ztranslate="0.2" coefs="0.5 0 0 0.5 0.2 0.2"/>
      <finalxform color="0" color_speed="0" linear="1" zscale="0.5" coefs="1 0 0 1 0 0"/>
    </flame>)");
  const FlameGenome& g = genomes[0];
  ASSERT_TRUE(isNativeGenome(g));
  const FlameImport imported = importFlameGenome(g, {});
  const Project& p = imported.project;
  ASSERT_EQ(p.functions.size(), 4u);
  for (const std::string& w : imported.warnings) EXPECT_EQ(w.find("sampled"), std::string::npos) << w;
  for (const Function& f : p.functions) {
    EXPECT_EQ(f.resolution, (Index3{2, 2, 2}));
    EXPECT_FALSE(f.sampling_error);
  }
  EXPECT_EQ(p.functions[3].variations.count("blur"), 1u);  // a random variation, kept
  // pre_blur moves the point and adds nothing to the sum: only blur's w·z is taken away.
  EXPECT_DOUBLE_EQ(p.functions[3].variations.at("zscale"), -0.3);
  // The genome drops the planar variations' z; GridIFS's carry w·z, which a zscale takes away.
  EXPECT_DOUBLE_EQ(p.functions[0].variations.at("zscale"), -0.4 - 0.2);
  EXPECT_DOUBLE_EQ(p.functions[0].variations.at("ztranslate"), -0.3);  // X's z is the flame's −z
  EXPECT_DOUBLE_EQ(p.functions[1].variations.at("zcone"), -0.4);
  ASSERT_TRUE(p.final_function);

  // Each compiled function is the genome's map seen in X = (x, y, −z), off the plane too.
  const auto ifs = compileIfs(p);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  std::uint64_t random = 1;
  const auto check = [&](const FlameXform& x, const CompiledFunction& f, const char* label) {
    for (int n = 0; n < 300; ++n) {
      const FlamePoint q{double(float(u(rng))), double(float(u(rng))), double(float(u(rng)))};
      const FlamePoint e = x.apply(q);
      const auto got = f.evaluateMap({float(q.x), float(q.y), float(-q.z)}, random);
      const double tolerance = 2e-5 * (1.0 + std::hypot(e.x, e.y, e.z));
      EXPECT_NEAR(got[0], e.x, tolerance) << label << " at " << q.x << ", " << q.y << ", " << q.z;
      EXPECT_NEAR(got[1], e.y, tolerance) << label;
      EXPECT_NEAR(got[2], -e.z, tolerance) << label;
    }
  };
  for (std::size_t i = 0; i < 3; ++i) check(g.xforms[i], ifs->functions[i], "xform");
  check(*g.finalXform, *ifs->finalFunction, "final");

  // The camera: a point of the flame's space lands where the flame camera puts it.
  const OrbitCamera orbit(p.camera, g.width, g.height);
  for (int n = 0; n < 200; ++n) {
    const FlamePoint q{u(rng) * 0.5, u(rng) * 0.5, u(rng) * 0.5};
    const FlamePixel want = genomePixel(g, q);
    const ProjectedPoint got = orbit.project(glm::dvec3(q.x, q.y, -q.z));
    ASSERT_TRUE(got.inFront);
    EXPECT_NEAR(got.x, want.x, 1e-6);
    EXPECT_NEAR(got.y, want.y, 1e-6);
  }

  // Exported, the genome comes back the same: JWildfire's 3D parts (another factorization of the
  // same maps), ztranslate's and zcone's signs turned back, preserve_z for GridIFS's w·z.
  const FlameExport exported = exportFlame(p, std::filesystem::temp_directory_path(), "again");
  EXPECT_NE(exported.xml.find("preserve_z=\"1\""), std::string::npos);
  EXPECT_NE(exported.xml.find("yzCoefs"), std::string::npos);
  for (const std::string& w : exported.warnings) EXPECT_EQ(w.find("plane part"), std::string::npos) << w;
  const FlameGenome again = parseFlameFile(exported.xml)[0];
  FlameImportOptions inlinePalette;
  inlinePalette.inlinePaletteReference = "file:again.palette.json";
  const FlameImport reimported = importFlameGenome(again, inlinePalette);
  const auto ifs2 = compileIfs(reimported.project);
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_EQ(reimported.project.functions[i].variations, p.functions[i].variations) << i;
  for (std::size_t i = 0; i < 3; ++i)
    for (int n = 0; n < 100; ++n) {
      const std::array<float, 3> q{float(u(rng)), float(u(rng)), float(u(rng))};
      const auto a = ifs->functions[i].evaluateMap(q, random), b = ifs2->functions[i].evaluateMap(q, random);
      for (int d = 0; d < 3; ++d)
        EXPECT_NEAR(a[std::size_t(d)], b[std::size_t(d)], 1e-4 * (1.0 + std::fabs(a[std::size_t(d)]))) << i;
    }
  const OrbitCamera orbit2(reimported.project.camera, g.width, g.height);
  const ProjectedPoint before = orbit.project(glm::dvec3(0.3, -0.2, 0.4)),
                       after = orbit2.project(glm::dvec3(0.3, -0.2, 0.4));
  EXPECT_NEAR(before.x, after.x, 1e-6);
  EXPECT_NEAR(before.y, after.y, 1e-6);

  // preserve_z keeps the planar variations' w·z: no zscale is added.
  const FlameImport kept = importFlameGenome(loadFlameFile(kData / "tetrahedron3d.flame")[1], {});
  EXPECT_EQ(kept.project.functions[0].variations, (std::map<std::string, double>{{"linear", 0.6}, {"swirl", 0.3}}));
  // GridIFS's spherical sees z, the genome's only the plane: such a genome is sampled, and says why.
  const auto spherical = parseFlameFile(R"(<flame size="100 100" scale="30">
      <xform weight="1" color="0" spherical="0.5" ztranslate="0.3" coefs="0.5 0 0 0.5 0 0"/>
    </flame>)");
  EXPECT_FALSE(isNativeGenome(spherical[0]));
  const FlameImport sampled = importFlameGenome(spherical[0], {});
  bool told = false;
  for (const std::string& w : sampled.warnings) told |= w.find("spherical") != std::string::npos;
  EXPECT_TRUE(told);
  EXPECT_TRUE(sampled.project.functions[0].sampling_error);
}

TEST(FlameImport3D, AffineXformsAreExactGridsInThreeDimensions) {
  const auto genomes = loadFlameFile(kData / "tetrahedron3d.flame");
  FlameImportOptions grids;
  grids.sampleOntoGrids = true;
  const FlameImport imported = importFlameGenome(genomes[0], grids);
  ASSERT_EQ(imported.project.functions.size(), 4u);
  EXPECT_TRUE(imported.frame.threeD);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t i = 0; i < 4; ++i) {
    const Function& fn = imported.project.functions[i];
    EXPECT_EQ(fn.resolution, (Index3{2, 2, 2}));
    ASSERT_TRUE(fn.sampling_error);
    EXPECT_LT(*fn.sampling_error, 1e-12);
    const auto grid = evaluateFunctionAt(fn, "");
    for (int n = 0; n < 100; ++n) {
      const Vec3 p(u(rng), u(rng), u(rng));
      const FlamePoint e = imported.frame.toX(genomes[0].xforms[i].apply(imported.frame.fromX({p.x, p.y, p.z})));
      const Vec3 got = grid->evaluate(p);
      EXPECT_NEAR(got.x, e.x, 1e-12);
      EXPECT_NEAR(got.y, e.y, 1e-12);
      EXPECT_NEAR(got.z, e.z, 1e-12);
    }
  }
  // The frame is a similarity in 3D: fromX inverts toX.
  const FlamePoint a{1.7, -2.2, 0.4}, b = imported.frame.fromX(imported.frame.toX(a));
  EXPECT_NEAR(a.x, b.x, 1e-12);
  EXPECT_NEAR(a.y, b.y, 1e-12);
  EXPECT_NEAR(a.z, b.z, 1e-12);
}

TEST(FlameImport3D, TheCameraSeesWhatTheFlameCameraSees) {
  const auto genomes = loadFlameFile(kData / "tetrahedron3d.flame");
  for (const FlameGenome& g : genomes) {
    FlameImportOptions options;
    options.sampleOntoGrids = true;
    options.resolution = 8;
    options.inlinePaletteReference = "file:x.palette.json";
    const FlameImport imported = importFlameGenome(g, options);
    const Camera& cam = imported.project.camera;
    EXPECT_EQ(cam.orthographic(), g.camPerspective == 0.0) << g.name;
    const OrbitCamera orbit(cam, g.width, g.height);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<std::pair<double, double>> depths;
    for (int n = 0; n < 200; ++n) {
      const FlamePoint p{u(rng), u(rng), u(rng)};
      const FlamePixel want = genomePixel(g, p);
      const FlamePoint x = imported.frame.toX(p);
      const ProjectedPoint got = orbit.project(glm::dvec3(x.x, x.y, x.z));
      ASSERT_TRUE(got.inFront);
      EXPECT_NEAR(got.x, want.x, 1e-6) << g.name;
      EXPECT_NEAR(got.y, want.y, 1e-6) << g.name;
      depths.emplace_back(want.depth, got.depth);
    }
    // Nearer for the flame camera is nearer for GridIFS's.
    for (std::size_t i = 1; i < depths.size(); ++i) {
      if (std::fabs(depths[i].first - depths[i - 1].first) > 1e-3) {
        EXPECT_EQ(depths[i].first < depths[i - 1].first, depths[i].second < depths[i - 1].second);
      }
    }
  }
}

TEST(FlameImport3D, OnlyXformsThatMixZIntoXyNeedLayersInZ) {
  const auto genomes = loadFlameFile(kData / "tetrahedron3d.flame");
  double previous = 1e300;
  for (int resolution : {12, 24}) {
    FlameImportOptions options;
    options.sampleOntoGrids = true;
    options.resolution = resolution;
    options.inlinePaletteReference = "file:x.palette.json";
    const FlameImport imported = importFlameGenome(genomes[1], options);
    const auto& fns = imported.project.functions;
    ASSERT_EQ(fns.size(), 2u);
    // The camera is turned: depth needs layers for every non-affine xform.
    EXPECT_EQ(fns[0].resolution, (Index3{resolution, resolution / 2, resolution}));
    EXPECT_EQ(fns[1].resolution, (Index3{resolution, resolution / 2, resolution}));
    ASSERT_TRUE(fns[0].sampling_error && fns[1].sampling_error);
    EXPECT_LT(*fns[0].sampling_error, previous);
    previous = *fns[0].sampling_error;
  }
  // Seen straight on, an xform that keeps z out of x and y is exact with two layers in depth.
  const auto straight = parseFlameFile(R"(<flame size="100 100" scale="40" cam_persp="0.2">
      <xform weight="1" color="0" sinusoidal="0.8" zscale="0.5" ztranslate="0.2" coefs="0.7 0 0 0.7 0.1 0"/>
      <xform weight="1" color="1" sinusoidal="0.8" yzCoefs="0.8 0.6 -0.6 0.8 0 0" coefs="0.7 0 0 0.7 -0.1 0"/>
    </flame>)");
  FlameImportOptions options;
  options.sampleOntoGrids = true;
  options.resolution = 16;
  const FlameImport imported = importFlameGenome(straight[0], options);
  EXPECT_EQ(imported.project.functions[0].resolution, (Index3{16, 2, 16}));
  EXPECT_EQ(imported.project.functions[1].resolution, (Index3{16, 8, 16}));
  FlameImportOptions coarse = options;
  coarse.resolution = 8;
  const FlameImport rough = importFlameGenome(straight[0], coarse);
  // The error is that of the image plane's bilinear interpolation: it shrinks with R.
  EXPECT_LT(*imported.project.functions[0].sampling_error, 0.5 * *rough.project.functions[0].sampling_error);
}

TEST(FlamePaletteHue, RotatesHueLikeFlam3) {
  Palette p;
  p.colors[0] = {1.f, 0.f, 0.f};
  p.colors[1] = {1.f, 0.5f, 0.f};
  p.colors[2] = {0.4f, 0.4f, 0.4f};
  const Palette third = rotatePaletteHue(p, 1.0 / 3.0);
  EXPECT_NEAR(third.colors[0].r, 0.f, 1e-6);
  EXPECT_NEAR(third.colors[0].g, 1.f, 1e-6);
  EXPECT_NEAR(third.colors[0].b, 0.f, 1e-6);
  const Palette half = rotatePaletteHue(p, 0.5);
  EXPECT_NEAR(half.colors[1].r, 0.f, 1e-6);
  EXPECT_NEAR(half.colors[1].g, 0.5f, 1e-6);
  EXPECT_NEAR(half.colors[1].b, 1.f, 1e-6);
  EXPECT_EQ(half.colors[2], p.colors[2]);  // gray has no hue
  const Palette full = rotatePaletteHue(p, 1.0), back = rotatePaletteHue(third, -1.0 / 3.0);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(full.colors[std::size_t(i)].r, p.colors[std::size_t(i)].r, 1e-6);
    EXPECT_NEAR(back.colors[std::size_t(i)].g, p.colors[std::size_t(i)].g, 1e-6);
  }
}

TEST(FlamePaletteHue, ImportTurnsACollectionPaletteButNotInlineColors) {
  try {
    flam3Palettes();
  } catch (const PaletteError&) {
    GTEST_SKIP() << "flam3's palette collection (flam3-palette) is not installed";
  }
  const auto genomes = loadFlameFile(kData / "tetrahedron3d.flame");
  FlameImportOptions options;
  options.resolution = 8;
  options.inlinePaletteReference = "file:tilted.palette.json";
  const FlameImport turned = importFlameGenome(genomes[1], options);  // palette 3, hue 0.25
  // The hue stays a setting on flam3's palette, so the artist can keep turning it.
  EXPECT_FALSE(turned.palette);
  EXPECT_EQ(turned.project.render.flame.palette, "flam3:3");
  EXPECT_DOUBLE_EQ(turned.project.render.flame.hue, 0.25);
  const Palette expected = rotatePaletteHue(flam3Palette("3"), 0.25);
  EXPECT_EQ(resolveFlamePalette(turned.project.render.flame).colors, expected.colors);
  EXPECT_NE(expected.colors, flam3Palette("3").colors);
  // The functions' z-buffer colours are the turned palette's.
  const Rgb c = expected.lookup(genomes[1].xforms[0].color);
  EXPECT_NEAR(turned.project.functions[0].color.x, c.r, 1e-6);
  // Inline colors stay as they are (flam3-render leaves them too).
  auto inline_ = parseFlameFile(R"(<flame size="10 10" hue="0.4">
      <xform weight="1" color="0" linear="1" coefs="0.5 0 0 0.5 0 0"/>
      <color index="0" rgb="255 0 0"/></flame>)");
  const FlameImport kept = importFlameGenome(inline_[0], options);
  ASSERT_TRUE(kept.palette);
  EXPECT_EQ(kept.palette->colors[0], (Rgb{1.f, 0.f, 0.f}));
}
