// GUI tier for the preview's display modes: the flame display (no chaos-game restart), the
// deterministic mesh preview F^n(A), and File > Export mesh… through the real window with xdotool,
// the file checked by loading it back with OpenMesh. The harness is gui/gui_harness.h.
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <set>
#include <tuple>

#include "mesh/mesh_io.h"

#include "gui/gui_harness.h"

using namespace gridifs::gui_test;

// The flame display is a second picture of the same chaos game: switching shows a
// different, non-empty image without restarting the renderer, and the choice is one undo step.
TEST(PreviewModesGui, FlameModeShowsADifferentPictureWithoutRestart) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "sierpinski_tetrahedron.gridifs", 1'000'000);
  App app(home, {project.string()});
  nlohmann::json probe = app.waitForPreview();  // niced workers: slow on a busy machine
  ASSERT_TRUE(probe["preview"]["done"].get<bool>());
  const Rect image = rectOf(probe, "preview.image");
  const auto zbuffer = grabSettled(home, image);
  const std::uint64_t restarts = probe["preview"]["restarts"];

  clickRect(rectOf(probe, "preview.mode.flame"));
  probe = app.waitFor(
      [](const nlohmann::json& j) {
        return j["preview_modes"]["mode"] == "flame" && j["preview_modes"]["flame_developed"].get<int>() >= 1 &&
               j["preview"]["done"].get<bool>();
      },
      90s);
  ASSERT_EQ(probe["preview_modes"]["mode"], "flame");
  std::this_thread::sleep_for(500ms);  // the last develop after the budget is reached
  probe = app.probe();
  EXPECT_EQ(probe["preview"]["restarts"].get<std::uint64_t>(), restarts) << "the mode switch restarted the chaos game";
  EXPECT_EQ(probe["undo"], "Flame display");
  EXPECT_EQ(probe["preview_modes"]["flame_error"], "");
  const auto flame = grabScreen(home, image);
  EXPECT_GT(litFraction(flame), 0.02) << "the flame picture looks empty";
  EXPECT_GT(meanAbsDifference(zbuffer, flame), 2.0) << "the flame picture is the z-buffer picture";

  // Tone mapping: one brightness drag is one undo step, re-develops the picture, no restart.
  clickRect(rectOf(probe, "flame.tone"));
  // The popup opens at the mouse and is moved inside the screen once its size is known: take the
  // slider's rectangle only after it has settled.
  const std::optional<Rect> slider = app.waitForStableRect("flame.Brightness");
  ASSERT_TRUE(slider) << "the tone popup did not open";
  const int developed = app.probe()["preview_modes"]["flame_developed"];
  const int y = slider->y + slider->h / 2, x0 = slider->x + slider->w / 2;
  dragFrom(x0, y, x0 + 8 * slider->w / 20, y, 8);
  probe = app.waitFor([&](const nlohmann::json& j) {
    return j["undo"] == "Brightness" && j["preview_modes"]["flame_developed"].get<int>() > developed &&
           j["preview_modes"]["flame_busy"] == false;
  });
  EXPECT_EQ(probe["undo"], "Brightness");
  EXPECT_EQ(probe["preview"]["restarts"].get<std::uint64_t>(), restarts) << "tone mapping restarted the chaos game";
  EXPECT_GT(probe["preview_modes"]["flame_developed"].get<int>(), developed);
  xdotool("keydown Escape sleep 0.15 keyup Escape");  // close the popup (held: ImGui 1.86 has no input queue)
  std::this_thread::sleep_for(500ms);
  const auto brighter = grabScreen(home, image);
  EXPECT_GT(meanAbsDifference(flame, brighter), 1.0) << "the brightness drag did not change the picture";

  // Back to the z-buffer: the same picture as before, still without a restart.
  clickRect(rectOf(probe, "preview.mode.zbuffer"));
  probe = app.waitFor([](const nlohmann::json& j) { return j["preview_modes"]["mode"] == "zbuffer"; }, 10s);
  ASSERT_EQ(probe["preview_modes"]["mode"], "zbuffer");
  const auto back = grabSettled(home, image);
  EXPECT_LT(meanAbsDifference(zbuffer, back), 0.5) << describeDifference(zbuffer, back, image);
  EXPECT_EQ(app.probe()["preview"]["restarts"].get<std::uint64_t>(), restarts);
}

