// A fractal field modulating the measure attractor's density (Colonna, "Animation of fractal
// objects", §3.2: cloud density from a fractal field that drifts with the wind): the file block,
// its validation, the weight formula against the point-by-point field, periodic loops.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "base/errors.h"
#include "io/project_io.h"
#include "volume/density_field.h"
#include "volume/measure_attractor.h"

using namespace gridifs;
namespace fs = std::filesystem;

namespace {

const char* kDriftingCloud = R"({
  "format": "gridifs", "version": 1,
  "functions": [
    {"name": "A", "kind": "median", "weight": 2,
     "set": {"primitive": "sphere", "center": [-0.4, 0, 0], "radius": 0.35}},
    {"name": "B", "kind": "median", "weight": 1,
     "set": {"primitive": "box", "center": [0.45, 0, 0], "size": [0.5, 0.5, 0.5]}}
  ],
  "volume": {"resolution": 32, "iterations": 60, "skip": 10, "seed": 5,
             "field": {"strength": 0.9, "scale": 0.4, "ratio": 0.5, "octaves": 4, "gain": 0.6,
                       "interpolation": "cubic", "seed": 11, "wind": [0.3, 0.1, 0], "period": [0, 0, 0, 2]}}
})";

Project withVolumeField(const std::string& key, const nlohmann::json& value) {
  nlohmann::json j = nlohmann::json::parse(kDriftingCloud);
  j["volume"]["field"][key] = value;
  return parseProject(j.dump());
}

DensityVolume volumeAt(Project project, double t) {
  project.time = t;
  VolumeJob job;
  job.settings = *project.volume;
  job.threads = 2;
  return computeDensityVolume(project, job);
}

}  // namespace

TEST(DensityField, TheVolumeBlockCarriesTheFieldAndRoundTrips) {
  const Project p = parseProject(kDriftingCloud);
  ASSERT_TRUE(p.volume && p.volume->field);
  EXPECT_DOUBLE_EQ(p.volume->field->strength, 0.9);
  EXPECT_EQ(p.volume->field->field.octaves, 4);
  EXPECT_EQ(p.volume->field->field.seed, 11u);
  EXPECT_DOUBLE_EQ(p.volume->field->field.wind.x, 0.3);
  EXPECT_DOUBLE_EQ(p.volume->field->field.period[3], 2.0);
  const std::string saved = serializeProject(p);
  EXPECT_EQ(parseProject(saved), p);
  const nlohmann::json field = nlohmann::json::parse(saved)["volume"]["field"];
  EXPECT_FALSE(field.contains("amplitude")) << "strength takes the amplitude's part";
  EXPECT_TRUE(field.contains("strength"));
  // A project without the block saves without it.
  nlohmann::json plain = nlohmann::json::parse(kDriftingCloud);
  plain["volume"].erase("field");
  EXPECT_FALSE(nlohmann::json::parse(serializeProject(parseProject(plain.dump())))["volume"].contains("field"));
}

