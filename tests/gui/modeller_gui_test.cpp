// GUI tier: the real modeller window under Xvfb + Mesa, real frames, real input through xdotool,
// assertions on pixels and on the saved file. Run by scripts/test as
// `xvfb-run -a -s "-screen 0 1600x1000x24" ctest -L gui`. The harness is gui/gui_harness.h.
#include <sys/stat.h>

#include <glm/geometric.hpp>

#include "gui/gui_harness.h"

using namespace gridifs::gui_test;

TEST(ModellerGui, ScreenshotShowsGridViewsAndPreview) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "default.gridifs");
  const fs::path shot = home.path / "shot.png";
  App app(home, {project.string(), "--screenshot", shot.string(), "--frames", "10", "--wait-points", "1000000"});
  ASSERT_EQ(app.waitExit(60s), 0);
  const nlohmann::json probe = app.probe();
  EXPECT_NE(probe["title"].get<std::string>().find("GridIFS"), std::string::npos);

  OIIO::ImageBuf image(shot.string());
  ASSERT_TRUE(image.init_spec(shot.string(), 0, 0)) << image.geterror();
  EXPECT_EQ(image.spec().width, probe["window"]["width"].get<int>());
  auto region = [&](const std::string& name) {
    const auto& r = probe["rects"][name];
    const int x = int(r[0].get<double>()), y = int(r[1].get<double>()), w = int(r[2].get<double>()),
              h = int(r[3].get<double>());
    std::vector<float> px(std::size_t(w) * h * 3);
    image.get_pixels(OIIO::ROI(x, x + w, y, y + h, 0, 1, 0, 3), OIIO::TypeDesc::FLOAT, px.data());
    return px;
  };
  // The preview shows the attractor: many pixels well away from the dark background.
  const auto preview = region("preview.image");
  std::size_t lit = 0;
  for (std::size_t i = 0; i < preview.size(); i += 3)
    if (preview[i] + preview[i + 1] + preview[i + 2] > 0.3f) ++lit;
  EXPECT_GT(double(lit) / double(preview.size() / 3), 0.03) << "the preview looks empty";
  // Each grid view shows grid lines and light nodes over its dark gradient.
  for (const char* view : {"view.Top", "view.Side", "view.Front", "view.User", "view.ifs"}) {
    const auto px = region(view);
    std::size_t bright = 0;
    for (std::size_t i = 0; i < px.size(); i += 3)
      if (px[i] + px[i + 1] + px[i + 2] > 1.5f) ++bright;
    EXPECT_GT(bright, 200u) << view << " shows no grid";
  }
}

TEST(ModellerGui, TwistSliderDragUndoAndSave) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "default.gridifs");
  const double originalK = std::get<gridifs::TwistOp>(gridifs::loadProject(project).functions[0].ops[0].params).k;
  App app(home, {project.string()});
  nlohmann::json probe = app.waitForPreview();
  ASSERT_TRUE(probe["preview"]["done"].get<bool>());
  const Rect previewRect = rectOf(probe, "preview.image");
  const auto before = grabScreen(home, previewRect);

  // Pick the twist in the stack and drag its k slider (one gesture = one undo step).
  const Rect row = rectOf(probe, "ops.row.0");
  clickAt(row.x + row.w / 2, row.y + row.h / 2);
  const std::optional<Rect> twistK = app.waitForStableRect("twist.k");
  ASSERT_TRUE(twistK) << "the twist's parameters are not shown";
  const Rect slider = *twistK;
  const std::uint64_t restarts = app.probe()["preview"]["restarts"];
  const int grab = slider.x + int(slider.w * (0.5 + originalK / (4.0 * M_PI)));  // the k = original spot
  dragFrom(grab, slider.y + slider.h / 2, grab + slider.w / 4, slider.y + slider.h / 2);
  probe = app.waitForPreview(restarts);
  EXPECT_EQ(probe["undo"], "twist k");
  EXPECT_TRUE(probe["dirty"].get<bool>());
  EXPECT_NE(probe["title"].get<std::string>().find('*'), std::string::npos);
  const auto twisted = grabScreen(home, previewRect);
  EXPECT_GT(meanAbsDifference(before, twisted), 1.0) << "the preview did not change with the twist";

  // Undo returns the model and the picture.
  pressKeys("ctrl+z");
  probe = app.waitForPreview(probe["preview"]["restarts"].get<std::uint64_t>());
  EXPECT_FALSE(probe["dirty"].get<bool>());
  const auto undone = grabScreen(home, previewRect);
  EXPECT_LT(meanAbsDifference(before, undone), 0.05) << "undo did not restore the preview";

  // Redo, save with Ctrl+S, and the file loads back with the edit.
  pressKeys("ctrl+shift+z");
  probe = app.waitFor([](const nlohmann::json& j) { return j["dirty"].get<bool>(); });
  pressKeys("ctrl+s");
  probe = app.waitFor([](const nlohmann::json& j) { return !j["dirty"].get<bool>(); });
  EXPECT_FALSE(probe["dirty"].get<bool>());
  const gridifs::Project saved = gridifs::loadProject(project);
  const double savedK = std::get<gridifs::TwistOp>(saved.functions[0].ops[0].params).k;
  EXPECT_GT(savedK, originalK + 0.5);
  EXPECT_TRUE(fs::exists(project.string() + "~"));

  pressKeys("ctrl+q");  // nothing unsaved: quits without asking
  EXPECT_EQ(app.waitExit(), 0);
}

