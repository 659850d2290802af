// The final function in the modeller: added from the Functions panel, its lattice node dragged in
// a grid view like any function's (one undo step, saved in the file's "final" block), undone back
// to the original file byte for byte; a Bézier lattice with too many nodes is refused with a
// message in the panel; mute and remove are one undo step each.
#include <glm/geometric.hpp>

#include "gui_harness.h"
#include "model/final_function.h"
#include "model/stack_evaluator.h"

using namespace gridifs::gui_test;

TEST(FinalFunctionGui, AddDragANodeSaveAndUndoBackToTheOriginalFile) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "sierpinski_tetrahedron.gridifs");
  const std::string original = fileText(project);
  ASSERT_FALSE(gridifs::loadProject(project).final_function);
  App app(home, {project.string()});
  nlohmann::json probe = app.waitForPreview();

  const std::optional<Rect> add = app.waitForStableRect("functions.add_final");
  ASSERT_TRUE(add) << "the Functions panel shows no Add final function button";
  std::uint64_t restarts = probe["preview"]["restarts"];
  clickRect(*add);
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Add final function"; });
  ASSERT_EQ(probe["undo"], "Add final function");
  EXPECT_EQ(probe["active_function"], "final");
  ASSERT_TRUE(app.waitForStableRect("functions.row.final")) << "no Final row in the Functions panel";

  // The grid views now show the final lattice: 6×6×6 nodes, as a new function has.
  probe = app.waitFor([](const nlohmann::json& j) { return j["nodes_top"].size() == 216; });
  const auto& nodes = probe["nodes_top"];
  ASSERT_EQ(nodes.size(), 216u);
  const int wx = probe["window"]["x"], wy = probe["window"]["y"];
  std::size_t pick = 0;  // the outermost node on the left of the top view
  for (std::size_t n = 0; n < nodes.size(); ++n)
    if (nodes[n][0].get<double>() < nodes[pick][0].get<double>()) pick = n;
  const int x = wx + int(std::lround(nodes[pick][0].get<double>()));
  const int y = wy + int(std::lround(nodes[pick][1].get<double>()));
  restarts = probe["preview"]["restarts"];
  dragFrom(x, y, x + 40, y + 25);
  probe = app.waitForPreview(restarts);  // the preview follows the bent lattice
  EXPECT_EQ(probe["undo"], "Move nodes");
  EXPECT_EQ(probe["active_function"], "final");
  keepShot(home, "final_function_drag.png");

  saveAndWait(app);
  const gridifs::Project saved = gridifs::loadProject(project);
  ASSERT_TRUE(saved.final_function) << "the saved file has no \"final\" block";
  EXPECT_NE(fileText(project).find("\"final\""), std::string::npos);
  ASSERT_EQ(saved.final_function->ops.size(), 1u);
  const auto* moves = std::get_if<gridifs::NodesOp>(&saved.final_function->ops[0].params);
  ASSERT_TRUE(moves) << "the drag did not record a nodes operation on the final function";
  ASSERT_EQ(moves->moves.size(), 1u);
  const gridifs::Vec3 d = moves->moves[0].displacement;
  EXPECT_GT(glm::length(d), 0.05) << "the node did not move";
  EXPECT_NEAR(d.z, 0.0, 1e-9) << "a drag in the Top view stays in its plane";
  // The lattice itself: exactly that node left its place; the functions are untouched.
  const gridifs::Grid lattice = gridifs::evaluateFunction(*saved.final_function);
  const gridifs::Grid identity = gridifs::evaluateFunction(gridifs::identityFinalFunction());
  int moved = 0;
  for (std::size_t n = 0; n < lattice.nodeCount(); ++n)
    moved += glm::length(lattice.nodes()[n] - identity.nodes()[n]) > 1e-9;
  EXPECT_EQ(moved, 1);
  EXPECT_EQ(saved.functions, gridifs::parseProject(original).functions);

  // Two undo steps (the drag, the add) and the file is the original, byte for byte.
  pressKeys("ctrl+z");
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Add final function"; });
  EXPECT_EQ(probe["undo"], "Add final function");
  pressKeys("ctrl+z");
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == ""; });
  EXPECT_EQ(probe["undo"], "");
  EXPECT_NE(probe["active_function"], "final");
  saveAndWait(app);
  EXPECT_EQ(fileText(project), original);
  pressKeys("ctrl+q");
  EXPECT_EQ(app.waitExit(), 0);
}

