#pragma once
// The whole project as saved in a .gridifs file.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "anim/keyframe_track.h"
#include "model/construction_tree.h"
#include "model/flame_settings.h"
#include "model/free_form_space.h"
#include "model/function.h"
#include "model/ifs_states.h"
#include "model/shading_settings.h"
#include "model/volume_render_settings.h"
#include "model/volume_settings.h"

namespace gridifs {

/// The project file's "version": the only one this build reads and writes (io/project_io.h).
inline constexpr int kProjectFormatVersion = 1;

/// "camera.projection": how directions from the eye become pixels (render/camera.h has the
/// formulas). Fisheye and equirectangular images are for planetarium domes and 360° video.
enum class CameraProjection { Perspective, Orthographic, Fisheye, Equirectangular };

/// "camera.stereo.layout": where the two eyes go in the frame; the left eye comes first.
enum class StereoLayout { TopBottom, SideBySide };

/// "camera.stereo": a stereo pair in one frame. Omni-directional stereo (the eyes on a circle of
/// diameter eye_separation about the world's vertical axis) for fisheye and equirectangular
/// cameras; parallel eyes, off-axis to the convergence distance, for perspective ones.
struct StereoSettings {
  double eye_separation = 0.065;  // units; the human 65 mm at a scale where X is 2 m wide
  StereoLayout layout = StereoLayout::TopBottom;
  double convergence = 4.0;  // units from the eye at which both eyes see a point at the same place
  bool operator==(const StereoSettings&) const = default;
};

struct Camera {
  double yaw = 30.0, pitch = 20.0, distance = 4.0;  // degrees, degrees, units
  Vec3 target{0.0};
  /// Degrees: vertical for perspective and orthographic; the circle's angle for fisheye;
  /// horizontal for equirectangular.
  double fov = 35.0;
  CameraProjection projection = CameraProjection::Perspective;
  std::optional<StereoSettings> stereo;
  /// Degrees the camera turns about its viewing axis, counter-clockwise as the camera sees it
  /// (the picture turns clockwise).
  double roll = 0.0;
  /// Lens shift of a flat camera, in frame heights: the picture's centre moves right (x) and up
  /// (y) without turning the camera (an off-axis view, as a view camera's rising front).
  double shift_x = 0.0, shift_y = 0.0;
  /// A flat camera's lens blur, flam3's cam_dof (Apophysis 7X's 3D camera): every sample moves
  /// across the picture, at a random angle, by a random distance up to 0.1 · lens_blur times its
  /// depth's distance from the target's plane, which stays sharp. 0: none.
  double lens_blur = 0.0;
  bool orthographic() const { return projection == CameraProjection::Orthographic; }
  /// Fisheye and equirectangular: the depth of a point is its distance from the eye, not its
  /// distance along the view axis, and straight lines do not stay straight.
  bool panoramic() const {
    return projection == CameraProjection::Fisheye || projection == CameraProjection::Equirectangular;
  }
  bool operator==(const Camera&) const = default;
};

struct RenderSettings {
  int width = 1024, height = 768;
  std::int64_t samples = 20'000'000;
  /// "quality": samples per output pixel (flam3's quality). When set it decides the sample count,
  /// quality × width × height, and `samples` is not used (renderSampleCount).
  std::optional<double> quality;
  std::uint64_t seed = 1;
  int skip = 20;
  Vec3 background{0.0};
  double depth_cue = 0.6;                   // 0: no attenuation, 1: farthest points black
  DisplayMode mode = DisplayMode::ZBuffer;  // "render.mode": "zbuffer" | "flame" | "shaded"
  FlameSettings flame;                      // "render.flame": the flame display (Draves & Reckase 2003, §4–8)
  ShadingSettings shading;                  // "render.shading": lights, occlusion, fog, depth of field
  /// "render.volume": the volume ray march (render --mode volume, the Volume preview); absent: defaults.
  std::optional<VolumeRenderSettings> volume;
  bool operator==(const RenderSettings&) const = default;
};

/// The chaos-game iterations a render of these settings runs: quality × width × height (at least
/// 1, at most 1e11) when `quality` is set, else `samples`. Pure; never throws.
std::int64_t renderSampleCount(const RenderSettings& render);

/// Where a project came from when exploring made it ("lineage", optional): the files of its
/// parents (none for a random world), the seed of the draw and, for a mutation, its strength.
struct Lineage {
  std::vector<std::string> parents;
  std::uint64_t seed = 0;
  std::optional<double> strength;
  bool operator==(const Lineage&) const = default;
};

/// "audio": a sound the project's animation follows: the file (relative to the
/// project's folder) and the frequency bands, [low, high) in Hz, whose energies `audio:B`
/// bindings read.
struct AudioSettings {
  std::string file;
  std::vector<std::array<double, 2>> bands;
  bool operator==(const AudioSettings&) const = default;
};

/// One of "bindings": live input or sound driving a number of the project (schema/live_binding.h).
struct Binding {
  std::string path;    // a parameter path, as tracks name them
  std::string source;  // "audio:B", "osc:/ADDRESS", "midi:cc:N" or "midi:CH:cc:N"
  double min = 0.0, max = 1.0;
  double smooth = 0.0;  // seconds
  bool operator==(const Binding&) const = default;
};

struct Project {
  Camera camera;
  RenderSettings render;
  std::vector<Function> functions;
  std::optional<Function> final_function;  // not in the loop: applied before plotting
  /// "transitions": N×N weights, after function i the next is j with probability
  /// ∝ weight_j · transitions[i][j] (core/transition_matrix.h). Empty: unrestricted.
  std::vector<std::vector<double>> transitions;
  /// "states": an IFS matrix with states and initial/final state sets (freeform/state_expansion.h);
  /// a project has either this or `transitions`.
  std::optional<IfsStates> states;
  /// "time": the current time in seconds; fractal fields and the calculator's `t` read it.
  double time = 0.0;
  /// "animation": the timeline; absent in projects that were never animated.
  std::optional<AnimationSettings> animation;
  /// "tracks": keyframed parameters by JSON path. A track overrides the stored value.
  KeyframeTracks tracks;
  /// "space": control points of a free-form IFS (freeform/free_form.h); its functions are Matrix ones.
  std::optional<FreeFormSpace> space;
  /// "volume": the density volume's settings (Sokolov & Gentil, §3.4); absent until first set.
  std::optional<VolumeSettings> volume;
  /// "view.preview_mode": the modeller's preview mode when last saved; absent: chosen on open.
  std::optional<StoredPreviewMode> preview_mode;
  /// "construction": the tree whose value the functions, transitions and space are (Thollot et
  /// al. §4.3, model/construction_tree.h); absent in projects built without one.
  std::optional<ConstructionTree> construction;
  std::optional<Lineage> lineage;
  std::optional<AudioSettings> audio;
  std::vector<Binding> bindings;
  bool operator==(const Project&) const = default;
};

/// The project a new document starts from: one 6×6×6 grid scaled by one half.
Project defaultNewProject();

/// Roughly how many bytes `project` occupies in memory (its containers and strings), for the
/// undo history's memory cap. Thread-safe; never throws.
std::size_t approximateMemory(const Project& project);

}  // namespace gridifs
