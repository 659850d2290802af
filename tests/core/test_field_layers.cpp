// Colonna's fractal fields beyond one displacement ("Animation of fractal objects"): the wind
// along a keyed path (§3.2: the sample point moves by the wind's displacement, ∫₀ᵗ wind), the field
// interpolated with a geometric shape (§1.2, fig. 3) and several field layers in one scene (fig. 6:
// a mountain under clouds) — the formulas, the file forms and the edits.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "base/errors.h"
#include "edit/project_edit.h"
#include "io/project_io.h"
#include "model/stack_evaluator.h"
#include "schema/field_layer.h"
#include "schema/project_time.h"
#include "volume/density_field.h"

using namespace gridifs;

namespace {

// ∫ from a to b of the track's value by the composite Simpson rule over n panels (n even).
double simpson(const KeyframeTrack& track, double a, double b, int n) {
  const double h = (b - a) / n;
  double sum = track.valueAt(a) + track.valueAt(b);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * track.valueAt(a + i * h);
  return sum * h / 3.0;
}

KeyframeTrack windTrack(KeyInterpolation interp) {
  return KeyframeTrack{{{0.5, 0.2, interp}, {1.5, -0.4, interp}, {2.0, 0.6, interp}, {3.5, 0.1, interp}}};
}

const char* kWindProject = R"({
  "format": "gridifs", "version": 1,
  "functions": [{"name": "a", "resolution": [4, 4, 4],
    "ops": [{"type": "field", "amplitude": [0.1, 0.1, 0.1], "octaves": 3, "seed": 3, "wind": [0.2, 0, 0.1]}]}],
  "tracks": {"functions[0].ops[0].wind[0]": [{"t": 0, "v": 0}, {"t": 2, "v": 1}]}
})";

const char* kLayeredScene = R"({
  "format": "gridifs", "version": 1,
  "functions": [{"name": "A", "kind": "condensation", "weight": 1,
                 "set": {"primitive": "sphere", "center": [0, 0, 0.3], "radius": 0.2}}],
  "volume": {"resolution": 24, "samples": 20000, "seed": 2,
    "field": [
      {"role": "terrain", "height": -0.5, "strength": 0.6, "octaves": 4, "seed": 1},
      {"role": "cloud", "height": 0.5, "thickness": 0.3, "strength": 3, "octaves": 3, "seed": 7},
      {"strength": 0.5, "octaves": 3, "seed": 4,
       "shape": {"primitive": "sphere", "center": [0, 0, 0], "radius": 0.5}, "blend": 0.7, "softness": 0.2}
    ]}
})";

}  // namespace

TEST(WindIntegral, StepAndLinearTracksIntegrateExactly) {
  // Step: the value of each key held to the next; linear: trapezoids; both by hand.
  const KeyframeTrack step = windTrack(KeyInterpolation::Step);
  EXPECT_NEAR(step.integral(0.0, 3.5), 0.5 * 0.2 + 0.2 * 1.0 + (-0.4) * 0.5 + 0.6 * 1.5, 1e-15);
  EXPECT_NEAR(step.integral(1.0, 1.75), 0.2 * 0.5 + (-0.4) * 0.25, 1e-15);
  const KeyframeTrack linear = windTrack(KeyInterpolation::Linear);
  EXPECT_NEAR(linear.integral(0.0, 3.5), 0.1 + (0.2 - 0.4) / 2 + (-0.4 + 0.6) / 2 * 0.5 + (0.6 + 0.1) / 2 * 1.5, 1e-15);
  // Part of a segment: from 1.0 (value -0.1) to 1.25 (value -0.25).
  EXPECT_NEAR(linear.integral(1.0, 1.25), 0.25 * (-0.1 - 0.25) / 2, 1e-15);
  // The ends hold: before the first key and after the last the end values.
  EXPECT_NEAR(linear.integral(-2.0, 0.5), 2.5 * 0.2, 1e-15);
  EXPECT_NEAR(linear.integral(3.5, 5.0), 1.5 * 0.1, 1e-15);
  // Reversed limits change the sign.
  EXPECT_NEAR(linear.integral(3.0, 1.0), -linear.integral(1.0, 3.0), 1e-15);
  EXPECT_EQ(KeyframeTrack{}.integral(0.0, 1.0), 0.0);
}

