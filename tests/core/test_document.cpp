// Document edits, gestures and undo/redo over random edit sequences.
#include <gtest/gtest.h>

#include <filesystem>

#include "edit/document.h"
#include "edit/project_edit.h"
#include "io/project_io.h"
#include "project_samples.h"
#include "schema/project_time.h"

using namespace gridifs;

TEST(Document, RandomEditSequencesUndoAndRedoExactly) {
  test_support::ProjectSampler sampler(31);
  for (int run = 0; run < 20; ++run) {
    Document doc(sampler.project());
    // The model of history: states[0..cursor] are reachable by undo, beyond by redo.
    std::vector<Project> states{doc.project()};
    std::size_t cursor = 0;
    for (int step = 0; step < 60; ++step) {
      const int action = sampler.integer(0, 9);
      if (action < 5) {
        const std::size_t f = std::size_t(sampler.integer(0, int(doc.project().functions.size()) - 1));
        Operation op = sampler.operation();
        doc.apply("add op", AddOperation{FunctionRef(int(f)), int(doc.project().functions[f].ops.size()), op});
        states.resize(cursor + 1);
        states.push_back(doc.project());
        ++cursor;
      } else if (action < 6) {
        const double w = sampler.real(0.1, 2);
        doc.beginGesture("weight drag");
        for (int k = 0; k < 5; ++k) doc.updateGesture(SetParameter{"functions[0].weight", w + k});
        doc.endGesture();  // one undo step for the whole drag
        states.resize(cursor + 1);
        states.push_back(doc.project());
        ++cursor;
      } else if (action < 8) {
        const bool did = doc.undo();
        EXPECT_EQ(did, cursor > 0);
        if (did) --cursor;
      } else {
        const bool did = doc.redo();
        EXPECT_EQ(did, cursor + 1 < states.size());
        if (did) ++cursor;
      }
      ASSERT_EQ(doc.project(), states[cursor]) << "run " << run << " step " << step;
    }
  }
}

TEST(Document, InvalidEditsAreRejectedAndChangeNothing) {
  Document doc(defaultNewProject());
  const Project before = doc.project();
  CalculatorOp broken;
  broken.x = "x +* 2";
  Operation op;
  op.params = broken;
  EXPECT_THROW(doc.apply("calc", AddOperation{FunctionRef(0), 0, op}), ModelError);
  EXPECT_EQ(doc.project(), before);
  EXPECT_FALSE(doc.canUndo());
  EXPECT_FALSE(doc.dirty());
}

TEST(Document, DirtyTracksTheSavedState) {
  Document doc(defaultNewProject());
  EXPECT_FALSE(doc.dirty());
  doc.apply(RenameFunction{FunctionRef(0), "x"});
  EXPECT_TRUE(doc.dirty());
  doc.undo();
  EXPECT_FALSE(doc.dirty());
  doc.redo();
  doc.markSaved("/tmp/x.gridifs");
  EXPECT_FALSE(doc.dirty());
}

TEST(Document, CancelledGestureRestoresTheStart) {
  Document doc(defaultNewProject());
  const Project before = doc.project();
  doc.beginGesture("drag");
  doc.updateGesture(SetParameter{"functions[0].placement.translate[0]", 0.4});
  EXPECT_NE(doc.project(), before);
  doc.cancelGesture();
  EXPECT_EQ(doc.project(), before);
  EXPECT_FALSE(doc.canUndo());
}

TEST(Document, EvaluatedGridsFollowEdits) {
  Document doc(defaultNewProject());
  const auto first = doc.evaluatedGrid(0);
  EXPECT_EQ(doc.evaluatedGrid(0), first);  // cached
  doc.apply(SetParameter{"functions[0].placement.translate[0]", 0.25});
  const auto moved = doc.evaluatedGrid(0);
  EXPECT_NE(moved, first);
  EXPECT_NEAR(moved->node(0, 0, 0).x, first->node(0, 0, 0).x + 0.25, 1e-12);
  const std::uint64_t revision = doc.revision();
  doc.undo();
  EXPECT_GT(doc.revision(), revision);
  EXPECT_EQ(*doc.evaluatedGrid(0), *first);
}