TEST(ModellerGui, DraggingANodeRecordsANodesOperation) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "default.gridifs");
  const std::size_t opsBefore = gridifs::loadProject(project).functions[0].ops.size();
  App app(home, {project.string()});
  nlohmann::json probe = app.waitForPreview();
  const auto& nodes = probe["nodes_top"];
  ASSERT_GT(nodes.size(), 10u);
  const int wx = probe["window"]["x"], wy = probe["window"]["y"];
  // The outermost node on the left of the top view is not hidden behind others.
  std::size_t pick = 0;
  for (std::size_t n = 0; n < nodes.size(); ++n)
    if (nodes[n][0].get<double>() < nodes[pick][0].get<double>()) pick = n;
  const int x = wx + int(std::lround(nodes[pick][0].get<double>())),
            y = wy + int(std::lround(nodes[pick][1].get<double>()));
  const std::uint64_t restarts = probe["preview"]["restarts"];
  dragFrom(x, y, x - 30, y + 20);
  probe = app.waitForPreview(restarts);
  EXPECT_EQ(probe["undo"], "Move nodes");
  EXPECT_EQ(probe["ops"].get<std::size_t>(), opsBefore + 1);
  pressKeys("ctrl+s");
  probe = app.waitFor([](const nlohmann::json& j) { return !j["dirty"].get<bool>(); });
  const gridifs::Project saved = gridifs::loadProject(project);
  ASSERT_EQ(saved.functions[0].ops.size(), opsBefore + 1);
  const auto* moves = std::get_if<gridifs::NodesOp>(&saved.functions[0].ops.back().params);
  ASSERT_NE(moves, nullptr);
  ASSERT_EQ(moves->moves.size(), 1u);
  EXPECT_GT(glm::length(moves->moves[0].displacement), 0.05);
}

TEST(ModellerGui, SaveIntoReadOnlyFolderKeepsTheOldFileAndShowsAnError) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path folder = home.path / "locked";
  fs::create_directories(folder);
  gridifs::Project p = gridifs::loadProject(fs::path(GRIDIFS_ASSETS) / "default.gridifs");
  p.render.samples = 500'000;
  const fs::path project = folder / "plate.gridifs";
  gridifs::saveProject(p, project);
  std::string original;
  {
    std::ifstream in(project);
    original.assign(std::istreambuf_iterator<char>(in), {});
  }
  App app(home, {project.string()});
  nlohmann::json probe = app.waitForPreview();
  // Read-only folder: permissions for a normal user; root ignores them, so also immutable.
  ::chmod(folder.c_str(), 0555);
  if (::geteuid() == 0) run("chattr +i '" + folder.string() + "' 2>/dev/null");

  const Rect add = rectOf(probe, "functions.add");
  clickAt(add.x + add.w / 2, add.y + add.h / 2);
  probe = app.waitFor([](const nlohmann::json& j) { return j["dirty"].get<bool>(); });
  ASSERT_TRUE(probe["dirty"].get<bool>());
  pressKeys("ctrl+s");
  probe = app.waitFor([](const nlohmann::json& j) { return j["modal"].get<bool>(); }, 10s);
  EXPECT_TRUE(probe["modal"].get<bool>()) << "no error dialog";
  EXPECT_TRUE(probe["status_error"].get<bool>());
  EXPECT_NE(probe["status"].get<std::string>().find("Could not save"), std::string::npos) << probe["status"];
  EXPECT_TRUE(probe["dirty"].get<bool>()) << "a failed save must not mark the project saved";

  if (::geteuid() == 0) run("chattr -i '" + folder.string() + "' 2>/dev/null");
  ::chmod(folder.c_str(), 0755);
  std::string after;
  {
    std::ifstream in(project);
    after.assign(std::istreambuf_iterator<char>(in), {});
  }
  EXPECT_EQ(after, original) << "the old file changed";
  EXPECT_EQ(gridifs::loadProject(project).functions.size(), p.functions.size());
}

