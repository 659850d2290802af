#pragma once
// The settings groups of a project, one table each (schema/settings_table.h): a function's own numbers and placement,
// the camera, "render", "render.flame", the parts of "render.shading", "render.volume", "animation", "volume", a field
// layer and a condensation set. Reading, writing, validation and
// the panels' sliders all take their keys, ranges, labels and tooltips from here.
//
// Thread-safety: each table is built once (thread-safe static) and never changes.
#include "model/project.h"
#include "schema/settings_table.h"

namespace gridifs {

/// The numbers every function holds, whatever its kind ("functions[i]" and "final"): its weight,
/// its colour, its palette index and colour speed (Draves & Reckase 2003, §5), whether it is
/// muted, and the sampling error of a map sampled onto its grid. A function's other fields (its
/// grid, operations, matrix or set) are described by the operation table and the function's kind.
const SettingTableOf<Function>& functionTable();

/// A grid function's "placement": where its grid sits in the common initial grid (translate,
/// rotate in degrees, scale); a function's post map ("post") uses it too. The condensation sets'
/// placements are read with their own reader's words.
const SettingTableOf<Placement>& placementTable();

/// A condensation set's numbers, one table per shape in the order its file lists them
/// ("functions[i].set", "volume.start", a field layer's "shape"; Sokolov & Gentil §3.1–3.2): a
/// sphere's centre and radius, a box's centre and full edge lengths, a torus's centre, radii and
/// axis, a drawing's threshold, thickness and inversion, a VDB grid's threshold; a mesh has none of
/// its own. A mesh's or a drawing's "placement" is placementTable()'s, with no zero scale.
const SettingTableOf<CondensationSet>& condensationSetTable(SetShape shape);

/// One weight of "transitions" (row i, column j: how likely function j is to follow function i,
/// Thollot et al. §3): its range, label and help, for the file reader, the parameter paths,
/// validation and the Matrices window.
const FieldInfo& transitionWeightField();

/// One coordinate of a free-form project's control point ("space.control_points[j][c]", Thollot,
/// Zair, Tosan & Vandorpe 1997 §5) and one entry of a matrix function's barycentric matrix
/// ("functions[i].matrix[r][c]"): their ranges, labels and help, for the file reader, the
/// parameter paths and the Matrices window.
const FieldInfo& controlPointField();
const FieldInfo& barycentricEntryField();

/// A grid function's resolution, nodes per axis ("functions[i].resolution[d]"; InterIFS's lattice,
/// Sokolov, Gentil & Ploss §2): its range, label and help, for the file reader, the parameter
/// paths, validation and the Functions panel.
const FieldInfo& gridResolutionField();

/// One entry of a post map given as a 3×4 matrix ("functions[i].post.matrix[r][c]"): rows x, y, z,
/// the last column the translation.
const FieldInfo& postMatrixEntryField();

/// A median function's rotation, degrees about its axis per unit of distance between the sets'
/// centres ("functions[i].rotate"), and that axis ("rotate_axis", any length but not zero):
/// Sokolov & Gentil §4.1's rotated median.
const FieldInfo& medianRotateField();
const FieldInfo& medianRotateAxisField();

/// The widest field of view of a perspective or orthographic camera, in degrees.
inline constexpr double kMaxFlatFov = 170.0;
/// "camera": yaw, pitch, distance, target, fov, projection. "stereo" has a table of its own.
const SettingTableOf<Camera>& cameraTable();
/// "camera.stereo": eye separation, layout, convergence.
const SettingTableOf<StereoSettings>& stereoTable();
/// "render": size, sample budget, seed, skipped iterations, background, depth cue. The display
/// mode and the "flame" and "shading" blocks are written after these fields.
const SettingTableOf<RenderSettings>& renderSettingsTable();
/// "render.flame": palette, tone mapping and density estimation (Draves & Reckase 2003, §4–8).
const SettingTableOf<FlameSettings>& flameSettingsTable();
/// "render.shading": ambient, specular and shininess; the lights, "ao", "fog" and "dof" blocks
/// have tables of their own.
const SettingTableOf<ShadingSettings>& shadingSettingsTable();
/// One entry of "render.shading.lights".
const SettingTableOf<ShadingLight>& shadingLightTable();
/// "render.shading.ao".
const SettingTableOf<AmbientOcclusionSettings>& ambientOcclusionTable();
/// "render.shading.fog".
const SettingTableOf<FogSettings>& fogTable();
/// "render.shading.dof".
const SettingTableOf<DepthOfFieldSettings>& depthOfFieldTable();

/// "render.volume": the volume ray march (its transfer function is a list of stops).
const SettingTableOf<VolumeRenderSettings>& volumeRenderTable();
/// One entry of "render.volume.transfer": a density and the colour and opacity it maps to.
const SettingTableOf<TransferStop>& transferStopTable();

/// "animation": the timeline (fps, start, end, loop) and the motion-blur shutter.
const SettingTableOf<AnimationSettings>& animationSettingsTable();
/// "volume": how the measure attractor becomes a density volume (Sokolov & Gentil, §3.4).
const SettingTableOf<VolumeSettings>& volumeSettingsTable();
/// A field layer's own numbers ("volume.field" or "volume.field[i]"; Colonna's fields shaping the
/// density, a cloud or a mountain, blended with a shape): strength, the plane's height, a cloud's
/// thickness, the shape's blend and softness. Each is written only where it matters or differs
/// from its default, so a file with one plain field saves as it always has. The field's own
/// parameters are the field operation's (schema/operation_table.h).
const SettingTableOf<VolumeDensityField>& fieldLayerTable();

}  // namespace gridifs
