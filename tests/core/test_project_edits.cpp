// Named edits (edit/project_edit.h): each has its documented effect on a small project, refuses
// references the project does not have, and goes through the Document as one undo step (a
// gesture of many updates included).
#include <gtest/gtest.h>

#include <numeric>

#include "edit/document.h"
#include "edit/edit_queue.h"
#include "edit/new_function.h"
#include "edit/project_edit.h"
#include "schema/operation_table.h"
#include "schema/settings_tables.h"

using namespace gridifs;

namespace {

/// Two grid functions; the first has a twist and a magnet.
Project twoFunctionProject() {
  Project p = defaultNewProject();
  p.functions.push_back(newGridFunction(p));
  p.functions[0].ops.resize(2);
  p.functions[0].ops[0].params.emplace<TwistOp>();
  p.functions[0].ops[1].params.emplace<MagnetOp>();
  return p;
}

Project applied(Project p, const ProjectEdit& edit) {
  applyEdit(p, edit);
  return p;
}

const OperationSpec& specOf(const OpParams& params) { return operationSpec(params); }

}  // namespace

TEST(ProjectEdits, NewFunctionsFollowTheModellersDefaults) {
  const Project p = defaultNewProject();
  const Function f = newGridFunction(p);
  EXPECT_EQ(f.name, "f2");  // the default project's function is f1
  EXPECT_EQ(f.kind, FunctionKind::Grid);
  EXPECT_EQ(f.placement.scale, Vec3(0.5));
  EXPECT_EQ(f.color, newFunctionColor(1));
  EXPECT_DOUBLE_EQ(f.palette_index, 0.25);
  EXPECT_EQ(newFunctionColor(9), newFunctionColor(1));  // eight hues, repeating

  const Function cond = newSetFunction(p, FunctionKind::Condensation);
  EXPECT_EQ(cond.name, "cond1");
  EXPECT_EQ(cond.set.shape, SetShape::Sphere);
  EXPECT_DOUBLE_EQ(cond.set.radius, 0.3);
  EXPECT_EQ(newSetFunction(p, FunctionKind::Median).name, "median1");
  EXPECT_EQ((AddFunction{cond}).label(), "Add condensation function");
  EXPECT_EQ((AddFunction{newSetFunction(p, FunctionKind::Median)}).label(), "Add median function");
  EXPECT_EQ((AddFunction{f}).label(), "Add function");

  // A free-form IFS takes matrix functions whose rows sum to 1 and contract towards the centroid.
  Project freeForm = p;
  applyEdit(freeForm, ApplyFreeFormPreset{FreeFormPreset::Sierpinski, {}});
  const Function m = newGridFunction(freeForm);
  ASSERT_EQ(m.kind, FunctionKind::Matrix);
  ASSERT_EQ(m.matrix.size(), 3u);
  for (const auto& row : m.matrix) EXPECT_NEAR(std::accumulate(row.begin(), row.end(), 0.0), 1.0, 1e-12);
  EXPECT_NEAR(m.matrix[0][0], 0.5 + 0.5 / 3.0, 1e-12);
}

