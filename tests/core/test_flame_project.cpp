// Flame settings in the project file: "render": {"mode": "flame", "flame": {...}}.
#include <gtest/gtest.h>

#include "io/project_io.h"

using namespace gridifs;

namespace {
std::string withRender(const std::string& render) {
  return R"({"format": "gridifs", "version": 1, "render": )" + render + R"(, "functions": [{"name": "f1"}]})";
}
void expectError(const std::string& render, const std::string& path) {
  try {
    parseProject(withRender(render));
    ADD_FAILURE() << "no error for " << render;
  } catch (const ModelError& e) {
    EXPECT_EQ(e.path(), path) << e.what();
  }
}
}  // namespace

TEST(FlameProject, OldFilesLoadWithDefaults) {
  const Project p = parseProject(withRender(R"({"width": 64, "height": 48})"));
  EXPECT_EQ(p.render.mode, DisplayMode::ZBuffer);
  EXPECT_EQ(p.render.flame, FlameSettings{});
  EXPECT_EQ(p.render.flame.palette, "ember");
}

TEST(FlameProject, ParsesAndRoundTrips) {
  const Project p = parseProject(withRender(R"({"mode": "flame", "flame": {"palette": "flam3:27",
      "brightness": 6.5, "gamma": 2.2, "gamma_threshold": 0.02, "vibrancy": 0.7, "highlight_power": -1,
      "supersample": 3, "estimator_radius": 5, "estimator_minimum": 0.5, "estimator_curve": 0.6,
      "filter_radius": 0.8}})"));
  EXPECT_EQ(p.render.mode, DisplayMode::Flame);
  const FlameSettings& f = p.render.flame;
  EXPECT_EQ(f.palette, "flam3:27");
  EXPECT_EQ(f.brightness, 6.5);
  EXPECT_EQ(f.gamma, 2.2);
  EXPECT_EQ(f.gamma_threshold, 0.02);
  EXPECT_EQ(f.vibrancy, 0.7);
  EXPECT_EQ(f.highlight_power, -1.0);
  EXPECT_EQ(f.supersample, 3);
  EXPECT_EQ(f.estimator_radius, 5.0);
  EXPECT_EQ(f.estimator_minimum, 0.5);
  EXPECT_EQ(f.estimator_curve, 0.6);
  EXPECT_EQ(f.filter_radius, 0.8);
  EXPECT_EQ(parseProject(serializeProject(p)), p);
  // Partial objects keep the other defaults.
  const Project q = parseProject(withRender(R"({"flame": {"gamma": 3}})"));
  EXPECT_EQ(q.render.flame.gamma, 3.0);
  EXPECT_EQ(q.render.flame.brightness, FlameSettings{}.brightness);
  EXPECT_EQ(parseProject(serializeProject(q)), q);
}

TEST(FlameProject, ErrorsNameTheJsonPath) {
  expectError(R"({"mode": "density"})", "render.mode");
  expectError(R"({"mode": 3})", "render.mode");
  expectError(R"({"flame": []})", "render.flame");
  expectError(R"({"flame": {"palette": "no-such"}})", "render.flame.palette");
  expectError(R"({"flame": {"palette": 7}})", "render.flame.palette");
  expectError(R"({"flame": {"gamma": 0}})", "render.flame.gamma");
  expectError(R"({"flame": {"vibrancy": 1.5}})", "render.flame.vibrancy");
  expectError(R"({"flame": {"supersample": 0}})", "render.flame.supersample");
  expectError(R"({"flame": {"supersample": 2.5}})", "render.flame.supersample");
  expectError(R"({"flame": {"estimator_radius": -1}})", "render.flame.estimator_radius");
  expectError(R"({"flame": {"estimator_radius": 2, "estimator_minimum": 3}})", "render.flame.estimator_minimum");
  expectError(R"({"flame": {"estimator_radius": 60, "supersample": 8, "estimator_curve": 0.05}})",
              "render.flame.estimator_curve");
  expectError(R"({"flame": {"filter_radius": "wide"}})", "render.flame.filter_radius");
}

TEST(FlameProject, ValidationRefusesFlameSettingsThatCouldNotBeReadBack) {
  Project p = parseProject(withRender("{}"));
  p.render.flame.supersample = 0;
  try {
    validateProject(p);
    ADD_FAILURE() << "supersample 0 accepted";
  } catch (const ModelError& e) {
    EXPECT_EQ(e.path(), "render.flame.supersample");
  }
  p.render.flame.supersample = 2;
  p.render.flame.palette = "nonsense";
  EXPECT_THROW(validateProject(p), ModelError);
  p.render.flame.palette = "ice";
  p.render.flame.gamma = 0.0;
  EXPECT_THROW(validateProject(p), ModelError);
  p.render.flame.gamma = 2.2;
  EXPECT_NO_THROW(validateProject(p));
}
