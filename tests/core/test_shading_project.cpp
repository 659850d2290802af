// Shading settings in the project file: "render": {"mode": "shaded", "shading": {...}}.
#include <gtest/gtest.h>

#include "io/project_io.h"

using namespace gridifs;

namespace {
std::string withShadedRender(const std::string& render) {
  return R"({"format": "gridifs", "version": 1, "render": )" + render + R"(, "functions": [{"name": "f1"}]})";
}
std::string errorFor(const std::string& render, const std::string& path) {
  try {
    parseProject(withShadedRender(render));
    ADD_FAILURE() << "no error for " << render;
  } catch (const ModelError& e) {
    EXPECT_EQ(e.path(), path) << e.what();
    return e.what();
  }
  return {};
}
}  // namespace

TEST(ShadingProject, OldFilesLoadWithDefaults) {
  const Project p = parseProject(withShadedRender(R"({"width": 64, "height": 48})"));
  EXPECT_EQ(p.render.shading, ShadingSettings{});
  ASSERT_EQ(p.render.shading.lights.size(), 1u);
  EXPECT_TRUE(p.render.shading.lights[0].shadows);
  EXPECT_FALSE(p.render.shading.dof.focus.has_value());
}

TEST(ShadingProject, ParsesTheDocumentedExampleAndRoundTrips) {
  const Project p = parseProject(withShadedRender(R"({"mode": "shaded", "shading": {
      "lights": [{"direction": [0.3, -0.5, 1], "color": [1, 0.9, 0.8], "intensity": 1.2, "shadows": true},
                 {"direction": [-1, 0, 0.2], "color": [0.2, 0.3, 1], "intensity": 0.4, "shadows": false}],
      "ambient": 0.2, "specular": 0.4, "shininess": 48,
      "ao": {"radius": 10, "strength": 0.6, "directions": 6},
      "fog": {"color": [0.1, 0.1, 0.2], "density": 0.05},
      "dof": {"aperture": 0.02, "focus": 3.5}}})"));
  EXPECT_EQ(p.render.mode, DisplayMode::Shaded);
  const ShadingSettings& s = p.render.shading;
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_EQ(s.lights[0].direction, Vec3(0.3, -0.5, 1.0));
  EXPECT_EQ(s.lights[0].color, Vec3(1.0, 0.9, 0.8));
  EXPECT_EQ(s.lights[0].intensity, 1.2);
  EXPECT_TRUE(s.lights[0].shadows);
  EXPECT_FALSE(s.lights[1].shadows);
  EXPECT_EQ(s.ambient, 0.2);
  EXPECT_EQ(s.specular, 0.4);
  EXPECT_EQ(s.shininess, 48.0);
  EXPECT_EQ(s.ao.radius, 10.0);
  EXPECT_EQ(s.ao.strength, 0.6);
  EXPECT_EQ(s.ao.directions, 6);
  EXPECT_EQ(s.fog.color, Vec3(0.1, 0.1, 0.2));
  EXPECT_EQ(s.fog.density, 0.05);
  EXPECT_EQ(s.dof.aperture, 0.02);
  EXPECT_EQ(s.dof.focus, 3.5);
  EXPECT_EQ(parseProject(serializeProject(p)), p);
  // Partial objects keep the other defaults; no lights at all is allowed (ambient only).
  const Project q = parseProject(withShadedRender(R"({"shading": {"lights": [], "ao": {"strength": 0}}})"));
  EXPECT_TRUE(q.render.shading.lights.empty());
  EXPECT_EQ(q.render.shading.ao.radius, AmbientOcclusionSettings{}.radius);
  EXPECT_EQ(parseProject(serializeProject(q)), q);
}

TEST(ShadingProject, BadInputIsOneSentenceWithTheJsonPath) {
  const std::string four = R"({"direction": [0, 0, 1]})";
  EXPECT_NE(errorFor(R"({"shading": {"lights": [)" + four + "," + four + "," + four + "," + four + "]}}",
                     "render.shading.lights")
                .find("at most 3 lights"),
            std::string::npos);
  EXPECT_NE(errorFor(R"({"shading": {"lights": [{"direction": [0, 0, 0]}]}})", "render.shading.lights[0].direction")
                .find("zero length"),
            std::string::npos);
  EXPECT_NE(errorFor(R"({"shading": {"ao": {"radius": -1}}})", "render.shading.ao.radius").find("negative"),
            std::string::npos);
  EXPECT_NE(errorFor(R"({"shading": {"ao": {"strength": -0.5}}})", "render.shading.ao.strength").find("negative"),
            std::string::npos);
  EXPECT_NE(errorFor(R"({"shading": {"dof": {"aperture": 0.1}}})", "render.shading.dof.focus").find("focus"),
            std::string::npos);
  errorFor(R"({"shading": {"lights": [{"intensity": -1}]}})", "render.shading.lights[0].intensity");
  errorFor(R"({"shading": {"lights": [{"color": [2, 0, 0]}]}})", "render.shading.lights[0].color[0]");
  errorFor(R"({"shading": {"lights": {"direction": [0, 0, 1]}}})", "render.shading.lights");
  errorFor(R"({"shading": {"ao": {"directions": 2.5}}})", "render.shading.ao.directions");
  errorFor(R"({"shading": {"fog": {"density": -1}}})", "render.shading.fog.density");
  errorFor(R"({"shading": {"shininess": 0}})", "render.shading.shininess");
  errorFor(R"({"shading": []})", "render.shading");
  errorFor(R"({"mode": "lit"})", "render.mode");
}

TEST(ShadingProject, SavingRefusesWhatReadingWould) {
  Project p = defaultNewProject();
  p.render.shading.lights.assign(4, ShadingLight{});
  EXPECT_THROW(validateProject(p), ModelError);
  p.render.shading.lights.resize(1);
  p.render.shading.dof.aperture = 0.1;
  EXPECT_THROW(validateProject(p), ModelError);
  p.render.shading.dof.focus = 4.0;
  EXPECT_NO_THROW(validateProject(p));
}