TEST(WindIntegral, SmoothTracksMatchTheNumericalIntegral) {
  const KeyframeTrack smooth = windTrack(KeyInterpolation::Smooth);
  // Simpson's rule is exact for the cubic segments when its panels end at the keys.
  const auto numerical = [&](double t) {
    double sum = 0.0, from = std::min(0.0, t), to = std::max(0.0, t);
    double a = from;
    for (const Keyframe& k : smooth.keys)
      if (k.t > a && k.t < to) {
        sum += simpson(smooth, a, k.t, 64);
        a = k.t;
      }
    sum += simpson(smooth, a, to, 64);
    return t < 0.0 ? -sum : sum;
  };
  for (double t : {-0.5, 0.3, 0.9, 1.5, 1.8, 2.7, 3.5, 4.2})
    EXPECT_NEAR(smooth.integral(0.0, t), numerical(t), 1e-13) << t;
  // A mixed track: each segment by its own interpolation.
  KeyframeTrack mixed = windTrack(KeyInterpolation::Smooth);
  mixed.keys[1].interp = KeyInterpolation::Step;
  mixed.keys[2].interp = KeyInterpolation::Linear;
  // Simpson is exact for the cubic and linear parts; the step's jump sits on a panel boundary.
  EXPECT_NEAR(mixed.integral(0.5, 1.5) + mixed.integral(1.5, 2.0) + mixed.integral(2.0, 3.5),
              simpson(mixed, 0.5, 1.5, 400) + 0.5 * (-0.4) + simpson(mixed, 2.0, 3.5, 400), 1e-12);
}

TEST(WindIntegral, AKeyedWindDriftsTheFieldByItsIntegral) {
  const Project loaded = parseProject(kWindProject);
  for (double t : {0.0, 0.7, 1.5, 3.0}) {
    const Project at = projectAtTime(loaded, t);
    const FieldOp& op = std::get<FieldOp>(at.functions[0].ops[0].params);
    ASSERT_TRUE(op.drift.has_value());
    // wind_x(τ) = τ/2 up to 2, then 1: ∫₀ᵗ = t²/4, or 1 + (t − 2). The other components keep wind·t.
    const double x = t <= 2.0 ? t * t / 4.0 : 1.0 + (t - 2.0);
    EXPECT_NEAR(op.drift->x, x, 1e-15) << t;
    EXPECT_DOUBLE_EQ(op.drift->y, 0.0);
    EXPECT_DOUBLE_EQ(op.drift->z, 0.1 * t);
    // The grid moves as a field with that constant shift: s = q + drift.
    const Grid grid = evaluateFunction(at.functions[0], std::size_t(-1), true, t);
    FieldOp reference = op;
    reference.drift.reset();
    reference.wind = t > 0.0 ? *op.drift / t : Vec3{0.0};
    const FractalField field(reference);
    const Grid u(at.functions[0].resolution);
    for (std::size_t n = 0; n < u.nodes().size(); ++n) {
      const Vec3 expected = u.nodes()[n] + field.displacement(u.nodes()[n], t);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(grid.nodes()[n][c], expected[c], 1e-6);
    }
  }
  // Without a wind track the field drifts by wind·t, as before.
  Project still = loaded;
  still.tracks.clear();
  EXPECT_FALSE(std::get<FieldOp>(projectAtTime(still, 1.0).functions[0].ops[0].params).drift.has_value());
  // Removing the keys (an edit) takes the drift away.
  const Project keyed = projectAtTime(loaded, 1.0);
  Project unkeyed = keyed;
  unkeyed.tracks.clear();
  EXPECT_FALSE(std::get<FieldOp>(keyEditedParameters(keyed, unkeyed).functions[0].ops[0].params).drift.has_value());
}