// The undo history has a memory cap: with large snapshots the oldest steps are dropped, the
// newest ones still undo exactly, and the history never holds more than the cap.
TEST(Document, UndoHistoryStaysUnderItsMemoryCapByDroppingTheOldestSteps) {
  Project big = defaultNewProject();
  big.functions[0].resolution = {64, 32, 32};
  NodesOp nodes;
  for (int i = 0; i < 64; ++i)
    for (int j = 0; j < 32; ++j)
      for (int k = 0; k < 32; k += 2) nodes.moves.push_back({{i, j, k}, Vec3{0.0, 0.0, 0.001}});
  Operation op;
  op.params = nodes;
  big.functions[0].ops.push_back(op);
  const std::size_t snapshot = approximateMemory(big);
  ASSERT_GT(snapshot, std::size_t(1) << 20);  // each undo step holds more than 1 MiB
  const int edits = int(Document::kMaxHistoryBytes / snapshot) + 40;
  ASSERT_LT(edits, int(Document::kMaxUndoSteps)) << "the memory cap, not the step cap, must bind";

  Document doc(big);
  for (int e = 1; e <= edits; ++e) doc.apply(SetParameter{"functions[0].weight", 1.0 + e});
  EXPECT_LE(doc.historyBytes(), Document::kMaxHistoryBytes);
  EXPECT_GT(doc.historyBytes(), Document::kMaxHistoryBytes - 2 * snapshot);
  int undone = 0;
  while (doc.undo()) {
    ++undone;
    EXPECT_EQ(doc.project().functions[0].weight, 1.0 + edits - undone);
  }
  EXPECT_LT(undone, edits) << "nothing was dropped";
  EXPECT_GE(undone, int(Document::kMaxHistoryBytes / snapshot) - 1);
  EXPECT_LE(doc.historyBytes(), Document::kMaxHistoryBytes);
  EXPECT_TRUE(doc.redo());  // the dropped steps are gone, the kept ones redo
  EXPECT_EQ(doc.project().functions[0].weight, 1.0 + edits - undone + 1);
}

TEST(Document, UnrecordedTimeChangesSurviveUndoAndKeyedEditsUndo) {
  Document d(loadProject(std::filesystem::path(GRIDIFS_ASSETS) / "sierpinski_tetrahedron.gridifs"));
  d.setRule(keyEditedParameters);
  d.apply(SetKeys{{{"camera.yaw", d.project().camera.yaw}}});
  ASSERT_TRUE(d.canUndo());
  d.applyUnrecorded(SetTime{1.0});
  EXPECT_EQ(d.undoLabel(), "Set key");  // the playhead made no undo step
  d.apply("Yaw", SetParameter{"camera.yaw", d.project().camera.yaw + 30.0});
  ASSERT_EQ(d.project().tracks.at("camera.yaw").keys.size(), 2u);
  const double keyedYaw = d.project().camera.yaw;
  d.applyUnrecorded(SetTime{0.0});
  EXPECT_DOUBLE_EQ(d.project().camera.yaw, keyedYaw - 30.0);
  d.applyUnrecorded(SetTime{1.0});
  EXPECT_DOUBLE_EQ(d.project().camera.yaw, keyedYaw);
  ASSERT_TRUE(d.undo());
  EXPECT_EQ(d.project().tracks.at("camera.yaw").keys.size(), 1u);
  EXPECT_DOUBLE_EQ(d.project().time, 1.0);  // undo keeps the playhead
  EXPECT_DOUBLE_EQ(d.project().camera.yaw, keyedYaw - 30.0);
  ASSERT_TRUE(d.undo());
  EXPECT_TRUE(d.project().tracks.empty());
  EXPECT_DOUBLE_EQ(d.project().time, 1.0);
}