// The deterministic preview draws F^n(A) as a lit mesh (many shades, not a flat fill).
TEST(PreviewModesGui, MeshModeDrawsTheDeterministicMesh) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "sierpinski_tetrahedron.gridifs", 200'000);
  App app(home, {project.string()});
  nlohmann::json probe = app.waitForPreview();  // niced workers: slow on a busy machine
  ASSERT_TRUE(probe["preview"]["done"].get<bool>());
  clickRect(rectOf(probe, "preview.mode.mesh"));
  probe = app.waitFor([](const nlohmann::json& j) {
    const auto& m = j["preview_modes"];
    return m["mode"] == "mesh" && m["mesh_faces"].get<std::uint64_t>() > 0 && !m["mesh_building"].get<bool>();
  });
  const auto& m = probe["preview_modes"];
  ASSERT_EQ(m["mesh_error"], "");
  ASSERT_GT(m["mesh_faces"].get<std::uint64_t>(), 0u);
  // 4 functions, the cube subdivided once (24 quads): 4^n × 24 faces.
  const int depth = m["mesh_depth"];
  EXPECT_EQ(m["mesh_faces"].get<std::uint64_t>(), std::uint64_t(std::pow(4.0, depth)) * 24u);
  std::this_thread::sleep_for(400ms);
  const auto px = grabScreen(home, rectOf(probe, "preview.image"));
  EXPECT_GT(litFraction(px), 0.02) << "no mesh in the preview";
  std::set<int> shades;  // lit faces: many distinct intensities
  for (std::size_t i = 0; i < px.size(); i += 3)
    if (px[i] + px[i + 1] + px[i + 2] > 0.3f) shades.insert(int((px[i] + px[i + 1] + px[i + 2]) * 40.0f));
  EXPECT_GT(shades.size(), 10u) << "the mesh is not shaded";
}

// File > Export mesh… with real input: type the output path, export, and the PLY
// loads back through OpenMesh with the planned face count and vertex colors.
TEST(PreviewModesGui, ExportMeshThroughTheMenuWritesAPlyThatLoadsBack) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "sierpinski_tetrahedron.gridifs", 200'000);
  const fs::path out = home.path / "exported.ply";
  App app(home, {project.string()});
  nlohmann::json probe = app.waitForPreview();  // niced workers: slow on a busy machine
  ASSERT_TRUE(probe["preview"]["done"].get<bool>());
  // The File menu is the first entry of the main menu bar.
  const int wx = probe["window"]["x"], wy = probe["window"]["y"];
  clickAt(wx + 18, wy + 9);
  const std::optional<Rect> menuItem = app.waitForStableRect("menu.export_mesh");
  ASSERT_TRUE(menuItem) << "the File menu did not open";
  clickRect(*menuItem);
  // The dialog sizes itself to its contents in its first frames.
  const std::optional<Rect> output = app.waitForStableRect("export.output");
  ASSERT_TRUE(output) << "the export dialog did not open";
  // Replace the suggested path. On a busy machine a click, the select-all or the first typed
  // keys can fall between frames, so the text is checked through the probe and typed again
  // if it did not come out whole.
  for (int attempt = 0; attempt < 3; ++attempt) {
    clickRect(*output);
    run("xdotool search --name GridIFS windowfocus >/dev/null 2>&1");
    std::this_thread::sleep_for(200ms);
    // Held for a moment: ImGui 1.86 has no input queue, a tap can fall between two frames.
    xdotool("keydown ctrl+a sleep 0.15 keyup ctrl+a");
    std::this_thread::sleep_for(200ms);
    xdotool("type --delay 15 '" + out.string() + "'");
    probe = app.waitFor([&](const nlohmann::json& j) { return j["export"]["output"] == out.string(); }, 5s);
    if (probe["export"]["output"] == out.string()) break;
  }
  ASSERT_EQ(probe["export"]["output"], out.string()) << "the typed path did not arrive";
  const std::optional<Rect> exportButton = app.waitForStableRect("export.run");
  ASSERT_TRUE(exportButton);
  clickRect(*exportButton);
  probe = app.waitFor([](const nlohmann::json& j) {
    const std::string phase = j["export"]["phase"];
    return phase == "done" || phase == "failed";
  });
  ASSERT_EQ(probe["export"]["phase"], "done") << probe["export"]["message"];
  ASSERT_TRUE(fs::exists(out)) << probe["export"]["message"];
  gridifs::IfsMesh mesh;
  mesh.request_vertex_colors();
  OpenMesh::IO::Options options = OpenMesh::IO::Options::VertexColor;
  ASSERT_TRUE(OpenMesh::IO::read_mesh(mesh, out.string(), options));
  EXPECT_EQ(mesh.n_faces(), 4u * 4u * 4u * 6u);  // depth 3 of a 4-map IFS on the cube
  EXPECT_EQ(mesh.n_vertices(), 4u * 4u * 4u * 8u);
  EXPECT_TRUE(options.check(OpenMesh::IO::Options::VertexColor));
  std::set<std::tuple<float, float, float>> colors;  // the functions' structural colors
  for (auto vh : mesh.vertices()) colors.insert({mesh.color(vh)[0], mesh.color(vh)[1], mesh.color(vh)[2]});
  EXPECT_GT(colors.size(), 1u);
  for (const auto& entry : fs::directory_iterator(home.path))  // no temporary left behind
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
}
