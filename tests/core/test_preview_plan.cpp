// The modeller's preview as core decides it (job/preview_plan.h): which edits start the chaos game
// over, which compile the IFS again and which only develop the picture anew, driven through the
// edits the panels make (SetParameter values on a Document), and the preview's prepared render
// validated as every render is.
#include "job/preview_plan.h"

#include <gtest/gtest.h>

#include "edit/parameter_edit.h"
#include "io/project_io.h"

namespace {

using gridifs::Document;
using gridifs::PreviewDecision;
using gridifs::PreviewInputs;
using gridifs::SetParameter;

/// A preview that started from `document` at 320×240 on 2 threads.
PreviewInputs startedFrom(const Document& document) {
  return PreviewInputs{document.revisions(), 320, 240, 2, /*started=*/true, /*haveIfs=*/true};
}

PreviewDecision afterEdit(const std::string& path, double value) {
  Document document(gridifs::loadProject(std::string(GRIDIFS_ASSETS) + "/default.gridifs"));
  const PreviewInputs last = startedFrom(document);
  document.apply(SetParameter{path, value});
  return decidePreview(last, document.revisions(), 320, 240, 2);
}

TEST(PreviewPlan, NothingChangedNothingHappens) {
  Document document(gridifs::loadProject(std::string(GRIDIFS_ASSETS) + "/default.gridifs"));
  const PreviewDecision d = decidePreview(startedFrom(document), document.revisions(), 320, 240, 2);
  EXPECT_FALSE(d.restart);
  EXPECT_FALSE(d.recompile);
  EXPECT_FALSE(d.redisplay);
}

TEST(PreviewPlan, TheFirstPublishStartsAndCompiles) {
  Document document(gridifs::loadProject(std::string(GRIDIFS_ASSETS) + "/default.gridifs"));
  const PreviewDecision d = decidePreview(PreviewInputs{}, document.revisions(), 320, 240, 2);
  EXPECT_TRUE(d.restart);
  EXPECT_TRUE(d.recompile);
  EXPECT_TRUE(d.redisplay);
}

TEST(PreviewPlan, AFunctionsEditCompilesAgain) {
  const PreviewDecision d = afterEdit("functions[0].placement.translate[0]", 0.1);
  EXPECT_TRUE(d.restart);
  EXPECT_TRUE(d.recompile);
}

TEST(PreviewPlan, ACameraEditRestartsWithTheSameIfs) {
  const PreviewDecision d = afterEdit("camera.yaw", 12.0);
  EXPECT_TRUE(d.restart);
  EXPECT_FALSE(d.recompile);
  EXPECT_FALSE(d.redisplay);
}

TEST(PreviewPlan, ARenderInputRestartsWithTheSameIfs) {
  const PreviewDecision d = afterEdit("render.seed", 7.0);
  EXPECT_TRUE(d.restart);
  EXPECT_FALSE(d.recompile);
}

TEST(PreviewPlan, ToneMappingOnlyDevelopsThePictureAgain) {
  // Draves & Reckase 2003, §4: gamma and brightness apply to the finished histogram.
  for (const char* path : {"render.flame.gamma", "render.flame.brightness", "render.background[0]"}) {
    const PreviewDecision d = afterEdit(path, 0.5);
    EXPECT_FALSE(d.restart) << path;
    EXPECT_TRUE(d.redisplay) << path;
  }
}

TEST(PreviewPlan, AResizeOrOtherThreadsRestart) {
  Document document(gridifs::loadProject(std::string(GRIDIFS_ASSETS) + "/default.gridifs"));
  const PreviewInputs last = startedFrom(document);
  EXPECT_TRUE(decidePreview(last, document.revisions(), 321, 240, 2).restart);
  EXPECT_TRUE(decidePreview(last, document.revisions(), 320, 240, 1).restart);
  EXPECT_FALSE(decidePreview(last, document.revisions(), 320, 240, 1).recompile);
}

TEST(PreviewPlan, AFailedCompileCompilesAgainAtTheNextEdit) {
  Document document(gridifs::loadProject(std::string(GRIDIFS_ASSETS) + "/default.gridifs"));
  PreviewInputs last = startedFrom(document);
  last.haveIfs = false;
  document.apply(SetParameter{"camera.yaw", 3.0});
  const PreviewDecision d = decidePreview(last, document.revisions(), 320, 240, 2);
  EXPECT_TRUE(d.restart);
  EXPECT_TRUE(d.recompile);
}

TEST(PreviewPlan, ThePreviewsRenderIsPreparedAndValidated) {
  Document document(gridifs::loadProject(std::string(GRIDIFS_ASSETS) + "/default.gridifs"));
  const gridifs::PreparedRender r = gridifs::preparePreview(document, 8, 300, 2);
  EXPECT_EQ(r.output.width, gridifs::kMinPreviewSide) << "the preview never falls below its least side";
  EXPECT_EQ(r.output.height, 300);
  EXPECT_TRUE(r.output.lowPriority);
  EXPECT_TRUE(r.job.accumulateColor) << "colour sums in every mode: the flame display needs no restart";
  ASSERT_TRUE(r.ifs);
  // The same IFS is reused when asked.
  EXPECT_EQ(gridifs::preparePreview(document, 64, 64, 2, r.ifs).ifs, r.ifs);
  // An absurd size is refused with the render's own words and path.
  try {
    gridifs::preparePreview(document, 100000, 100000, 2);
    FAIL() << "a 10-gigapixel preview was accepted";
  } catch (const gridifs::RenderJobError& e) {
    EXPECT_EQ(e.path(), "render");
    EXPECT_NE(std::string(e.what()).find("too large"), std::string::npos) << e.what();
  }
}

}  // namespace