TEST(DensityField, BadFieldsAreRejectedWithTheirPath) {
  auto pathOf = [](const std::string& key, const nlohmann::json& value) {
    try {
      withVolumeField(key, value);
    } catch (const ModelError& e) {
      return e.path();
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(pathOf("strength", -1), "volume.field.strength");
  EXPECT_EQ(pathOf("strength", 1000), "volume.field.strength");
  EXPECT_EQ(pathOf("octaves", 0), "volume.field.octaves");
  EXPECT_EQ(pathOf("octaves", 17), "volume.field.octaves");
  EXPECT_EQ(pathOf("ratio", 1.5), "volume.field.ratio");
  EXPECT_EQ(pathOf("period", nlohmann::json::array({0, 0, -1, 0})), "volume.field.period[2]");
  EXPECT_EQ(pathOf("interpolation", "bicubic"), "volume.field.interpolation");
  try {
    nlohmann::json j = nlohmann::json::parse(kDriftingCloud);
    j["volume"]["field"] = 3;
    parseProject(j.dump());
    ADD_FAILURE() << "a field that is not an object was accepted";
  } catch (const ModelError& e) {
    EXPECT_EQ(e.path(), "volume.field");
  }
}

TEST(DensityField, EachVisitedVoxelIsWeightedByTheFieldAtItsCentre) {
  Project plain = parseProject(kDriftingCloud);
  const VolumeDensityField field = *plain.volume->field;
  plain.volume->field.reset();
  const double t = 0.7;
  const DensityVolume before = volumeAt(plain, t);
  const DensityVolume after = volumeAt(parseProject(kDriftingCloud), t);
  ASSERT_EQ(before.density.size(), after.density.size());
  // Expected: before · weight(p, t), divided by its largest value. The weights come from the
  // point-by-point field, the volume from the whole-step evaluation.
  std::vector<double> expected(before.density.size());
  double largest = 0.0;
  for (std::uint32_t v = 0; v < expected.size(); ++v) {
    expected[v] =
        before.density[v] > 0.0f ? before.density[v] * densityFieldWeight(field, before.lattice.centre(v), t) : 0.0;
    largest = std::max(largest, expected[v]);
  }
  ASSERT_GT(largest, 0.0);
  int visited = 0;
  double lowest = 1e9, highest = 0.0;  // the field's weights, relative to each other
  for (std::uint32_t v = 0; v < expected.size(); ++v) {
    if (before.density[v] == 0.0f) {
      EXPECT_EQ(after.density[v], 0.0f) << "the field adds no density outside the attractor";
      continue;
    }
    ++visited;
    EXPECT_NEAR(after.density[v], expected[v] / largest, 1e-5) << v;
    const double relative = after.density[v] / before.density[v];
    lowest = std::min(lowest, relative);
    highest = std::max(highest, relative);
  }
  EXPECT_GT(visited, 1000);
  EXPECT_GT(highest, 2.0 * lowest) << "a strength of 0.9 should thin the cloud unevenly";
  EXPECT_FLOAT_EQ(*std::max_element(after.density.begin(), after.density.end()), 1.0f);
}

TEST(DensityField, StrengthZeroLeavesTheDensityAsItWas) {
  Project plain = parseProject(kDriftingCloud);
  plain.volume->field.reset();
  const DensityVolume a = volumeAt(plain, 0.3);
  const DensityVolume b = volumeAt(withVolumeField("strength", 0.0), 0.3);
  EXPECT_EQ(a.density, b.density);
}

TEST(DensityField, APeriodInTimeClosesTheLoop) {
  // The wind shifts the sample point by wind·t, which a period in t alone does not undo; a loop
  // needs the spatial periods to absorb wind·Lt. Without wind the cloud repeats exactly.
  const Project calm = withVolumeField("wind", nlohmann::json::array({0, 0, 0}));
  EXPECT_EQ(volumeAt(calm, 0.25).density, volumeAt(calm, 2.25).density);
  EXPECT_NE(volumeAt(calm, 0.25).density, volumeAt(calm, 1.0).density);
  // With wind (0.3, 0.1, 0) and spatial periods that hold a whole number of wind steps per loop
  // (0.6 and 0.2 per 2 time units), it repeats too.
  nlohmann::json j = nlohmann::json::parse(kDriftingCloud);
  j["volume"]["field"]["period"] = {0.6, 0.2, 0, 2};
  const Project looping = parseProject(j.dump());
  const DensityVolume a = volumeAt(looping, 0.25), b = volumeAt(looping, 2.25);
  float worst = 0.0f;
  for (std::size_t v = 0; v < a.density.size(); ++v) worst = std::max(worst, std::abs(a.density[v] - b.density[v]));
  EXPECT_LT(worst, 1e-5f) << "the wind's shift over one loop is a whole number of spatial periods";
}