TEST(ProjectEdits, FunctionListEditsKeepTheTransitionMatrixSquare) {
  Project p = twoFunctionProject();
  applyEdit(p, SetTransitionPreset{TransitionPreset::Cycle});
  ASSERT_EQ(p.transitions, (std::vector<std::vector<double>>{{0, 1}, {1, 0}}));

  const Project added = applied(p, AddFunction{newGridFunction(p)});
  ASSERT_EQ(added.functions.size(), 3u);
  EXPECT_EQ(added.functions[2].name, "f3");
  EXPECT_EQ(added.transitions.size(), 3u);

  const Project copied = applied(p, DuplicateFunction{0});
  ASSERT_EQ(copied.functions.size(), 3u);
  EXPECT_EQ(copied.functions[1].name, "f1_1");
  EXPECT_EQ(copied.functions[1].ops, p.functions[0].ops);
  EXPECT_EQ(copied.functions[2].name, "f2");

  const Project removed = applied(p, RemoveFunction{0});
  ASSERT_EQ(removed.functions.size(), 1u);
  EXPECT_EQ(removed.functions[0].name, "f2");
  EXPECT_EQ(removed.transitions.size(), 1u);

  const Project moved = applied(p, MoveFunction{1, 0});
  EXPECT_EQ(moved.functions[0].name, "f2");
  EXPECT_EQ(moved.functions[1].name, "f1");
  EXPECT_EQ((MoveFunction{1, 0}).label(), "Move function up");
  EXPECT_EQ((MoveFunction{0, 1}).label(), "Move function down");

  const Project withFinal = applied(p, AddFinalFunction{});
  ASSERT_TRUE(withFinal.final_function.has_value());
  EXPECT_FALSE(applied(withFinal, RemoveFinalFunction{}).final_function.has_value());
}

TEST(ProjectEdits, FunctionFieldEditsSetWhatTheyName) {
  const Project p = applied(twoFunctionProject(), AddFinalFunction{});
  const FunctionRef f2(1), last = FunctionRef::finalFunction();
  EXPECT_EQ(applied(p, RenameFunction{f2, "leaf"}).functions[1].name, "leaf");
  EXPECT_TRUE(applied(p, SetFunctionMuted{last, true}).final_function->muted);
  EXPECT_EQ(applied(p, SetFunctionResolution{f2, {3, 4, 5}}).functions[1].resolution, (Index3{3, 4, 5}));
  Placement pl;
  pl.rotate = Vec3(0, 0, 30);
  EXPECT_EQ(applied(p, SetPlacement{f2, pl}).functions[1].placement, pl);
  const Project moved = applied(p, MovePlacement{f2, Vec3(0.1, 0.2, 0.3)});
  EXPECT_EQ(moved.functions[1].placement.translate, Vec3(0.1, 0.2, 0.3));
  EXPECT_EQ(moved.functions[1].placement.scale, Vec3(0.5));  // only the translation
  EXPECT_EQ(applied(p, SetInterpolation{last, LatticeInterpolation::Bezier}).final_function->interpolation,
            LatticeInterpolation::Bezier);
  EXPECT_DOUBLE_EQ(applied(p, SetParameter{f2.path() + ".weight", 2.5}).functions[1].weight, 2.5);
  EXPECT_EQ(applied(p, SetFunctionColor{f2, Vec3(0.1)}).functions[1].color, Vec3(0.1));
  EXPECT_DOUBLE_EQ(applied(p, SetParameter{f2.path() + ".palette_index", 0.75}).functions[1].palette_index, 0.75);
  EXPECT_DOUBLE_EQ(applied(p, SetParameter{f2.path() + ".color_speed", 0.125}).functions[1].color_speed, 0.125);
  EXPECT_EQ(applied(p, AddSymmetry{3}).functions.size(), 4u);  // two rotations by 120° and 240°

  // The labels are the modeller's undo steps.
  EXPECT_EQ((SetFunctionMuted{last, true}).label(), "Mute final function");
  EXPECT_EQ((SetFunctionMuted{f2, false}).label(), "Unmute function");
  EXPECT_EQ((SetInterpolation{last, LatticeInterpolation::Bezier}).label(), "Bézier final lattice");
}