TEST(ModellerGui, AutosaveIsOfferedBackAfterACrash) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "default.gridifs", 300'000);
  const std::size_t functions = gridifs::loadProject(project).functions.size();
  {
    App app(home, {project.string(), "--autosave-seconds", "1"});
    nlohmann::json probe = app.waitForPreview();
    const Rect add = rectOf(probe, "functions.add");
    clickAt(add.x + add.w / 2, add.y + add.h / 2);
    probe = app.waitFor([](const nlohmann::json& j) { return j["dirty"].get<bool>(); });
    ASSERT_TRUE(probe["dirty"].get<bool>());
    // Wait for the autosave, then "crash" (App's destructor kills the process with SIGKILL).
    const fs::path state = home.path / "state" / "gridifs";
    const auto end = std::chrono::steady_clock::now() + 20s;
    bool saved = false;
    while (!saved && std::chrono::steady_clock::now() < end) {
      std::error_code ec;
      for (fs::directory_iterator it(state, ec); !ec && it != fs::directory_iterator(); it.increment(ec))
        saved = saved || it->path().extension() == ".gridifs";
      std::this_thread::sleep_for(200ms);
    }
    ASSERT_TRUE(saved) << "no recovery file in " << state;
  }
  App again(home, {});
  // Popups settle their size and position over a few frames: wait until the button stays put.
  const std::optional<Rect> recover = again.waitForStableRect("recovery.recover", 30s);
  ASSERT_TRUE(recover) << "no offer to recover";
  clickRect(*recover);
  nlohmann::json probe =
      again.waitFor([&](const nlohmann::json& j) { return j["functions"].get<std::size_t>() == functions + 1; });
  EXPECT_EQ(probe["functions"].get<std::size_t>(), functions + 1);
  EXPECT_TRUE(probe["dirty"].get<bool>()) << "recovered work must count as unsaved";
  EXPECT_EQ(fs::path(probe["path"].get<std::string>()), fs::absolute(project));
}

TEST(ModellerGui, AFileThatDoesNotLoadIsReportedNotFatal) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path bad = home.path / "bad.gridifs";
  std::ofstream(bad)
      << R"({"format": "gridifs", "version": 1, "functions": [{"name": "f", "resolution": [6, 6, "x"]}]})";
  App app(home, {bad.string()});
  const nlohmann::json probe = app.waitFor([](const nlohmann::json& j) { return j["modal"].get<bool>(); }, 15s);
  EXPECT_TRUE(probe["modal"].get<bool>()) << "no error dialog";
  const std::string status = probe["status"];
  EXPECT_NE(status.find("functions[0].resolution[2]"), std::string::npos) << status;
  EXPECT_EQ(probe["functions"].get<int>(), 1) << "the default project stays open";
  EXPECT_EQ(probe["path"], "");
}

TEST(ModellerGui, ImportFlameFromTheFileMenu) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  App app(home, {exampleCopy(home, "default.gridifs").string()});
  nlohmann::json probe = app.waitForPreview();
  auto importFile = [&](const fs::path& file) {
    // The browser opens in the document's folder: the artist types a short name there.
    fs::copy_file(file, home.path / file.filename(), fs::copy_options::overwrite_existing);
    focusWindow();
    clickAt(probe["window"]["x"].get<int>() + 20, probe["window"]["y"].get<int>() + 10);  // File
    probe = app.waitFor([](const nlohmann::json& j) { return j["rects"].contains("menu.import_flame"); }, 10s);
    ASSERT_TRUE(probe["rects"].contains("menu.import_flame")) << "the File menu did not open";
    const Rect item = rectOf(probe, "menu.import_flame");
    clickAt(item.x + item.w / 2, item.y + item.h / 2);
    probe = app.waitFor(
        [](const nlohmann::json& j) { return j["modal"].get<bool>() && j["rects"].contains("browser.fileName"); }, 10s);
    ASSERT_TRUE(probe["rects"].contains("browser.fileName")) << "the file browser did not open";
    std::this_thread::sleep_for(500ms);  // the dialog places itself in its first frames
    const Rect name = rectOf(app.probe(), "browser.fileName");
    clickAt(name.x + name.w / 2, name.y + name.h / 2);
    focusWindow();
    xdotool("type --delay 15 '" + file.filename().string() + "'");
    std::this_thread::sleep_for(300ms);
    pressKeys("Return");
  };
  // A broken file: an error in the window, the document unchanged.
  importFile(fs::path(GRIDIFS_TEST_DATA) / "flame" / "bad" / "missing_coefs.flame");
  probe = app.waitFor(
      [](const nlohmann::json& j) {
        return j["modal"].get<bool>() && j["status"].get<std::string>().find("Could not import") != std::string::npos;
      },
      15s);
  EXPECT_NE(probe["status"].get<std::string>().find("has no coefs"), std::string::npos) << probe["status"];
  EXPECT_EQ(probe["functions"].get<int>(), 4);
  EXPECT_FALSE(probe["dirty"].get<bool>());
  pressKeys("Escape");
  probe = app.waitFor([](const nlohmann::json& j) { return !j["modal"].get<bool>(); }, 10s);
  ASSERT_FALSE(probe["modal"].get<bool>());
  // A good one: a new, unsaved document with its functions, one undo step.
  importFile(fs::path(GRIDIFS_TEST_DATA) / "flame" / "sierpinski_chaos.flam3");
  probe = app.waitFor([](const nlohmann::json& j) { return j["functions"].get<int>() == 3 && !j["modal"].get<bool>(); },
                      20s);
  EXPECT_EQ(probe["functions"].get<int>(), 3);
  EXPECT_EQ(probe["undo"], "Import flame");
  EXPECT_TRUE(probe["dirty"].get<bool>());
  EXPECT_EQ(probe["path"], "");
  EXPECT_NE(probe["status"].get<std::string>().find("Imported sierpinski-no-repeat"), std::string::npos)
      << probe["status"];
}