TEST(FieldBlend, TheShapeValueFollowsItsSignedDistance) {
  CondensationSet sphere;
  sphere.center = {0.1, 0.0, 0.0};
  sphere.radius = 0.5;
  EXPECT_NEAR(primitiveSignedDistance(sphere, {0.1, 0.0, 0.0}), -0.5, 1e-15);
  EXPECT_NEAR(primitiveSignedDistance(sphere, {0.1, 0.8, 0.0}), 0.3, 1e-15);
  CondensationSet box;
  box.shape = SetShape::Box;
  box.size = {1.0, 0.5, 2.0};
  EXPECT_NEAR(primitiveSignedDistance(box, {0.0, 0.0, 0.0}), -0.25, 1e-15);
  EXPECT_NEAR(primitiveSignedDistance(box, {0.8, 0.65, 0.0}), std::hypot(0.3, 0.4), 1e-15);
  CondensationSet torus;
  torus.shape = SetShape::Torus;
  torus.major = 0.5;
  torus.minor = 0.1;
  EXPECT_NEAR(primitiveSignedDistance(torus, {0.5, 0.0, 0.0}), -0.1, 1e-15);
  EXPECT_NEAR(primitiveSignedDistance(torus, {0.0, 0.0, 0.0}), 0.4, 1e-15);

  VolumeDensityField layer;
  layer.field.octaves = 4;
  layer.field.seed = 5;
  const Vec3 points[] = {{0.1, 0.0, 0.0}, {0.1, 0.45, 0.0}, {0.1, 0.5, 0.0}, {0.1, 0.9, 0.2}};
  const double plain[] = {fieldLayerValue(layer, points[0], 0.4), fieldLayerValue(layer, points[1], 0.4),
                          fieldLayerValue(layer, points[2], 0.4), fieldLayerValue(layer, points[3], 0.4)};
  layer.shape = sphere;
  layer.softness = 0.2;
  // S = clamp(−d/softness, −1, 1): 1 deep inside, 0.25 at 0.05 inside, 0 on the boundary, −1 far out.
  const double s[] = {1.0, 0.25, 0.0, -1.0};
  for (double blend : {0.0, 0.3, 1.0}) {
    layer.blend = blend;
    for (int i = 0; i < 4; ++i) {
      EXPECT_NEAR(fieldShapeValue(layer, points[i]), s[i], 1e-12);
      EXPECT_NEAR(fieldLayerValue(layer, points[i], 0.4), (1.0 - blend) * plain[i] + blend * s[i], 1e-12);
    }
  }
  // The many-point evaluation gives the same values up to single-precision rounding.
  const std::vector<double> many = fieldLayerValues(layer, {std::begin(points), std::end(points)}, 0.4);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(many[i], fieldLayerValue(layer, points[i], 0.4), 1e-5);
}