TEST(ProjectEdits, OperationEditsMoveTheirKeyframeTracksAlong) {
  Project p = twoFunctionProject();
  const FunctionRef f(0);
  p.tracks["functions[0].ops[1].strength"].setKey({0.0, 0.5, KeyInterpolation::Linear});

  Operation scale;
  scale.params.emplace<ScaleOp>();
  const Project added = applied(p, AddOperation{f, 0, scale});
  ASSERT_EQ(added.functions[0].ops.size(), 3u);
  EXPECT_TRUE(std::holds_alternative<ScaleOp>(added.functions[0].ops[0].params));
  EXPECT_TRUE(added.tracks.count("functions[0].ops[2].strength"));
  EXPECT_EQ((AddOperation{f, 0, scale}).label(), std::string("Add ") + specOf(scale.params).title);

  const Project moved = applied(p, MoveOperation{f, 1, 0});
  EXPECT_TRUE(std::holds_alternative<MagnetOp>(moved.functions[0].ops[0].params));
  EXPECT_TRUE(moved.tracks.count("functions[0].ops[0].strength"));
  EXPECT_EQ((MoveOperation{f, 1, 0}).label(), "Move operation up");

  const Project copied = applied(p, DuplicateOperation{f, 0});
  ASSERT_EQ(copied.functions[0].ops.size(), 3u);
  EXPECT_EQ(copied.functions[0].ops[1], p.functions[0].ops[0]);
  EXPECT_TRUE(copied.tracks.count("functions[0].ops[2].strength"));

  const Project removed = applied(p, RemoveOperation{f, 1});
  EXPECT_EQ(removed.functions[0].ops.size(), 1u);
  EXPECT_TRUE(removed.tracks.empty());  // the track of the removed operation goes with it

  EXPECT_TRUE(applied(p, SetOperationMuted{f, 1, true}).functions[0].ops[1].muted);
  EXPECT_EQ((SetOperationMuted{f, 1, false}).label(), "Unmute operation");
  Operation edited = p.functions[0].ops[0];
  std::get<TwistOp>(edited.params).k = 45.0;
  EXPECT_EQ(applied(p, SetOperation{f, 0, edited}).functions[0].ops[0], edited);
  const Selection box{SelectionBox{{0, 1}, {0, 1}, {0, 1}}};
  EXPECT_EQ(applied(p, SetOperationSelection{f, 1, box}).functions[0].ops[1].selection, box);
  EXPECT_EQ(applied(p, PlaceCenter{f, 1, Vec3(0.25)}).functions[0].ops[1].center.point, Vec3(0.25));
}

TEST(ProjectEdits, NewOperationsStartAtTheSelectedNodes) {
  const Grid grid(Index3{3, 3, 3});
  const Selection corner{SelectionBox{{0, 0}, {0, 0}, {0, 0}}};  // node (0, 0, 0) at (-1, -1, -1)
  const OperationSpec& magnet = specOf(MagnetOp{});
  const Operation op = newOperation(magnet, corner, Center::Kind::Selection, Vec3(0.5), grid);
  EXPECT_EQ(op.selection, corner);
  EXPECT_EQ(op.center.kind, Center::Kind::Selection);
  EXPECT_EQ(std::get<MagnetOp>(op.params).point, Vec3(-1.0));
  // With nothing selected the anchor is the centroid of all nodes; a point center is the point.
  EXPECT_EQ(std::get<MagnetOp>(newOperation(magnet, {}, Center::Kind::Grid, Vec3(0.5), grid).params).point, Vec3(0.0));
  EXPECT_EQ(std::get<MagnetOp>(newOperation(magnet, {}, Center::Kind::Point, Vec3(0.5), grid).params).point, Vec3(0.5));
}

