// The Construction tree window (key T): a part of the current functions and a file leaf make a
// tree, its operation changes, a leaf saved on disk is read again and the functions follow, an
// operation that cannot apply shows its reason inline, and every change is one undo step.
#include <cmath>

#include "gui_harness.h"

using namespace gridifs::gui_test;

namespace {

/// `n` half-size copies around a circle of radius `r` in the plane y = 0.
gridifs::Project ring(int n, double r, const std::string& prefix) {
  gridifs::Project p = gridifs::defaultNewProject();
  const gridifs::Function base = p.functions[0];
  p.functions.clear();
  for (int i = 0; i < n; ++i) {
    gridifs::Function f = base;
    f.name = prefix + std::to_string(i + 1);
    const double a = 2.0 * M_PI * i / n;
    f.placement.scale = gridifs::Vec3{0.5};
    f.placement.translate = gridifs::Vec3{r * std::cos(a), 0.0, r * std::sin(a)};
    p.functions.push_back(f);
  }
  p.render.samples = 300'000;
  p.camera.yaw = 90.0;
  p.camera.pitch = 0.0;
  return p;
}

std::size_t functionsOf(const nlohmann::json& j) { return j["functions"].get<std::size_t>(); }

}  // namespace

TEST(ConstructionTreeGui, BuildsATreeFollowsAnEditedLeafAndUndoes) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = home.path / "tree.gridifs", leaf = home.path / "ring2.gridifs";
  gridifs::saveProject(ring(3, 0.5, "a"), project);
  gridifs::saveProject(ring(2, 0.6, "b"), leaf);
  App app(home, {project.string()});
  nlohmann::json probe = app.waitForPreview();
  ASSERT_EQ(functionsOf(probe), 3u);

  // The current functions become the tree's first leaf, a part: nothing else changes.
  pressKeys("t");
  const std::optional<Rect> addPart = app.waitForStableRect("tree.add_part");
  ASSERT_TRUE(addPart) << "the Construction tree window did not open";
  clickRect(*addPart);
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Add part part1"; });
  EXPECT_EQ(probe["undo"], "Add part part1");
  EXPECT_EQ(probe["construction"]["nodes"], 1);
  EXPECT_EQ(functionsOf(probe), 3u);

  // A file leaf typed beside it: the union of both.
  const std::optional<Rect> field = app.waitForStableRect("tree.file");
  ASSERT_TRUE(field);
  clickRect(*field);
  xdotool("type --delay 15 'ring2.gridifs'");
  std::this_thread::sleep_for(200ms);
  xdotool("keydown Return sleep 0.15 keyup Return");
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Add leaf ring2.gridifs"; });
  ASSERT_EQ(probe["undo"], "Add leaf ring2.gridifs") << probe["construction"].dump();
  EXPECT_EQ(probe["construction"]["nodes"], 3);
  EXPECT_EQ(probe["construction"]["root_op"], "union");
  EXPECT_EQ(functionsOf(probe), 5u);

  // The root's operation becomes a concatenation.
  const std::optional<Rect> root = app.waitForStableRect("tree.node.root");
  ASSERT_TRUE(root);
  clickRect(*root);
  const std::optional<Rect> concat = app.waitForStableRect("tree.op.concat");
  ASSERT_TRUE(concat);
  clickRect(*concat);
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Operation: concat"; });
  EXPECT_EQ(probe["construction"]["root_op"], "concat");

  // Two IFSs without a function of the same name have no word in common, so their intersection
  // has no attractor: the reason shows in the window, nothing changes.
  const std::optional<Rect> meet = app.waitForStableRect("tree.op.intersection");
  ASSERT_TRUE(meet);
  clickRect(*meet);
  probe = app.waitFor([](const nlohmann::json& j) { return !j["construction"]["error"].get<std::string>().empty(); });
  EXPECT_NE(probe["construction"]["error"].get<std::string>().find("intersection failed"), std::string::npos);
  EXPECT_EQ(probe["undo"], "Operation: concat");
  EXPECT_TRUE(probe["rects"].contains("tree.error"));

  // The leaf is edited and saved (as another modeller would): the functions follow, one step.
  const std::uint64_t restarts = app.probe()["preview"]["restarts"];
  gridifs::saveProject(ring(4, 0.6, "b"), leaf);
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Leaf edited"; });
  ASSERT_EQ(probe["undo"], "Leaf edited");
  EXPECT_EQ(functionsOf(probe), 7u);
  probe = app.waitForPreview(restarts);
  EXPECT_TRUE(probe["preview"]["done"].get<bool>());
  run("import -window root '" + (home.path / "construction_tree.png").string() + "'");
  if (const char* keep = std::getenv("GRIDIFS_GUI_SHOTS"))  // for a person to look at
    fs::copy_file(home.path / "construction_tree.png", fs::path(keep) / "construction_tree.png",
                  fs::copy_options::overwrite_existing);

  // Saved: the tree is in the file, with the leaf's path relative to the project.
  saveAndWait(app);
  const std::string text = fileText(project);
  EXPECT_NE(text.find("\"construction\""), std::string::npos);
  EXPECT_NE(text.find("\"file\": \"ring2.gridifs\""), std::string::npos);
  EXPECT_EQ(gridifs::loadProject(project).functions.size(), 7u);

  // Undo walks back through the steps: the edited leaf, the operation, the leaf, the part.
  pressKeys("ctrl+z");
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Operation: concat"; });
  EXPECT_EQ(functionsOf(probe), 5u);
  pressKeys("ctrl+z");
  pressKeys("ctrl+z");
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Add part part1"; });
  EXPECT_EQ(functionsOf(probe), 3u);
  EXPECT_EQ(probe["construction"]["nodes"], 1);
  pressKeys("ctrl+z");
  probe = app.waitFor([](const nlohmann::json& j) { return j["construction"]["nodes"] == 0; });
  EXPECT_EQ(probe["construction"]["nodes"], 0);
  pressKeys("ctrl+q");  // unsaved (undone) edits: answer "Don't save"
  const std::optional<Rect> discard = app.waitForStableRect("unsaved.discard");
  ASSERT_TRUE(discard);
  clickRect(*discard);
  EXPECT_EQ(app.waitExit(), 0);
}
