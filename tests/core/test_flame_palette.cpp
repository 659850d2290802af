// Palettes for the flame display (Draves & Reckase 2003, §5).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tone/palette.h"

using namespace gridifs;

namespace {
bool haveFlam3() { return std::filesystem::exists(kFlam3PaletteFile); }
std::string readPaletteFile(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

TEST(FlamePalette, ParsesFlam3EntriesAs00RRGGBB) {
  std::string data;
  for (int i = 0; i < 256; ++i) data += i == 0 ? "00ff8000" : "00000000";
  const auto palettes =
      parseFlam3Palettes("<palettes>\n<palette number=\"0\" name=\"x\" data=\"" + data + "\"/>\n</palettes>");
  ASSERT_EQ(palettes.size(), 1u);
  EXPECT_EQ(palettes[0].name, "x");
  EXPECT_FLOAT_EQ(palettes[0].colors[0].r, 1.f);
  EXPECT_FLOAT_EQ(palettes[0].colors[0].g, 128 / 255.f);
  EXPECT_FLOAT_EQ(palettes[0].colors[0].b, 0.f);
  EXPECT_THROW(parseFlam3Palettes("<palette number=\"1\" data=\"00ff\"/>"), PaletteError);
  EXPECT_THROW(parseFlam3Palettes("<nothing/>"), PaletteError);
}

TEST(FlamePalette, ReadsDebiansFlam3CollectionByNumberAndName) {
  if (!haveFlam3()) GTEST_SKIP() << "flam3-palette is not installed";
  const auto& all = flam3Palettes();
  EXPECT_GT(all.size(), 100u);
  const Palette first = flam3Palette("0");
  EXPECT_EQ(first.name, "south-sea-bather");
  EXPECT_EQ(flam3Palette("south-sea-bather"), first);
  // The file's first entry is 00b9eaeb.
  EXPECT_FLOAT_EQ(first.colors[0].r, 0xb9 / 255.f);
  EXPECT_FLOAT_EQ(first.colors[0].g, 0xea / 255.f);
  EXPECT_FLOAT_EQ(first.colors[0].b, 0xeb / 255.f);
  EXPECT_EQ(resolvePalette("flam3:0"), first);
  EXPECT_THROW(flam3Palette("999999"), PaletteError);
  EXPECT_THROW(flam3Palette("no-such-palette"), PaletteError);
}

TEST(FlamePalette, LookupFollowsFlam3LinearMode) {
  Palette p;
  for (int i = 0; i < 256; ++i) p.colors[i] = {i / 255.f, 1.f - i / 255.f, 0.5f};
  EXPECT_EQ(p.lookup(0.0), p.colors[0]);
  EXPECT_EQ(p.lookup(-3.0), p.colors[0]);
  EXPECT_EQ(p.lookup(1.0), p.colors[255]);
  EXPECT_EQ(p.lookup(0.5), p.colors[128]);  // index c·256 = 128 exactly
  const Rgb mid = p.lookup((10.0 + 0.25) / 256.0);
  EXPECT_NEAR(mid.r, 0.75f * p.colors[10].r + 0.25f * p.colors[11].r, 1e-6);
}

TEST(FlamePalette, JsonRoundTripAndInterpolatedStops) {
  const Palette ember = builtinPalette("ember");
  const Palette back = parsePaletteJson(serializePaletteJson(ember));
  EXPECT_EQ(back.name, "ember");
  for (int i = 0; i < 256; ++i) {
    EXPECT_NEAR(back.colors[i].r, ember.colors[i].r, 1e-4);
    EXPECT_NEAR(back.colors[i].b, ember.colors[i].b, 1e-4);
  }
  const Palette three =
      parsePaletteJson(R"({"format": "gridifs-palette", "name": "t", "colors": [[1,0,0],[0,1,0],[0,0,1]]})");
  EXPECT_EQ(three.colors[0], (Rgb{1, 0, 0}));
  EXPECT_EQ(three.colors[255], (Rgb{0, 0, 1}));
  EXPECT_NEAR(three.colors[128].g, 1.0, 0.01);
  EXPECT_THROW(parsePaletteJson(R"({"format": "gridifs-palette", "colors": [[1,0,0]]})"), PaletteError);
  EXPECT_THROW(parsePaletteJson(R"({"format": "gridifs-palette", "colors": [[1,0,0],[2,0,0]]})"), PaletteError);
  EXPECT_THROW(parsePaletteJson(R"({"colors": [[1,0,0],[0,0,0]]})"), PaletteError);
  EXPECT_THROW(parsePaletteJson("not json"), PaletteError);
}

TEST(FlamePalette, ShippedPaletteFilesMatchTheBuiltIns) {
  for (const std::string& name : builtinPaletteNames()) {
    const std::filesystem::path file = std::filesystem::path(GRIDIFS_ASSETS) / "palettes" / (name + ".json");
    ASSERT_TRUE(std::filesystem::exists(file)) << file;
    const Palette fromFile = parsePaletteJson(readPaletteFile(file));
    const Palette builtIn = builtinPalette(name);
    EXPECT_EQ(fromFile.name, name);
    for (int i = 0; i < 256; ++i) {
      EXPECT_NEAR(fromFile.colors[i].r, builtIn.colors[i].r, 1e-4) << name << " " << i;
      EXPECT_NEAR(fromFile.colors[i].g, builtIn.colors[i].g, 1e-4) << name << " " << i;
      EXPECT_NEAR(fromFile.colors[i].b, builtIn.colors[i].b, 1e-4) << name << " " << i;
    }
    EXPECT_EQ(resolvePalette("file:" + file.string()).name, name);
  }
}

TEST(FlamePalette, ReferencesResolveOrFailWithASentence) {
  EXPECT_EQ(resolvePalette(kDefaultPaletteRef).name, "ember");
  EXPECT_TRUE(isPaletteReferenceSyntax("ember"));
  EXPECT_TRUE(isPaletteReferenceSyntax("flam3:12"));
  EXPECT_TRUE(isPaletteReferenceSyntax("file:my.json"));
  EXPECT_FALSE(isPaletteReferenceSyntax("nonsense"));
  EXPECT_FALSE(isPaletteReferenceSyntax("flam3:"));
  EXPECT_THROW(resolvePalette("nonsense"), PaletteError);
  EXPECT_THROW(resolvePalette("file:/no/such/palette.json"), PaletteError);
  // Built-in palettes never contain black, so every function stays visible.
  for (const std::string& name : builtinPaletteNames())
    for (const Rgb& c : builtinPalette(name).colors) EXPECT_GT(c.r + c.g + c.b, 0.1f) << name;
}