TEST(ProjectEdits, MoveNodesExtendsOneTrailingNodesOperation) {
  Project p = defaultNewProject();
  const Function start = p.functions[0];  // 6×6×6, no operations
  std::vector<unsigned char> mask(216, 0);
  mask[1] = 1;  // node (1, 0, 0)
  mask[6] = 1;  // node (0, 1, 0)
  EXPECT_EQ(nodeMoveOperation(start), 0);
  applyEdit(p, MoveNodes{FunctionRef(0), start, mask, Vec3(0.1, 0, 0)});
  ASSERT_EQ(p.functions[0].ops.size(), 1u);
  const auto& moves = std::get<NodesOp>(p.functions[0].ops[0].params).moves;
  ASSERT_EQ(moves.size(), 2u);
  EXPECT_EQ(moves[0].index, (Index3{1, 0, 0}));
  EXPECT_EQ(moves[1].index, (Index3{0, 1, 0}));
  EXPECT_EQ(moves[1].displacement, Vec3(0.1, 0, 0));

  // The same edit again gives the same function: a drag's updates start from the drag's start.
  const Project once = p;
  applyEdit(p, MoveNodes{FunctionRef(0), start, mask, Vec3(0.1, 0, 0)});
  EXPECT_EQ(p, once);

  // A second drag extends that operation rather than stacking another.
  const Function second = p.functions[0];
  EXPECT_EQ(nodeMoveOperation(second), 0);
  applyEdit(p, MoveNodes{FunctionRef(0), second, mask, Vec3(0, 0.2, 0)});
  ASSERT_EQ(p.functions[0].ops.size(), 1u);
  EXPECT_EQ(std::get<NodesOp>(p.functions[0].ops[0].params).moves[0].displacement, Vec3(0.1, 0.2, 0));
}

TEST(ProjectEdits, SettingEditsGoThroughTheTables) {
  const Project p = defaultNewProject();
  // A number of a settings table is set by its path, even while the file leaves it out: the
  // shading of a project that is not shaded yet, a focus distance not set yet.
  EXPECT_DOUBLE_EQ(applied(p, SetParameter{"render.flame.gamma", 3.5}).render.flame.gamma, 3.5);
  EXPECT_EQ((SetParameter{"render.flame.gamma", 3.5, flameSettingsTable().field("gamma").label}).label(),
            flameSettingsTable().field("gamma").label);
  EXPECT_DOUBLE_EQ(applied(p, SetParameter{"render.depth_cue", 0.25}).render.depth_cue, 0.25);
  EXPECT_DOUBLE_EQ(
      applied(p, SetParameter{"render.shading.lights[0].intensity", 0.7}).render.shading.lights[0].intensity, 0.7);
  EXPECT_EQ(applied(p, SetParameter{"render.shading.ao.directions", 6}).render.shading.ao.directions, 6);
  EXPECT_THROW(applied(p, SetParameter{"render.shading.ao.directions", 5.6}), ModelError);  // a whole number
  EXPECT_DOUBLE_EQ(*applied(p, SetParameter{"render.shading.dof.focus", 3.0}).render.shading.dof.focus, 3.0);
  EXPECT_EQ(applied(p, SetParameter{"render.volume.resolution", 64}).render.volume->resolution, 64);

  EXPECT_EQ(applied(p, SetDisplayMode{DisplayMode::Shaded}).render.mode, DisplayMode::Shaded);
  EXPECT_EQ((SetDisplayMode{DisplayMode::Flame}).label(), "Flame display");
  EXPECT_EQ(applied(p, SetSampleBudget{4'000'000}).render.samples, 4'000'000);
  EXPECT_EQ(applied(p, SetBackground{Vec3(0.2)}).render.background, Vec3(0.2));
  EXPECT_EQ(applied(p, SetPalette{"flam3:27"}).render.flame.palette, "flam3:27");
  EXPECT_DOUBLE_EQ(applied(p, SetDensityEstimation{false}).render.flame.estimator_radius, 0.0);
  EXPECT_DOUBLE_EQ(
      applied(applied(p, SetDensityEstimation{false}), SetDensityEstimation{true}).render.flame.estimator_radius,
      FlameSettings{}.estimator_radius);

  Project toned = applied(applied(p, SetPalette{"flam3:3"}), SetParameter{"render.flame.gamma", 2.0});
  applyEdit(toned, ResetFlameSettings{});
  EXPECT_EQ(toned.render.flame.palette, "flam3:3");  // the palette stays
  EXPECT_DOUBLE_EQ(toned.render.flame.gamma, FlameSettings{}.gamma);

  Camera cam;
  cam.yaw = 90.0;
  EXPECT_EQ(applied(p, SetCamera{cam}).camera, cam);
  EXPECT_DOUBLE_EQ(applied(p, SetParameter{"camera.distance", 7.0}).camera.distance, 7.0);
  EXPECT_DOUBLE_EQ(applied(p, SetTime{1.5}).time, 1.5);
  AnimationSettings backwards;
  backwards.start = 3.0;
  backwards.end = 1.0;
  EXPECT_DOUBLE_EQ(applied(p, SetAnimation{backwards}).animation->end, 3.0);  // an end not before the start
}