TEST(FieldLayers, AListOfLayersLoadsSavesAndValidates) {
  const Project p = parseProject(kLayeredScene);
  ASSERT_TRUE(p.volume && p.volume->field);
  ASSERT_EQ(p.volume->more_fields.size(), 2u);
  EXPECT_EQ(p.volume->field->role, FieldRole::Terrain);
  EXPECT_DOUBLE_EQ(p.volume->field->height, -0.5);
  EXPECT_EQ(p.volume->more_fields[0].role, FieldRole::Cloud);
  EXPECT_DOUBLE_EQ(p.volume->more_fields[0].thickness, 0.3);
  EXPECT_EQ(p.volume->more_fields[1].role, FieldRole::Density);
  ASSERT_TRUE(p.volume->more_fields[1].shape.has_value());
  EXPECT_DOUBLE_EQ(p.volume->more_fields[1].blend, 0.7);
  const std::string saved = serializeProject(p);
  EXPECT_EQ(parseProject(saved), p);
  EXPECT_TRUE(nlohmann::json::parse(saved)["volume"]["field"].is_array());
  // One plain field still saves as one object, without the layer fields.
  Project single = p;
  single.volume->more_fields.clear();
  single.volume->field = VolumeDensityField{};
  const nlohmann::json one = nlohmann::json::parse(serializeProject(single))["volume"]["field"];
  ASSERT_TRUE(one.is_object());
  for (const char* key : {"role", "height", "thickness", "shape", "blend", "softness"})
    EXPECT_FALSE(one.contains(key)) << key;
  // Bad layers name their place in the list.
  const auto errorPath = [](const std::function<void(nlohmann::json&)>& change) {
    nlohmann::json j = nlohmann::json::parse(kLayeredScene);
    change(j);
    try {
      parseProject(j.dump());
    } catch (const ModelError& e) {
      return e.path();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(errorPath([](nlohmann::json& j) { j["volume"]["field"][1]["role"] = "fog"; }), "volume.field[1].role");
  EXPECT_EQ(errorPath([](nlohmann::json& j) { j["volume"]["field"][2]["blend"] = 1.5; }), "volume.field[2].blend");
  EXPECT_EQ(errorPath([](nlohmann::json& j) { j["volume"]["field"][2]["softness"] = 0; }), "volume.field[2].softness");
  EXPECT_EQ(errorPath([](nlohmann::json& j) {
              j["volume"]["field"][2]["shape"] = {{"mesh", "a.obj"}};
            }),
            "volume.field[2].shape");
  EXPECT_EQ(errorPath([](nlohmann::json& j) { j["volume"]["field"][0]["octaves"] = 40; }), "volume.field[0].octaves");
}

TEST(FieldLayers, TerrainAndCloudLayersAddTheirDensity) {
  const Project p = parseProject(kLayeredScene);
  DensityVolume volume;
  volume.lattice = VoxelLattice{24};
  volume.density.assign(volume.lattice.voxelCount(), 0.0f);
  VolumeSettings settings = *p.volume;
  settings.more_fields.pop_back();  // the terrain and the cloud
  const double t = 0.6;
  applyFieldLayers(volume, settings, t, 2);
  const VolumeDensityField& terrain = *settings.field;
  const VolumeDensityField& cloud = settings.more_fields[0];
  int rock = 0, sky = 0;
  for (int k = 0; k < 24; ++k)
    for (int j = 0; j < 24; ++j)
      for (int i = 0; i < 24; ++i) {
        const Vec3 c = volume.lattice.centre(i, j, k);
        const double ground =
            terrain.height + terrain.strength * fieldLayerValue(terrain, {c.x, c.y, terrain.height}, t);
        const double g = std::clamp(cloud.strength * fieldLayerValue(cloud, {c.x, c.y, cloud.height}, t), 0.0, 1.0);
        // Voxels within a rounding of the surfaces are left out.
        if (std::abs(c.z - ground) < 1e-4 || std::abs(std::abs(c.z - cloud.height) - 0.5 * g * cloud.thickness) < 1e-4)
          continue;
        double expected = 0.0;
        if (g > 0.0 && std::abs(c.z - cloud.height) <= 0.5 * g * cloud.thickness) expected = g;
        if (c.z <= ground) expected = 1.0;
        EXPECT_NEAR(volume.at(i, j, k), expected, 1e-4) << i << " " << j << " " << k;
        rock += expected == 1.0;
        sky += expected > 0.0 && expected < 1.0;
        EXPECT_NEAR(fieldLayerDensity(c.z <= ground ? terrain : cloud, c, t), expected, 1e-4);
      }
  EXPECT_GT(rock, 24 * 24);  // a mountain stands on the floor of the volume
  EXPECT_GT(sky, 10);        // and clouds float above it
}

TEST(FieldLayers, ADensityLayerBlendedWithAShapeWeightsTheVisits) {
  const Project p = parseProject(kLayeredScene);
  const VolumeDensityField& layer = p.volume->more_fields[1];
  DensityVolume volume;
  volume.lattice = VoxelLattice{16};
  volume.density.assign(volume.lattice.voxelCount(), 0.0f);
  for (std::size_t v = 0; v < volume.density.size(); v += 3) volume.density[v] = 0.5f + 0.5f * float(v % 7) / 7.0f;
  const std::vector<float> before = volume.density;
  modulateDensity(volume, layer, 0.2, 2);
  // Each visited voxel scaled by max(0, 1 + strength·G), then the whole divided by its largest value.
  std::vector<double> weighted(before.size());
  double largest = 0.0;
  for (std::size_t v = 0; v < before.size(); ++v) {
    weighted[v] = before[v] * densityFieldWeight(layer, volume.lattice.centre(std::uint32_t(v)), 0.2);
    largest = std::max(largest, weighted[v]);
  }
  for (std::size_t v = 0; v < before.size(); ++v) EXPECT_NEAR(volume.density[v], weighted[v] / largest, 1e-5);
}

TEST(FieldLayers, EditsAddSetAndRemoveLayers) {
  Project p = parseProject(kLayeredScene);
  p.volume.reset();
  applyEdit(p, AddFieldLayer{FieldRole::Terrain});
  applyEdit(p, AddFieldLayer{FieldRole::Cloud});
  ASSERT_EQ(fieldLayerCount(p), 2u);
  EXPECT_EQ(fieldLayerAt(p, 0)->role, FieldRole::Terrain);
  EXPECT_EQ(fieldLayerAt(p, 1)->role, FieldRole::Cloud);
  VolumeDensityField changed = *fieldLayerAt(p, 1);
  changed.field.octaves = 9;
  applyEdit(p, SetFieldLayer{1, changed});
  EXPECT_EQ(fieldLayerAt(p, 1)->field.octaves, 9);
  p.tracks["volume.field[0].strength"] = KeyframeTrack{{{0.0, 0.5}}};
  p.tracks["volume.field[1].gain"] = KeyframeTrack{{{0.0, 0.4}}};
  applyEdit(p, RemoveFieldLayer{0});
  ASSERT_EQ(fieldLayerCount(p), 1u);
  EXPECT_EQ(fieldLayerAt(p, 0)->role, FieldRole::Cloud);
  // The removed layer's track goes; the other follows its layer, now the single field.
  ASSERT_EQ(p.tracks.size(), 1u);
  EXPECT_EQ(p.tracks.begin()->first, "volume.field.gain");
  applyEdit(p, AddFieldLayer{FieldRole::Density});
  EXPECT_EQ(p.tracks.begin()->first, "volume.field[0].gain");
  EXPECT_THROW(applyEdit(p, SetFieldLayer{3, changed}), ModelError);
  EXPECT_EQ(editLabel(AddFieldLayer{FieldRole::Cloud}), "Add cloud layer");
}
