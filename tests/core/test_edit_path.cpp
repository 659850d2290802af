// The modeller's edit path without a window: widgets' edits (ProjectEdit values, the panels' own)
// go through the EditQueue into the Document, which publishes per-concern revisions; a geometry change compiles a new
// snapshot from the Document's evaluation cache and restarts the renderer as a new generation.
#include <gtest/gtest.h>

#include "edit/document.h"
#include "edit/edit_queue.h"
#include "freeform/free_form_presets.h"
#include "render/chaos_renderer.h"
#include "render/compiled_ifs.h"
#include "tests/core/renderer_scenes.h"

namespace gridifs {
namespace {

using test::waitUntil;

TEST(EditPath, SliderDragIsOneUndoStepAndChangesGeometryOnly) {
  Document document(test::sierpinskiTetrahedron());
  const Revisions before = document.revisions();
  EditQueue edits;
  Placement placement = document.project().functions[0].placement;
  edits.begin("Scale");
  for (int frame = 1; frame <= 10; ++frame) {
    placement.scale = Vec3{0.5 - 0.01 * frame};
    edits.update(SetPlacement{FunctionRef(0), placement});
  }
  edits.end();
  EXPECT_EQ(edits.apply(document), "");
  EXPECT_EQ(document.project().functions[0].placement.scale, Vec3{0.4});
  const Revisions after = document.revisions();
  EXPECT_GT(after.geometry, before.geometry);
  EXPECT_EQ(after.render, before.render);
  EXPECT_EQ(after.display, before.display);
  EXPECT_EQ(after.camera, before.camera);
  EXPECT_EQ(document.undoLabel(), "Scale");
  EXPECT_TRUE(document.undo());
  EXPECT_FALSE(document.canUndo());
  EXPECT_GT(document.revisions().geometry, after.geometry);
}

TEST(EditPath, DisplayAndCameraEditsLeaveGeometryAlone) {
  Document document(test::sierpinskiTetrahedron());
  EditQueue edits;
  const Revisions r0 = document.revisions();
  edits.commit("Background", SetBackground{Vec3{0.2}});
  edits.apply(document);
  const Revisions r1 = document.revisions();
  EXPECT_GT(r1.display, r0.display);
  EXPECT_EQ(r1.geometry, r0.geometry);
  EXPECT_EQ(r1.render, r0.render);
  edits.commit("Palette", SetPalette{"ice"});
  edits.commit("Orbit", SetParameter{"camera.yaw", document.project().camera.yaw + 10.0});
  edits.apply(document);
  const Revisions r2 = document.revisions();
  EXPECT_GT(r2.render, r1.render);  // the palette is looked up per sample
  EXPECT_GT(r2.camera, r1.camera);
  EXPECT_EQ(r2.geometry, r0.geometry);
  EXPECT_EQ(r2.display, r1.display);
}

TEST(EditPath, ControlPointDragIsOneUndoStepAndChangesGeometry) {
  Project project = test::sierpinskiTetrahedron();
  applyFreeFormPreset(project, FreeFormPreset::BezierCurve);
  Document document(project);
  const Revisions before = document.revisions();
  const Vec3 start = document.project().space->control_points[1];
  EditQueue edits;
  edits.begin("Move control point");
  for (int frame = 1; frame <= 5; ++frame) edits.update(MoveControlPoint{1, start + Vec3(0.02 * frame, 0.0, 0.0)});
  edits.end();
  EXPECT_EQ(edits.apply(document), "");
  EXPECT_GT(document.revisions().geometry, before.geometry);  // the preview restarts on this
  EXPECT_EQ(document.revisions().render, before.render);
  EXPECT_EQ(document.undoLabel(), "Move control point");
  EXPECT_TRUE(document.undo());
  EXPECT_FALSE(document.canUndo());
  EXPECT_EQ(document.project().space->control_points[1], start);
}

TEST(EditPath, RejectedEditKeepsTheDocumentAndReportsWhy) {
  Document document(test::sierpinskiTetrahedron());
  const Revisions before = document.revisions();
  EditQueue edits;
  Project weightless = document.project();
  for (Function& f : weightless.functions) f.weight = 0.0;
  edits.commit("Weight", ReplaceProject{weightless});
  const std::string error = edits.apply(document);
  EXPECT_NE(error.find("weight"), std::string::npos) << error;
  EXPECT_EQ(document.revisions(), before);
}

TEST(EditPath, AnEditReEvaluatesOnlyTheEditedFunction) {
  Document document(test::sierpinskiTetrahedron());
  ASSERT_GE(document.project().functions.size(), 2u);
  const auto first = document.evaluatedGrid(0), second = document.evaluatedGrid(1);
  EditQueue edits;
  edits.commit(SetParameter{"functions[0].placement.translate[0]",
                            document.project().functions[0].placement.translate.x + 0.01});
  edits.apply(document);
  EXPECT_NE(document.evaluatedGrid(0), first);
  EXPECT_EQ(document.evaluatedGrid(1), second);  // the same shared grid: not evaluated again
}

TEST(EditPath, GeometryEditRestartsTheRendererAsANewGeneration) {
  Document document(test::sierpinskiTetrahedron());
  RenderJob job = RenderJob::fromProject(document.project(), 2);
  job.width = job.height = 64;
  job.samples = 0;  // unlimited, as in the preview
  ChaosRenderer renderer;
  const std::uint64_t first = renderer.restart(compileIfs(document.project(), document.evaluation()), job);
  RenderImage image;
  ASSERT_TRUE(waitUntil([&] {
    renderer.snapshot(image, DisplaySettings{});
    return image.generation == first && image.hitPixels > 0;
  }));

  std::uint64_t published = document.revisions().geometry;
  EditQueue edits;
  edits.commit(
      SetParameter{"functions[0].placement.translate[1]", document.project().functions[0].placement.translate.y + 0.2});
  edits.apply(document);
  ASSERT_NE(document.revisions().geometry, published);  // what the preview compares
  published = document.revisions().geometry;
  const std::uint64_t second = renderer.restart(compileIfs(document.project(), document.evaluation()), job);
  EXPECT_GT(second, first);
  ASSERT_TRUE(waitUntil([&] {
    renderer.snapshot(image, DisplaySettings{});
    return image.generation == second && image.hitPixels > 0;
  }));
  EXPECT_EQ(renderer.generation(), second);
  renderer.stop();
}

}  // namespace
}  // namespace gridifs