TEST(ProjectEdits, ShadingEditsChangeTheirLight) {
  Project p = applied(defaultNewProject(), AddLight{});
  ASSERT_EQ(p.render.shading.lights.size(), 2u);
  EXPECT_FALSE(p.render.shading.lights[1].shadows);
  EXPECT_DOUBLE_EQ(p.render.shading.lights[1].intensity, 0.4);
  EXPECT_EQ(applied(p, SetLightDirection{1, Vec3(0, 0, 1)}).render.shading.lights[1].direction, Vec3(0, 0, 1));
  EXPECT_EQ(applied(p, SetLightColor{1, Vec3(0.5)}).render.shading.lights[1].color, Vec3(0.5));
  EXPECT_TRUE(applied(p, SetLightShadows{1, true}).render.shading.lights[1].shadows);
  EXPECT_EQ((SetLightShadows{1, false}).label(), "Light casts no shadows");
  const Project removed = applied(p, RemoveLight{0});
  ASSERT_EQ(removed.render.shading.lights.size(), 1u);
  EXPECT_EQ(removed.render.shading.lights[0], p.render.shading.lights[1]);
  EXPECT_EQ(applied(p, SetFogColor{Vec3(0.3)}).render.shading.fog.color, Vec3(0.3));
  const Project dof = applied(p, SetAperture{0.05, 2.5});
  EXPECT_DOUBLE_EQ(dof.render.shading.dof.aperture, 0.05);
  EXPECT_DOUBLE_EQ(*dof.render.shading.dof.focus, 2.5);
}

TEST(ProjectEdits, KeysAreSetAndRemovedAtTheCurrentTime) {
  Project p = applied(defaultNewProject(), SetTime{2.0});
  applyEdit(p, SetKeys{{{"functions[0].weight", 0.5}, {"camera.yaw", 10.0}}});
  ASSERT_EQ(p.tracks.size(), 2u);
  ASSERT_EQ(p.tracks["functions[0].weight"].keys.size(), 1u);
  EXPECT_DOUBLE_EQ(p.tracks["functions[0].weight"].keys[0].t, 2.0);
  EXPECT_DOUBLE_EQ(p.tracks["functions[0].weight"].keys[0].v, 0.5);
  // A key already there keeps its interpolation.
  p.tracks["camera.yaw"].keys[0].interp = KeyInterpolation::Smooth;
  applyEdit(p, SetKeys{{{"camera.yaw", 20.0}}});
  EXPECT_EQ(p.tracks["camera.yaw"].keys[0].interp, KeyInterpolation::Smooth);
  EXPECT_DOUBLE_EQ(p.tracks["camera.yaw"].keys[0].v, 20.0);
  applyEdit(p, RemoveKeys{{"camera.yaw", "render.flame.gamma"}});
  EXPECT_EQ(p.tracks.count("camera.yaw"), 0u);  // a track left without keys goes
  EXPECT_EQ(p.tracks.size(), 1u);
}

