// The final function in the modeller's edit path: the FunctionRef every panel edits through,
// "Add final function" (an undistorted lattice, which leaves every point and colour where it was),
// an edit of its lattice (a geometry change the preview restarts on), undo, and removal.
#include <gtest/gtest.h>

#include "base/errors.h"
#include "edit/document.h"
#include "edit/edit_queue.h"
#include "io/project_io.h"
#include "model/final_function.h"
#include "model/function_ref.h"
#include "render/chaos_renderer.h"
#include "render/compiled_ifs.h"
#include "schema/project_time.h"
#include "schema/validation.h"
#include "tests/core/renderer_scenes.h"

namespace gridifs {
namespace {

/// The first points of the chaos game, positions then colours.
std::pair<std::vector<float>, std::vector<float>> finalChaosPoints(const Document& document) {
  RenderJob job = RenderJob::fromProject(document.project(), 1);
  job.samples = 4000;
  std::vector<float> xyz, rgb;
  generatePoints(*compileIfs(document.project(), document.evaluation()), job,
                 [&](const PointBatch& b, const RenderStats&) {
                   xyz.insert(xyz.end(), b.xyz, b.xyz + 3 * b.count);
                   rgb.insert(rgb.end(), b.rgb, b.rgb + 3 * b.count);
                   return true;
                 });
  return {xyz, rgb};
}

TEST(FinalFunction, ARefAddressesAFunctionOrTheFinalFunction) {
  Project p = test::sierpinskiTetrahedron();
  const FunctionRef second(1), last = FunctionRef::finalFunction();
  EXPECT_FALSE(second.isFinal());
  EXPECT_TRUE(last.isFinal());
  EXPECT_EQ(second.path(), "functions[1]");
  EXPECT_EQ(last.path(), "final");
  EXPECT_EQ(&second.in(p), &p.functions[1]);
  EXPECT_FALSE(last.existsIn(p));
  EXPECT_THROW(last.in(p), ModelError);
  EXPECT_THROW(FunctionRef(int(p.functions.size())).in(p), ModelError);
  p.final_function = identityFinalFunction();
  EXPECT_TRUE(last.existsIn(p));
  EXPECT_EQ(&last.in(p), &*p.final_function);
  EXPECT_FALSE(second == last);
}

TEST(FinalFunction, AddingItLeavesEveryPointAndColourWhereItWas) {
  for (const LatticeInterpolation interpolation : {LatticeInterpolation::Trilinear, LatticeInterpolation::Bezier}) {
    Document document(test::sierpinskiTetrahedron());
    const auto before = finalChaosPoints(document);
    const Revisions r0 = document.revisions();
    EditQueue edits;
    edits.commit(AddFinalFunction{});
    const SetInterpolation bezier{FunctionRef::finalFunction(), interpolation};
    if (interpolation != LatticeInterpolation::Trilinear) edits.commit(bezier);
    ASSERT_EQ(edits.apply(document), "");
    ASSERT_TRUE(document.project().final_function);
    EXPECT_EQ(document.project().final_function->resolution, (Index3{6, 6, 6}));  // like a new function
    EXPECT_EQ(document.project().final_function->interpolation, interpolation);
    EXPECT_EQ(document.undoLabel(),
              interpolation == LatticeInterpolation::Trilinear ? "Add final function" : bezier.label());
    EXPECT_GT(document.revisions().geometry, r0.geometry);
    const auto after = finalChaosPoints(document);
    ASSERT_EQ(after.first.size(), before.first.size());
    ASSERT_GT(after.first.size(), 1000u);
    for (std::size_t i = 0; i < before.first.size(); ++i) {
      ASSERT_NEAR(after.first[i], before.first[i], 2e-6) << "point coordinate " << i;
      ASSERT_NEAR(after.second[i], before.second[i], 1e-6) << "colour component " << i;
    }
  }
}

TEST(FinalFunction, EditingItsLatticeIsGeometryAndUndoRestoresIt) {
  Document document(test::sierpinskiTetrahedron());
  EditQueue edits;
  edits.commit(AddFinalFunction{});
  edits.apply(document);
  const Project added = document.project();
  const auto identity = finalChaosPoints(document);
  const std::uint64_t geometry = document.revisions().geometry;

  // A node drag as the grid views make it: one gesture through the FunctionRef, one undo step.
  const FunctionRef ref = FunctionRef::finalFunction();
  MoveNodes drag{ref, *added.final_function, std::vector<unsigned char>(6 * 6 * 6, 0), Vec3{0.0}};
  drag.mask[5 + 6 * (5 + 6 * 5)] = 1;  // node (5, 5, 5), the far corner
  edits.begin("Move nodes");
  for (int frame = 1; frame <= 4; ++frame) {
    drag.displacement = Vec3{0.1 * frame, 0.0, 0.0};
    edits.update(drag);
  }
  edits.end();
  ASSERT_EQ(edits.apply(document), "");
  EXPECT_GT(document.revisions().geometry, geometry);  // the preview restarts on this
  EXPECT_EQ(document.undoLabel(), "Move nodes");
  const Grid& lattice = *document.evaluatedFinal();
  EXPECT_NEAR(lattice.node(5, 5, 5).x, 1.4, 1e-12);
  const auto bent = finalChaosPoints(document);
  double moved = 0.0;
  for (std::size_t i = 0; i < bent.first.size(); ++i)
    moved = std::max(moved, double(std::abs(bent.first[i] - identity.first[i])));
  EXPECT_GT(moved, 0.01) << "points near the moved corner node follow it";

  // Bézier with more than 8 nodes per axis is refused, and the document keeps its last state.
  Project bezier = document.project();
  ref.in(bezier).interpolation = LatticeInterpolation::Bezier;
  ref.in(bezier).resolution = {9, 6, 6};
  edits.commit("Bézier final lattice", ReplaceProject{bezier});
  const std::string error = edits.apply(document);
  EXPECT_NE(error.find("final.resolution[0]"), std::string::npos) << error;
  EXPECT_NE(error.find("at most 8 nodes per axis"), std::string::npos) << error;
  EXPECT_EQ(document.project().final_function->interpolation, LatticeInterpolation::Trilinear);

  EXPECT_TRUE(document.undo());
  EXPECT_EQ(document.project(), added);
  EXPECT_EQ(serializeProject(document.project()), serializeProject(added));
  EXPECT_TRUE(document.undo());
  EXPECT_FALSE(document.project().final_function);
}

TEST(FinalFunction, ItsParametersAreKeyedLikeAFunction) {
  // The diamond beside a parameter keys it by its path; for the final function that is "final.…".
  Project p = test::sierpinskiTetrahedron();
  p.final_function = identityFinalFunction();
  KeyframeTrack track;
  track.setKey({0.0, 1.0});
  track.setKey({1.0, 0.5});
  const std::string path = FunctionRef::finalFunction().path() + ".placement.scale[0]";
  p.tracks[path] = track;
  Document document(p);
  document.setRule(keyEditedParameters);
  document.applyUnrecorded(SetTime{1.0});
  EXPECT_DOUBLE_EQ(document.project().final_function->placement.scale.x, 0.5);
  // Editing the keyed value at another time adds a key there.
  document.applyUnrecorded(SetTime{0.5});
  document.apply(SetParameter{path, 2.0});
  EXPECT_EQ(document.project().tracks.at(path).keys.size(), 3u);
  EXPECT_DOUBLE_EQ(document.project().final_function->placement.scale.x, 2.0);
}

TEST(FinalFunction, RemovingItDropsItsKeyframeTracks) {
  Project p = test::sierpinskiTetrahedron();
  p.final_function = identityFinalFunction();
  KeyframeTrack track;
  track.setKey({0.0, 1.0});
  track.setKey({1.0, 2.0});
  p.tracks["final.placement.scale[0]"] = track;
  p.tracks["functions[0].weight"] = track;
  p.tracks["finality"] = track;  // not a path of the final function
  removeFinalFunction(p);
  EXPECT_FALSE(p.final_function);
  EXPECT_EQ(p.tracks.count("final.placement.scale[0]"), 0u);
  EXPECT_EQ(p.tracks.count("functions[0].weight"), 1u);
  EXPECT_EQ(p.tracks.count("finality"), 1u);
}

}  // namespace
}  // namespace gridifs