TEST(FinalFunctionGui, TooManyNodesForBezierAreRefusedAndMuteAndRemoveAreUndoSteps) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "sierpinski_tetrahedron.gridifs");
  gridifs::Project fine = gridifs::loadProject(project);
  fine.final_function = gridifs::identityFinalFunction();
  fine.final_function->resolution = {10, 6, 6};  // trilinear: fine; Bézier: more than 8 along x
  gridifs::saveProject(fine, project);
  const std::string original = fileText(project);
  App app(home, {project.string()});
  nlohmann::json probe = app.waitForPreview();

  const std::optional<Rect> row = app.waitForStableRect("functions.row.final");
  ASSERT_TRUE(row) << "no Final row in the Functions panel";
  clickRect(*row);
  probe = app.waitFor([](const nlohmann::json& j) { return j["active_function"] == "final"; });
  ASSERT_EQ(probe["active_function"], "final");
  const std::optional<Rect> combo = app.waitForStableRect("final.interpolation");
  ASSERT_TRUE(combo) << "no Interpolation combo for the final function";
  clickRect(*combo);
  const std::optional<Rect> bezier = app.waitForStableRect("final.interpolation.bezier");
  ASSERT_TRUE(bezier) << "the Interpolation combo did not open";
  clickRect(*bezier);
  probe = app.waitFor([](const nlohmann::json& j) { return !j["final_message"].get<std::string>().empty(); });
  const std::string message = probe["final_message"];
  EXPECT_NE(message.find("at most 8 nodes per axis"), std::string::npos) << message;
  EXPECT_NE(message.find("10×6×6"), std::string::npos) << message;
  EXPECT_EQ(probe["undo"], "") << "the refused change reached the document";
  EXPECT_FALSE(probe["dirty"].get<bool>());
  // The message is on screen in the panel, in orange.
  const std::optional<Rect> shown = app.waitForStableRect("final.message");
  ASSERT_TRUE(shown) << "no message in the Functions panel";
  const std::vector<float> px = grabSettled(home, *shown);
  std::size_t orange = 0;
  for (std::size_t i = 0; i + 2 < px.size(); i += 3)
    orange += px[i] > 0.8f && px[i + 1] > 0.4f && px[i + 1] < 0.75f && px[i + 2] < 0.45f;
  EXPECT_GT(orange, 20u) << "the message is not drawn";
  keepShot(home, "final_function_bezier_refused.png");

  // Mute: one undo step.
  clickRect(*app.waitForStableRect("functions.mute.final"));
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Mute final function"; });
  EXPECT_EQ(probe["undo"], "Mute final function");
  pressKeys("ctrl+z");
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == ""; });
  EXPECT_EQ(probe["undo"], "");

  // Remove: one undo step; the last function becomes active.
  const std::optional<Rect> remove = app.waitForStableRect("functions.remove_final");
  ASSERT_TRUE(remove);
  clickRect(*remove);
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Remove final function"; });
  EXPECT_EQ(probe["undo"], "Remove final function");
  EXPECT_EQ(probe["active_function"], probe["functions"].get<int>() - 1);
  EXPECT_TRUE(app.waitForStableRect("functions.add_final")) << "no way back to a final function";
  pressKeys("ctrl+z");
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "" && !j["dirty"].get<bool>(); });
  EXPECT_FALSE(probe["dirty"].get<bool>());
  pressKeys("ctrl+q");
  EXPECT_EQ(app.waitExit(), 0);
  EXPECT_EQ(fileText(project), original);
}