TEST(ProjectEdits, MatrixAndSetEdits) {
  Project p = twoFunctionProject();
  applyEdit(p, SetTransitionPreset{TransitionPreset::NoRepeats});
  EXPECT_EQ(p.transitions, (std::vector<std::vector<double>>{{0, 1}, {1, 0}}));
  EXPECT_DOUBLE_EQ(applied(p, SetParameter{"transitions[0][0]", 0.5}).transitions[0][0], 0.5);
  EXPECT_TRUE(applied(p, RemoveTransitions{}).transitions.empty());

  Project freeForm = applied(applied(p, AddFinalFunction{}), ApplyFreeFormPreset{FreeFormPreset::BezierCurve, {}});
  ASSERT_TRUE(freeForm.space.has_value());
  EXPECT_FALSE(freeForm.final_function.has_value());
  applyEdit(freeForm, SetMatrixEntry{0, 1, 2, 0.3});
  const auto& row = freeForm.functions[0].matrix[1];
  EXPECT_DOUBLE_EQ(row[2], 0.3);
  EXPECT_NEAR(std::accumulate(row.begin(), row.end(), 0.0), 1.0, 1e-12);  // the diagonal balances it
  EXPECT_EQ(applied(freeForm, MoveControlPoint{1, Vec3(0.5)}).space->control_points[1], Vec3(0.5));
  const Project grid = applied(freeForm, BackToGridIfs{});
  EXPECT_FALSE(grid.space.has_value());
  EXPECT_EQ(grid.functions, defaultNewProject().functions);

  Project sets = applied(defaultNewProject(), AddFunction{newSetFunction(defaultNewProject(), FunctionKind::Median)});
  const FunctionRef s(1);
  CondensationSet moved = sets.functions[1].set;
  moved.center = Vec3(0.2);
  EXPECT_EQ(applied(sets, SetCondensationSet{s, moved}).functions[1].set, moved);
  const Project mesh = applied(sets, SetSetShape{s, SetShape::Mesh, "bunny.obj"});
  EXPECT_EQ(mesh.functions[1].set.shape, SetShape::Mesh);
  EXPECT_EQ(mesh.functions[1].set.path, "bunny.obj");
  EXPECT_EQ(applied(mesh, SetSetFile{s, "cow.ply"}).functions[1].set.path, "cow.ply");
  EXPECT_EQ(applied(mesh, SetSetFill{s, SetFill::Surface}).functions[1].set.fill, SetFill::Surface);
  EXPECT_EQ((SetSetFill{s, SetFill::Surface}).label(), "Fill surface");
  EXPECT_EQ(applied(mesh, SetSetGrid{s, "density"}).functions[1].set.grid, "density");
  EXPECT_DOUBLE_EQ(applied(sets, SetParameter{s.path() + ".rotate", 15.0}).functions[1].rotate, 15.0);
  EXPECT_EQ(applied(sets, SetMedianAxis{s, Vec3{1.0, 0.0, 0.0}}).functions[1].rotate_axis, (Vec3{1.0, 0.0, 0.0}));
}

TEST(ProjectEdits, InvalidReferencesThrowAndLeaveTheDocumentUntouched) {
  const std::vector<ProjectEdit> invalid = {
      SetParameter{"functions[5].weight", 1.0},
      RemoveFunction{-1},
      MoveFunction{0, 2},
      DuplicateFunction{7},
      RemoveFinalFunction{},
      SetFunctionColor{FunctionRef::finalFunction(), Vec3(1.0)},
      RemoveOperation{FunctionRef(0), 2},
      SetOperation{FunctionRef(1), 0, Operation{}},
      AddOperation{FunctionRef(0), 3, Operation{}},
      MoveOperation{FunctionRef(0), 1, 2},
      SetLightColor{4, Vec3(1.0)},
      RemoveLight{1},
      SetParameter{"render.flame.no_such_key", 1.0},
      SetParameter{"render.flame.palette", 1.0},  // not a number
      SetParameter{"transitions[0][1]", 0.5},     // no matrix
      SetMatrixEntry{0, 0, 0, 0.5},               // not a matrix function
      MoveControlPoint{0, Vec3(0.0)},             // no free-form space
      SetSetShape{FunctionRef(9), SetShape::Box, std::nullopt},
  };
  Document doc(twoFunctionProject());
  doc.apply(SetParameter{"functions[0].weight", 2.0});
  const Project before = doc.project();
  const auto revision = doc.revision();
  for (const ProjectEdit& edit : invalid) {
    Project copy = before;
    EXPECT_THROW(applyEdit(copy, edit), ModelError) << editLabel(edit);
    EXPECT_THROW(doc.apply("invalid", edit), ModelError);
    EXPECT_EQ(doc.project(), before);
    EXPECT_EQ(doc.revision(), revision);
    EXPECT_EQ(doc.undoLabel(), "Set functions[0].weight");
  }
  // The error names what is missing.
  try {
    doc.apply(RemoveOperation{FunctionRef(0), 2});
    FAIL();
  } catch (const ModelError& e) {
    EXPECT_EQ(e.path(), "functions[0].ops[2]");
  }
  // A valid edit whose result is invalid is refused by validation in the same way.
  EXPECT_THROW(doc.apply(SetFunctionResolution{FunctionRef(0), {1, 6, 6}}), ModelError);
  EXPECT_EQ(doc.project(), before);
}

