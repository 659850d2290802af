// Flame variations in the modeller: the Variations section of a function adds swirl from its
// searchable list (one undo step, the preview restarts), a drag of its weight is one more undo
// step saved in the file's "variations", and undo takes both back to the original file.
#include "gui_harness.h"

using namespace gridifs::gui_test;

namespace {

/// Scrolls the Functions panel (whose Name field was at `anchor` before any scrolling) until
/// `item` is in sight and returns its place.
std::optional<Rect> scrollTo(App& app, const Rect& anchor, const std::string& item) {
  for (int tries = 0; tries < 15; ++tries) {
    const nlohmann::json probe = app.waitFor([](const nlohmann::json&) { return true; });
    if (probe["rects"].contains(item)) {
      const Rect r = rectOf(probe, item);
      // In sight: below the panel's title and above the Operations panel below it.
      if (r.w > 0 && r.y > anchor.y - 100 && r.y + r.h < anchor.y + 240) return app.waitForStableRect(item);
    }
    run("xdotool mousemove " + std::to_string(anchor.x + anchor.w / 2) + " " + std::to_string(anchor.y + 60) +
        " click --repeat 2 5");
  }
  return std::nullopt;
}

}  // namespace

TEST(VariationsGui, AddSwirlDragItsWeightAndUndo) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "sierpinski_tetrahedron.gridifs");
  const std::string original = fileText(project);
  App app(home, {project.string()});
  nlohmann::json probe = app.waitForPreview();

  const std::optional<Rect> anchor = app.waitForStableRect("function.name");
  ASSERT_TRUE(anchor) << "no Functions panel";
  const std::optional<Rect> header = scrollTo(app, *anchor, "variations.header");
  ASSERT_TRUE(header) << "no Variations section in the Functions panel";
  clickRect(*header);
  const std::optional<Rect> filter = scrollTo(app, *anchor, "variations.filter");
  ASSERT_TRUE(filter) << "the Variations section has no search field";
  clickRect(*filter);
  xdotool("type --delay 40 swi");
  const std::optional<Rect> swirl = scrollTo(app, *anchor, "variations.add.swirl");
  ASSERT_TRUE(swirl) << "swirl is not in the searched list";
  std::uint64_t restarts = probe["preview"]["restarts"];
  clickRect(*swirl);
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Add variation swirl"; });
  ASSERT_EQ(probe["undo"], "Add variation swirl");
  probe = app.waitForPreview(restarts);  // the preview restarts live
  saveAndWait(app);
  EXPECT_EQ(gridifs::loadProject(project).functions[0].variations, (std::map<std::string, double>{{"swirl", 1.0}}));

  const std::optional<Rect> weight = scrollTo(app, *anchor, "variations.weight.swirl");
  ASSERT_TRUE(weight) << "no weight slider for swirl";
  restarts = probe["preview"]["restarts"];
  dragFrom(weight->x + weight->w / 2, weight->y + weight->h / 2, weight->x + weight->w / 2 - 60,
           weight->y + weight->h / 2);
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Variation weight"; });
  ASSERT_EQ(probe["undo"], "Variation weight");
  probe = app.waitForPreview(restarts);
  saveAndWait(app);
  const double dragged = gridifs::loadProject(project).functions[0].variations.at("swirl");
  EXPECT_LT(dragged, 0.95) << "the drag did not lower the weight";

  // One undo step per gesture: the drag, then the add; the file is the original again.
  pressKeys("ctrl+z");
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Add variation swirl"; });
  EXPECT_EQ(probe["undo"], "Add variation swirl");
  saveAndWait(app);
  EXPECT_EQ(gridifs::loadProject(project).functions[0].variations.at("swirl"), 1.0);
  pressKeys("ctrl+z");
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == ""; });
  saveAndWait(app);
  EXPECT_EQ(fileText(project), original);
  pressKeys("ctrl+q");
  EXPECT_EQ(app.waitExit(), 0);
}