TEST(ProjectEdits, TheDocumentUndoesAndRedoesANamedEdit) {
  Document doc(twoFunctionProject());
  const Project original = doc.project();
  doc.apply(RenameFunction{FunctionRef(1), "leaf"});
  EXPECT_EQ(doc.undoLabel(), "Rename function");
  EXPECT_EQ(doc.project().functions[1].name, "leaf");
  const Project renamed = doc.project();
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.project(), original);
  EXPECT_EQ(doc.redoLabel(), "Rename function");
  ASSERT_TRUE(doc.redo());
  EXPECT_EQ(doc.project(), renamed);

  doc.apply("Combine (union)", ReplaceProject{defaultNewProject()});
  EXPECT_EQ(doc.undoLabel(), "Combine (union)");
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.project(), renamed);

  // An edit that changes nothing pushes no step; an unrecorded one pushes none either.
  doc.apply(RenameFunction{FunctionRef(1), "leaf"});
  EXPECT_EQ(doc.undoLabel(), "Rename function");
  doc.applyUnrecorded(SetTime{1.0});
  EXPECT_DOUBLE_EQ(doc.project().time, 1.0);
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.project().functions[1].name, "f2");
  EXPECT_FALSE(doc.canUndo());
}

TEST(ProjectEdits, AGestureOfNamedEditsIsOneUndoStep) {
  Document doc(twoFunctionProject());
  const Project original = doc.project();
  EditQueue edits;
  edits.begin("Function weight");
  for (double w : {1.5, 2.0, 2.5}) edits.update(SetParameter{"functions[1].weight", w});
  edits.end();
  EXPECT_EQ(edits.apply(doc), "");
  EXPECT_DOUBLE_EQ(doc.project().functions[1].weight, 2.5);
  EXPECT_EQ(doc.undoLabel(), "Function weight");
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.project(), original);
  EXPECT_FALSE(doc.canUndo());

  // A node drag: many updates from the drag's start, one step, the last displacement.
  const Function start = doc.project().functions[0];
  std::vector<unsigned char> mask(start.resolution[0] * start.resolution[1] * start.resolution[2], 0);
  mask[0] = 1;
  edits.begin("Move nodes");
  for (int k = 1; k <= 4; ++k) edits.update(MoveNodes{FunctionRef(0), start, mask, Vec3(0.05 * k, 0, 0)});
  edits.end();
  EXPECT_EQ(edits.apply(doc), "");
  Project expected = original;
  applyEdit(expected, MoveNodes{FunctionRef(0), start, mask, Vec3(0.2, 0, 0)});
  EXPECT_EQ(doc.project(), expected);
  EXPECT_EQ(doc.undoLabel(), "Move nodes");
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.project(), original);

  // A commit takes its label from the edit; an invalid one is dropped with its message.
  edits.commit(AddFunction{newGridFunction(doc.project())});
  edits.commit(RemoveOperation{FunctionRef(0), 9});
  const std::string error = edits.apply(doc);
  EXPECT_NE(error.find("functions[0].ops[9]"), std::string::npos) << error;
  EXPECT_EQ(doc.undoLabel(), "Add function");
  EXPECT_EQ(doc.project().functions.size(), 3u);
}
