#include "schema/settings_tables.h"

#include <cmath>
#include <cstdint>
#include <limits>

#include <glm/geometric.hpp>

#include "schema/field_layer.h"
#include "schema/palette_reference.h"

namespace gridifs {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& message) { throw ModelError(path, message); }

void flameRules(const void* group, const std::string& path) {
  const FlameSettings& f = *static_cast<const FlameSettings*>(group);
  if (f.estimator_radius <= 0.0) return;
  if (f.estimator_minimum > f.estimator_radius)
    fail(settingPath(path, "estimator_minimum"), "the estimator minimum is larger than its radius");
  // The density estimator builds ((radius·ss + 1)/(minimum·ss + 1))^(1/curve) kernels.
  const double kernels =
      std::pow((f.estimator_radius * f.supersample + 1.0) / (f.estimator_minimum * f.supersample + 1.0),
               1.0 / f.estimator_curve);
  if (!(kernels <= 1e7))
    fail(settingPath(path, "estimator_curve"), "the curve is too small for this radius (too many kernels)");
}

void lightRules(const void* group, const std::string& path) {
  const Vec3& d = static_cast<const ShadingLight*>(group)->direction;
  if (d.x * d.x + d.y * d.y + d.z * d.z < 1e-12)
    fail(settingPath(path, "direction"), "the light direction has zero length, so the light points nowhere");
}

void depthOfFieldRules(const void* group, const std::string& path) {
  const DepthOfFieldSettings& dof = *static_cast<const DepthOfFieldSettings*>(group);
  if (dof.aperture > 0.0 && !dof.focus)
    fail(settingPath(path, "focus"), "an aperture above 0 needs a focus distance (the view depth that stays sharp)");
}

void animationEndRule(const void* group, const std::string& path) {
  const AnimationSettings& a = *static_cast<const AnimationSettings*>(group);
  if (a.end < a.start) fail(path, "the animation must not end before it starts");
}

constexpr const char* kFewerSkipped = "expected fewer skipped iterations than iterations";

void volumeSkipRule(const void* group, const std::string& path) {
  const VolumeSettings& v = *static_cast<const VolumeSettings*>(group);
  if (v.skip >= v.iterations) fail(path, kFewerSkipped);
}

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

const ChoiceNames kProjections{{"perspective", "orthographic", "fisheye", "equirectangular"},
                               {"Perspective", "Orthographic", "Fisheye (dome)", "Equirectangular (360°)"}};
const ChoiceNames kStereoLayouts{{"top-bottom", "side-by-side"}, {"Top-bottom", "Side-by-side"}};

/// A flat lens cannot see half the sphere; a fisheye sees all of it, an equirectangular image
/// wraps all the way round.
void fovRule(const void* group, const std::string& path) {
  const Camera& c = *static_cast<const Camera*>(group);
  if (!c.panoramic() && c.fov > kMaxFlatFov)
    fail(path, "a " + std::string(c.orthographic() ? "orthographic" : "perspective") +
                   " camera's field of view must be at most 170 degrees (fisheye and equirectangular reach 360)");
}

void projectionRule(const void* group, const std::string& path) {
  const Camera& c = *static_cast<const Camera*>(group);
  if (c.stereo && c.orthographic())
    fail(path, "an orthographic camera has no stereo parallax; use a perspective, fisheye or equirectangular one");
}

/// A panoramic image has no flat picture plane to slide.
void shiftRule(const void* group, const std::string& path) {
  const Camera& c = *static_cast<const Camera*>(group);
  if (c.panoramic() && (c.shift_x != 0.0 || c.shift_y != 0.0))
    fail(path, "a lens shift needs a perspective or orthographic camera (fisheye and equirectangular have none)");
}

/// The blur moves samples across a flat picture plane, which a panoramic image does not have.
void lensBlurRule(const void* group, const std::string& path) {
  const Camera& c = *static_cast<const Camera*>(group);
  if (c.panoramic() && c.lens_blur != 0.0)
    fail(path, "a lens blur needs a perspective or orthographic camera (fisheye and equirectangular have none)");
}

}  // namespace

const SettingTableOf<Camera>& cameraTable() {
  static const SettingTableOf<Camera> table{{{
      setting<&Camera::yaw>({.key = "yaw",
                             .label = "Yaw",
                             .tooltip = "The eye's turn about the vertical axis",
                             .min = -1e6,
                             .max = 1e6,
                             .sliderMin = -180.0,
                             .sliderMax = 180.0,
                             .format = "yaw %.1f°"}),
      setting<&Camera::pitch>({.key = "pitch",
                               .label = "Pitch",
                               .tooltip = "How high the eye stands above the target (90°: straight above)",
                               .min = -90.0,
                               .max = 90.0,
                               .sliderMin = -90.0,
                               .sliderMax = 90.0,
                               .format = "pitch %.1f°"}),
      setting<&Camera::distance>({.key = "distance",
                                  .label = "Distance",
                                  .tooltip = "How far the eye stands from the target",
                                  .min = 1e-3,
                                  .max = 1e4,
                                  .sliderMin = 0.05,
                                  .sliderMax = 50.0,
                                  .format = "distance %.3f",
                                  .logarithmic = true}),
      setting<&Camera::target>(
          {.key = "target", .label = "Target", .tooltip = "The point the eye looks at", .min = -1e4, .max = 1e4}),
      setting<&Camera::fov>({.key = "fov",
                             .label = "Field of view",
                             .tooltip = "Degrees: vertical for perspective and orthographic, the circle for "
                                        "fisheye (180: a dome master), horizontal for equirectangular",
                             .min = 1.0,
                             .max = 360.0,
                             .sliderMin = 1.0,
                             .sliderMax = 360.0,
                             .format = "fov %.1f°",
                             .rule = fovRule}),
      // Written only when not perspective: "ortho": true in older files still reads as
      // orthographic (io/project_io.cpp).
      setting<&Camera::projection>({.key = "projection",
                                    .label = "Projection",
                                    .tooltip = "Perspective, orthographic, fisheye (planetarium domes) or "
                                               "equirectangular (360° video)",
                                    .choices = &kProjections,
                                    .omitDefault = true,
                                    .rule = projectionRule}),
      setting<&Camera::roll>({.key = "roll",
                              .label = "Roll",
                              .tooltip = "The camera's turn about its viewing axis (the picture turns the other way)",
                              .min = -1e6,
                              .max = 1e6,
                              .sliderMin = -180.0,
                              .sliderMax = 180.0,
                              .format = "roll %.1f°",
                              .omitDefault = true}),
      setting<&Camera::shift_x>({.key = "shift_x",
                                 .label = "Shift x",
                                 .tooltip = "Slides the picture right, in frame heights, without turning the camera",
                                 .min = -100.0,
                                 .max = 100.0,
                                 .sliderMin = -1.0,
                                 .sliderMax = 1.0,
                                 .format = "shift x %.3f",
                                 .omitDefault = true,
                                 .rule = shiftRule}),
      setting<&Camera::shift_y>({.key = "shift_y",
                                 .label = "Shift y",
                                 .tooltip = "Slides the picture up, in frame heights, without turning the camera",
                                 .min = -100.0,
                                 .max = 100.0,
                                 .sliderMin = -1.0,
                                 .sliderMax = 1.0,
                                 .format = "shift y %.3f",
                                 .omitDefault = true,
                                 .rule = shiftRule}),
      setting<&Camera::lens_blur>({.key = "lens_blur",
                                   .label = "Lens blur",
                                   .tooltip = "Blurs what lies in front of or behind the target's plane, more "
                                              "the farther it lies (flam3's cam_dof)",
                                   .min = 0.0,
                                   .max = 1000.0,
                                   .sliderMin = 0.0,
                                   .sliderMax = 2.0,
                                   .format = "lens blur %.3f",
                                   .omitDefault = true,
                                   .rule = lensBlurRule}),
  }}};
  return table;
}

const SettingTableOf<StereoSettings>& stereoTable() {
  static const SettingTableOf<StereoSettings> table{{{
      setting<&StereoSettings::eye_separation>(
          {.key = "eye_separation",
           .label = "Eye separation",
           .tooltip = "The distance between the eyes, in the scene's units (X is 2 units wide)",
           .min = 0.0,
           .max = 100.0,
           .sliderMin = 0.0,
           .sliderMax = 0.5,
           .format = "eyes %.3f apart"}),
      setting<&StereoSettings::layout>({.key = "layout",
                                        .label = "Layout",
                                        .tooltip = "Where the eyes go in the frame; the left eye comes first",
                                        .choices = &kStereoLayouts}),
      setting<&StereoSettings::convergence>(
          {.key = "convergence",
           .label = "Convergence",
           .tooltip = "The distance at which both eyes see a point at the same place (the screen's depth)",
           .min = 1e-3,
           .max = 1e4,
           .sliderMin = 0.1,
           .sliderMax = 50.0,
           .format = "converge at %.2f",
           .logarithmic = true}),
  }}};
  return table;
}

const SettingTableOf<RenderSettings>& renderSettingsTable() {
  static const SettingTableOf<RenderSettings> table{{{
      setting<&RenderSettings::width>({.key = "width", .min = 1, .max = 16384}),
      setting<&RenderSettings::height>({.key = "height", .min = 1, .max = 16384}),
      setting<&RenderSettings::samples>({.key = "samples", .min = 1, .max = 1e11}),
      // flam3's quality (samples per output pixel): written only when set, so older files save
      // unchanged; when set it decides the sample count (renderSampleCount).
      setting<&RenderSettings::quality>({.key = "quality",
                                         .label = "Quality",
                                         .tooltip = "Samples per output pixel; when set it decides the sample count",
                                         .min = 1e-3,
                                         .max = 1e6,
                                         .sliderMin = 1.0,
                                         .sliderMax = 5000.0,
                                         .format = "%.0f samples/pixel",
                                         .logarithmic = true}),
      setting<&RenderSettings::seed>({.key = "seed"}),
      setting<&RenderSettings::skip>({.key = "skip", .min = 0, .max = 100000}),
      setting<&RenderSettings::background>({.key = "background",
                                            .label = "Background",
                                            .tooltip = "Background color of the preview and of renders",
                                            .min = 0.0,
                                            .max = 1.0}),
      setting<&RenderSettings::depth_cue>(
          {.key = "depth_cue",
           .label = "Depth cue",
           .tooltip = "Depth cueing (Gröller & Wegenkittl 1994, §3.1): 0 keeps colors, 1 fades the farthest points "
                      "to black",
           .min = 0.0,
           .max = 1.0,
           .sliderMin = 0.0,
           .sliderMax = 1.0,
           .format = "depth cue %.2f"}),
  }}};
  return table;
}

const SettingTableOf<FlameSettings>& flameSettingsTable() {
  static const SettingTableOf<FlameSettings> table{
      {{
           setting<&FlameSettings::palette>(
               {.key = "palette",
                .label = "Palette",
                .accepts = isPaletteReferenceSyntax,
                .expected = "expected a built-in palette name, \"flam3:NUMBER\", \"flam3:NAME\" or \"file:PATH\""}),
           setting<&FlameSettings::brightness>({.key = "brightness",
                                                .label = "Brightness",
                                                .tooltip = "flam3 brightness (k1): exposure of the log-density image",
                                                .min = 0.0,
                                                .max = 1e4,
                                                .sliderMin = 0.05,
                                                .sliderMax = 100.0,
                                                .format = "%.2f",
                                                .logarithmic = true}),
           setting<&FlameSettings::gamma>({.key = "gamma",
                                           .label = "Gamma",
                                           .tooltip = "Gamma of the log-density image (Draves & Reckase 2003, §6)",
                                           .min = 0.05,
                                           .max = 100.0,
                                           .sliderMin = 0.5,
                                           .sliderMax = 10.0,
                                           .format = "%.2f"}),
           setting<&FlameSettings::gamma_threshold>(
               {.key = "gamma_threshold",
                .label = "Gamma threshold",
                .tooltip = "Below this density the gamma curve is linear (less noise in thin areas)",
                .min = 0.0,
                .max = 1.0,
                .sliderMin = 0.0,
                .sliderMax = 1.0,
                .format = "%.4f"}),
           setting<&FlameSettings::vibrancy>(
               {.key = "vibrancy",
                .label = "Vibrancy",
                .tooltip = "0: gamma per channel (washed out); 1: gamma through alpha (saturated colors)",
                .min = 0.0,
                .max = 1.0,
                .sliderMin = 0.0,
                .sliderMax = 1.0,
                .format = "%.2f"}),
           setting<&FlameSettings::highlight_power>(
               {.key = "highlight_power",
                .label = "Highlight power",
                .tooltip = "How saturated highlights turn white; negative clips instead",
                .min = -1.0,
                .max = 100.0,
                .sliderMin = -1.0,
                .sliderMax = 10.0,
                .format = "%.2f"}),
           setting<&FlameSettings::supersample>(
               {.key = "supersample",
                .label = "Supersample",
                .tooltip = "The histogram at this many times the image size in each direction, filtered down",
                .min = 1,
                .max = 8}),
           setting<&FlameSettings::estimator_radius>(
               {.key = "estimator_radius",
                .label = "Estimator radius",
                .tooltip = "Widest kernel radius in pixels, used where the density is lowest",
                .min = 0.0,
                .max = 64.0,
                .sliderMin = 0.5,  // the panel never goes below the estimator minimum either
                .sliderMax = 20.0,
                .format = "%.1f px"}),
           setting<&FlameSettings::estimator_minimum>(
               {.key = "estimator_minimum",
                .label = "Estimator minimum",
                .tooltip = "Narrowest kernel radius in pixels, used where the density is highest",
                .min = 0.0,
                .max = 64.0}),
           setting<&FlameSettings::estimator_curve>({.key = "estimator_curve",
                                                     .label = "Estimator curve",
                                                     .tooltip = "How fast the kernel narrows as the density grows",
                                                     .min = 0.05,
                                                     .max = 10.0}),
           setting<&FlameSettings::filter_radius>({.key = "filter_radius",
                                                   .label = "Filter radius",
                                                   .tooltip = "Gaussian filter radius in pixels",
                                                   .min = 0.0,
                                                   .max = 10.0}),
           setting<&FlameSettings::density_unit>({.key = "density_unit", .min = 1e-6, .max = 1e6, .omitDefault = true}),
           // Written only when changed, so files saved before these existed save byte for byte.
           setting<&FlameSettings::hue>(
               {.key = "hue",
                .label = "Hue",
                .tooltip = "Turns the palette's hue by this fraction of a circle (flam3's hue)",
                .min = 0.0,
                .max = 1.0,
                .sliderMin = 0.0,
                .sliderMax = 1.0,
                .format = "hue %.3f",
                .omitDefault = true}),
           setting<&FlameSettings::palette_keys>(
               {.key = "palette_keys",
                .label = "Palette keys",
                .tooltip = "The gradient being edited; it replaces the palette while set",
                .omitDefault = true,
                .maxLength = 2048,
                .accepts = isPaletteKeysSyntax,
                .expected = "expected 2 to 64 gradient keys \"POSITION:#RRGGBB\" (positions from 0 to 1) separated by "
                            "spaces"}),
           setting<&FlameSettings::density_display>(
               {.key = "density_display",
                .label = "Density display",
                .tooltip = "How hit counts become brightness: log density, linear or binary membership",
                .omitDefault = true,
                .accepts = isDensityDisplayName,
                .expected = "expected \"log\", \"linear\" or \"binary\""}),
       },
       flameRules}};
  return table;
}

const SettingTableOf<ShadingSettings>& shadingSettingsTable() {
  static const SettingTableOf<ShadingSettings> table{{{
      setting<&ShadingSettings::ambient>({.key = "ambient",
                                          .label = "Ambient",
                                          .tooltip = "Light that reaches every point, scaled by the ambient occlusion",
                                          .min = 0.0,
                                          .max = 10.0,
                                          .sliderMin = 0.0,
                                          .sliderMax = 1.0,
                                          .format = "ambient %.2f",
                                          .noun = "ambient term"}),
      setting<&ShadingSettings::specular>({.key = "specular",
                                           .label = "Specular",
                                           .tooltip = "Strength of the highlights (Blinn-Phong)",
                                           .min = 0.0,
                                           .max = 10.0,
                                           .sliderMin = 0.0,
                                           .sliderMax = 2.0,
                                           .format = "specular %.2f",
                                           .noun = "specular strength"}),
      setting<&ShadingSettings::shininess>({.key = "shininess",
                                            .label = "Shininess",
                                            .tooltip = "How small and sharp the highlights are",
                                            .min = 1.0,
                                            .max = 4096.0,
                                            .sliderMin = 1.0,
                                            .sliderMax = 512.0,
                                            .format = "shininess %.0f",
                                            .logarithmic = true,
                                            .noun = "shininess"}),
  }}};
  return table;
}

const SettingTableOf<ShadingLight>& shadingLightTable() {
  static const SettingTableOf<ShadingLight> table{
      {{
           setting<&ShadingLight::direction>({.key = "direction",
                                              .label = "Light direction",
                                              .tooltip = "Where the light comes from",
                                              .noun = "light direction"}),
           setting<&ShadingLight::color>({.key = "color",
                                          .label = "Light colour",
                                          .tooltip = "The light's colour",
                                          .min = 0.0,
                                          .max = 1.0,
                                          .noun = "colour"}),
           setting<&ShadingLight::intensity>({.key = "intensity",
                                              .label = "Light intensity",
                                              .tooltip = "How bright the light is",
                                              .min = 0.0,
                                              .max = 1e3,
                                              .sliderMin = 0.0,
                                              .sliderMax = 4.0,
                                              .format = "intensity %.2f",
                                              .noun = "light intensity"}),
           setting<&ShadingLight::shadows>(
               {.key = "shadows",
                .label = "Shadows",
                .tooltip = "Shadows: the chaos game also fills a depth buffer seen from this light (re-renders)"}),
       },
       lightRules}};
  return table;
}

const SettingTableOf<AmbientOcclusionSettings>& ambientOcclusionTable() {
  static const SettingTableOf<AmbientOcclusionSettings> table{{{
      setting<&AmbientOcclusionSettings::radius>(
          {.key = "radius",
           .label = "Occlusion radius",
           .tooltip = "How far (in pixels) the occlusion looks for surrounding surfaces",
           .min = 0.0,
           .max = limits::kMaxAoRadius,
           .sliderMin = 0.0,
           .sliderMax = 64.0,
           .format = "radius %.0f px",
           .noun = "occlusion radius"}),
      setting<&AmbientOcclusionSettings::strength>({.key = "strength",
                                                    .label = "Occlusion strength",
                                                    .tooltip = "How much creases and corners darken (0: off)",
                                                    .min = 0.0,
                                                    .max = 1.0,
                                                    .sliderMin = 0.0,
                                                    .sliderMax = 1.0,
                                                    .format = "strength %.2f",
                                                    .noun = "occlusion strength"}),
      setting<&AmbientOcclusionSettings::directions>(
          {.key = "directions",
           .label = "Occlusion directions",
           .tooltip = "Screen directions searched for the horizon (more: smoother, slower)",
           .min = 1,
           .max = limits::kMaxAoDirections,
           .sliderMin = 1,
           .sliderMax = limits::kMaxAoDirections,
           .format = "%d directions",
           .noun = "occlusion directions"}),
  }}};
  return table;
}

const SettingTableOf<FogSettings>& fogTable() {
  static const SettingTableOf<FogSettings> table{{{
      setting<&FogSettings::color>({.key = "color",
                                    .label = "Fog colour",
                                    .tooltip = "The colour distant points fade to",
                                    .min = 0.0,
                                    .max = 1.0,
                                    .noun = "colour"}),
      setting<&FogSettings::density>({.key = "density",
                                      .label = "Fog density",
                                      .tooltip = "How quickly points fade with distance (0: no fog)",
                                      .min = 0.0,
                                      .max = 1e3,
                                      .sliderMin = 0.0,
                                      .sliderMax = 2.0,
                                      .format = "density %.3f",
                                      .noun = "fog density"}),
  }}};
  return table;
}

const SettingTableOf<DepthOfFieldSettings>& depthOfFieldTable() {
  static const SettingTableOf<DepthOfFieldSettings> table{
      {{
           setting<&DepthOfFieldSettings::aperture>(
               {.key = "aperture",
                .label = "Aperture",
                .tooltip = "Blur away from the focus distance (0: everything sharp; re-renders the chaos game)",
                .min = 0.0,
                .max = 10.0,
                .sliderMin = 0.0,
                .sliderMax = 0.5,
                .format = "aperture %.3f",
                .noun = "aperture"}),
           setting<&DepthOfFieldSettings::focus>(
               {.key = "focus",
                .label = "Focus distance",
                .tooltip = "The view depth that stays sharp (the camera's distance puts the target in focus)",
                .min = 0.0,
                .max = 1e4,
                .sliderMin = 0.05,
                .sliderMax = 100.0,
                .format = "focus %.2f",
                .logarithmic = true,
                .noun = "focus distance"}),
       },
       depthOfFieldRules}};
  return table;
}

const SettingTableOf<AnimationSettings>& animationSettingsTable() {
  static const SettingTableOf<AnimationSettings> table{
      {{
           setting<&AnimationSettings::fps>({.key = "fps",
                                             .label = "Frame rate",
                                             .tooltip = "Frames per second: frame f is at time f / fps",
                                             .min = 0.0,
                                             .max = 1000.0,
                                             .sliderMin = 1.0,
                                             .sliderMax = 240.0,
                                             .format = "%.3g fps",
                                             .invalid = "frames per second must be in (0, 1000]",
                                             .openMin = true}),
           setting<&AnimationSettings::start>({.key = "start",
                                               .label = "Timeline start",
                                               .tooltip = "First moment of the animation, in seconds",
                                               .min = -kUnbounded,
                                               .max = kUnbounded,
                                               .sliderMin = -limits::kMaxCoordinate,
                                               .sliderMax = limits::kMaxCoordinate,
                                               .format = "from %.2f",
                                               .invalid = "the start time must be a finite number"}),
           setting<&AnimationSettings::end>({.key = "end",
                                             .label = "Timeline end",
                                             .tooltip = "Last moment of the animation, in seconds",
                                             .min = -kUnbounded,
                                             .max = kUnbounded,
                                             .sliderMin = -limits::kMaxCoordinate,
                                             .sliderMax = limits::kMaxCoordinate,
                                             .format = "to %.2f",
                                             .invalid = "the end time must be a finite number",
                                             .rule = animationEndRule}),
           // Draves & Reckase, motion blur: the time samples of a frame spread over this fraction
           // of the frame interval. Written only when changed (after loop), so files saved before
           // it existed save unchanged.
           setting<&AnimationSettings::shutter>(
               {.key = "shutter",
                .label = "Shutter",
                .tooltip = "Motion blur: the fraction of the frame interval a frame's time samples spread over",
                .min = 0.0,
                .max = 1.0,
                .sliderMin = 0.0,
                .sliderMax = 1.0,
                .format = "shutter %.2f",
                .omitDefault = true,
                .invalid = "the shutter must be a fraction of the frame interval between 0 and 1"}),
           setting<&AnimationSettings::loop>(
               {.key = "loop", .label = "Loop", .tooltip = "Play the range over and over"}),
           setting<&AnimationSettings::motion_blur>(
               {.key = "motion_blur",
                .label = "Motion blur",
                .tooltip = "Time samples per frame, spread over the shutter (1: no motion blur)",
                .min = 1,
                .max = 256,
                .sliderMin = 1,
                .sliderMax = 32,
                .format = "%d time samples",
                .omitDefault = true,
                .invalid = "motion blur must be between 1 and 256 time samples per frame"}),
           // Draves & Reckase 2003, §9, directional motion blur.
           setting<&AnimationSettings::motion_fade>(
               {.key = "motion_fade",
                .label = "Motion fade",
                .tooltip = "Directional motion blur: earlier time samples are drawn dimmer (0: uniform blur)",
                .min = 0.0,
                .max = 16.0,
                .sliderMin = 0.0,
                .sliderMax = 8.0,
                .format = "fade %.2f",
                .omitDefault = true,
                .invalid = "the motion fade must be between 0 and 16"}),
       },
       nullptr,
       SettingWords::FiniteOnly}};
  return table;
}

const SettingTableOf<VolumeSettings>& volumeSettingsTable() {
  static const SettingTableOf<VolumeSettings> table{
      {{
           setting<&VolumeSettings::resolution>(
               {.key = "resolution", .min = kMinVolumeResolution, .max = kMaxVolumeResolution}),
           setting<&VolumeSettings::iterations>({.key = "iterations", .min = 1, .max = 1'000'000}),
           setting<&VolumeSettings::skip>(
               {.key = "skip", .min = 0, .max = 1'000'000, .invalid = kFewerSkipped, .rule = volumeSkipRule}),
           setting<&VolumeSettings::seed>({.key = "seed", .min = 0, .max = double(INT64_MAX)}),
           setting<&VolumeSettings::samples>(
               {.key = "samples", .min = 1, .max = 1e11, .invalid = "expected between 1 and 1e11 samples"}),
       },
       nullptr,
       SettingWords::IntegerRange}};
  return table;
}

const SettingTableOf<CondensationSet>& condensationSetTable(SetShape shape) {
  static const SettingSpec center =
      setting<&CondensationSet::center>({.key = "center",
                                         .label = "Center",
                                         .tooltip = "Where the set's centre sits in X = [-1, 1]³",
                                         .sliderMin = -2.0,
                                         .sliderMax = 2.0,
                                         .invalid = "expected finite coordinates"});
  // A ball's and a torus's radii: positive, at most 10.
  static constexpr auto radius = [](const char* key, const char* label, const char* tooltip) {
    return SettingInfo{.key = key,
                       .label = label,
                       .tooltip = tooltip,
                       .min = 0.0,
                       .max = 10.0,
                       .sliderMin = 0.001,
                       .sliderMax = 10.0,
                       .speed = 0.002,
                       .invalid = "expected a radius between 0 and 10",
                       .openMin = true};
  };
  static constexpr auto nonZeroAxis = [](const void* owner, const std::string& path) {
    if (glm::length(static_cast<const CondensationSet*>(owner)->axis) < 1e-9)
      throw ModelError(path, "expected a non-zero axis");
  };
  static const SettingTableOf<CondensationSet> sphere{{{
      center,
      setting<&CondensationSet::radius>(radius("radius", "Radius", "The ball's radius")),
  }}};
  static const SettingTableOf<CondensationSet> box{{{
      center,
      setting<&CondensationSet::size>({.key = "size",
                                       .label = "Size",
                                       .tooltip = "The box's full edge lengths along x, y and z",
                                       .min = 0.0,
                                       .max = 20.0,
                                       .sliderMin = 0.001,
                                       .sliderMax = 20.0,
                                       .speed = 0.004,
                                       .invalid = "expected an edge length between 0 and 20",
                                       .openMin = true}),
  }}};
  static const SettingTableOf<CondensationSet> torus{{{
      center,
      setting<&CondensationSet::major>(radius("major", "Major", "Distance from the centre to the tube's centre line")),
      setting<&CondensationSet::minor>(radius("minor", "Minor", "The tube's radius")),
      setting<&CondensationSet::axis>({.key = "axis",
                                       .label = "Axis",
                                       .tooltip = "The axis the ring turns about (any length; it is normalized)",
                                       .sliderMin = -1.0,
                                       .sliderMax = 1.0,
                                       .speed = 0.01,
                                       .invalid = "expected a non-zero axis",
                                       .rule = nonZeroAxis}),
  }}};
  static const SettingTableOf<CondensationSet> image{{{
      setting<&CondensationSet::threshold>(
          {.key = "threshold",
           .label = "Threshold",
           .tooltip = "Pixels darker than this grey level (0 black, 1 white) belong to the set",
           .min = 0.0,
           .max = 1.0,
           .sliderMin = 0.0,
           .sliderMax = 1.0,
           .invalid = "expected a number between 0 and 1"}),
      setting<&CondensationSet::thickness>({.key = "thickness",
                                            .label = "Thickness",
                                            .tooltip = "The slab's thickness along z, before the placement",
                                            .min = 0.0,
                                            .max = 2.0,
                                            .sliderMin = 0.001,
                                            .sliderMax = 2.0,
                                            .speed = 0.001,
                                            .invalid = "expected a thickness between 0 and 2",
                                            .openMin = true}),
      setting<&CondensationSet::invert>(
          {.key = "invert", .label = "Invert", .tooltip = "Light pixels belong to the set instead of dark ones"}),
  }}};
  static const SettingTableOf<CondensationSet> vdb{{{
      setting<&CondensationSet::threshold>({.key = "threshold",
                                            .label = "Threshold",
                                            .tooltip = "Voxels whose value is at least this belong to the set",
                                            .sliderMin = -limits::kMaxCoordinate,
                                            .sliderMax = limits::kMaxCoordinate,
                                            .invalid = "expected a finite number"}),
  }}};
  static const SettingTableOf<CondensationSet> mesh{};
  switch (shape) {
    case SetShape::Sphere:
      return sphere;
    case SetShape::Box:
      return box;
    case SetShape::Torus:
      return torus;
    case SetShape::Image:
      return image;
    case SetShape::Vdb:
      return vdb;
    case SetShape::Mesh:
      break;
  }
  return mesh;
}

const SettingTableOf<VolumeDensityField>& fieldLayerTable() {
  // Where each is written at its default too: a plane for clouds and terrain, a thickness for
  // clouds, a blend and softness with a shape.
  static constexpr auto layered = [](const void* owner) {
    return static_cast<const VolumeDensityField*>(owner)->role != FieldRole::Density;
  };
  static constexpr auto cloud = [](const void* owner) {
    return static_cast<const VolumeDensityField*>(owner)->role == FieldRole::Cloud;
  };
  static constexpr auto shaped = [](const void* owner) {
    return static_cast<const VolumeDensityField*>(owner)->shape.has_value();
  };
  static const SettingTableOf<VolumeDensityField> table{{{
      setting<&VolumeDensityField::strength>(
          {.key = "strength",
           .label = "Strength",
           .tooltip = "How much the field counts: the density's weight 1 + strength·field, the cloud's density "
                      "strength·field, the mountain's height strength·field",
           .min = 0.0,
           .max = kMaxDensityFieldStrength,
           .sliderMin = 0.0,
           .sliderMax = 10.0}),
      setting<&VolumeDensityField::height>(
          {.key = "height",
           .label = "Height",
           .tooltip = "The layer's plane z = height (the cloud's middle, the mountain's base)",
           .min = -kMaxFieldLayerExtent,
           .max = kMaxFieldLayerExtent,
           .sliderMin = -1.0,
           .sliderMax = 1.0,
           .omitDefault = true,
           .writtenAtDefault = layered}),
      setting<&VolumeDensityField::thickness>({.key = "thickness",
                                               .label = "Thickness",
                                               .tooltip = "The cloud's full thickness where it is densest",
                                               .min = 0.0,
                                               .max = kMaxFieldLayerExtent,
                                               .sliderMin = 0.0,
                                               .sliderMax = 1.0,
                                               .omitDefault = true,
                                               .writtenAtDefault = cloud}),
      setting<&VolumeDensityField::blend>({.key = "blend",
                                           .label = "Blend",
                                           .tooltip = "0: the field alone; 1: the shape alone",
                                           .min = 0.0,
                                           .max = 1.0,
                                           .sliderMin = 0.0,
                                           .sliderMax = 1.0,
                                           .omitDefault = true,
                                           .writtenAtDefault = shaped}),
      setting<&VolumeDensityField::softness>(
          {.key = "softness",
           .label = "Softness",
           .tooltip = "The distance over which the shape goes from inside (1) to outside (−1)",
           .min = 0.0,
           .max = kMaxFieldLayerExtent,
           .sliderMin = 0.01,
           .sliderMax = 1.0,
           .omitDefault = true,
           .writtenAtDefault = shaped,
           .invalid = "expected a positive number of at most 1000",
           .openMin = true}),
  }}};
  return table;
}

const SettingTableOf<Function>& functionTable() {
  static const SettingTableOf<Function> table{{{
      setting<&Function::weight>({.key = "weight",
                                  .label = "Weight",
                                  .tooltip = "Probability of choosing this function is proportional to its weight",
                                  .min = 0.0,
                                  .max = 1e9,
                                  .speed = 0.01}),
      setting<&Function::color>({.key = "color",
                                 .label = "Color",
                                 .tooltip = "The function's colour in the z-buffer display",
                                 .min = 0.0,
                                 .max = 1.0}),
      setting<&Function::palette_index>(
          {.key = "palette_index",
           .label = "Palette index",
           .tooltip = "Structural color coordinate c_i for flame-style coloring (Draves & Reckase 2003, §5)",
           .min = 0.0,
           .max = 1.0,
           .sliderMin = 0.0,
           .sliderMax = 1.0}),
      setting<&Function::color_speed>(
          {.key = "color_speed",
           .label = "Color speed",
           .tooltip = "How far each point's colour moves towards this function's palette index",
           .min = 0.0,
           .max = 1.0,
           .sliderMin = 0.0,
           .sliderMax = 1.0}),
      setting<&Function::muted>(
          {.key = "muted", .label = "Muted", .tooltip = "A muted function takes no part in the IFS"}),
      // Set by flame import when a map is sampled onto the grid: the largest distance between
      // them at cell centres, written only when set.
      setting<&Function::sampling_error>({.key = "sampling_error",
                                          .label = "Sampling error",
                                          .tooltip = "The largest distance between the grid and the map it samples",
                                          .min = 0.0,
                                          .max = limits::kMaxCoordinate}),
  }}};
  return table;
}

const ChoiceNames kVolumeDisplays{{"lit", "xray"}, {"Lit", "X-ray"}};

const SettingTableOf<VolumeRenderSettings>& volumeRenderTable() {
  static const SettingTableOf<VolumeRenderSettings> table{{{
      setting<&VolumeRenderSettings::resolution>(
          {.key = "resolution",
           .label = "Volume resolution",
           .tooltip = "Voxels per axis of the density volume the ray march reads",
           .min = kMinVolumeResolution,
           .max = kMaxVolumeResolution}),
      setting<&VolumeRenderSettings::density_scale>(
          {.key = "density_scale",
           .label = "Volume density scale",
           .tooltip = "Density scale: how much light the densest voxels absorb per unit of length (higher: thicker, "
                      "darker shadows)",
           .min = kMinVolumeDensityScale,
           .max = kMaxVolumeDensityScale,
           .sliderMin = 0.5,
           .sliderMax = 500.0,
           .format = "density %.3g",
           .logarithmic = true}),
      setting<&VolumeRenderSettings::display>(
          {.key = "display",
           .label = "Volume display",
           .tooltip = "Lit (emission and absorption, shadowed) or X-ray (summed density)",
           .choices = &kVolumeDisplays}),
  }}};
  return table;
}

const SettingTableOf<TransferStop>& transferStopTable() {
  static const SettingTableOf<TransferStop> table{{{
      setting<&TransferStop::density>({.key = "density", .label = "Density", .min = 0.0, .max = 1.0}),
      setting<&TransferStop::color>({.key = "color", .label = "Color", .min = 0.0, .max = 1000.0}),
      setting<&TransferStop::opacity>({.key = "opacity", .label = "Opacity", .min = 0.0, .max = 1.0}),
  }}};
  return table;
}

const FieldInfo& controlPointField() {
  static const FieldInfo field{.key = "control_points",
                               .label = "Control point",
                               .tooltip = "A point of the control net the barycentric maps combine",
                               .min = -limits::kMaxCoordinate,
                               .max = limits::kMaxCoordinate,
                               .sliderMin = -1e3,
                               .sliderMax = 1e3,
                               .speed = 0.005,
                               .format = "%.3f"};
  return field;
}

const FieldInfo& barycentricEntryField() {
  static const FieldInfo field{
      .key = "matrix",
      .label = "Matrix entry",
      .tooltip = "How much of the column's control point the row's image takes (rows sum to 1)",
      .min = -limits::kMaxCoordinate,
      .max = limits::kMaxCoordinate,
      .speed = 0.01,
      .format = "%.3g"};
  return field;
}

const FieldInfo& gridResolutionField() {
  static const FieldInfo field{.key = "resolution",
                               .label = "Resolution",
                               .tooltip = "Nodes of the grid along x, y and z",
                               .min = double(limits::kMinResolution),
                               .max = double(limits::kMaxResolution),
                               .speed = 0.1,
                               .format = "%.0f"};
  return field;
}

const FieldInfo& postMatrixEntryField() {
  static const FieldInfo field{.key = "matrix",
                               .label = "Post matrix entry",
                               .tooltip = "An entry of the post map's 3x4 matrix (the last column moves)",
                               .min = -limits::kMaxCoordinate,
                               .max = limits::kMaxCoordinate,
                               .format = "%.4g"};
  return field;
}

const FieldInfo& medianRotateField() {
  static const FieldInfo field{.key = "rotate",
                               .label = "Rotate",
                               .tooltip =
                                   "The rotated median (Sokolov & Gentil, §4.1): degrees about the axis per unit "
                                   "of distance between the sets' centres; 0 is the plain median",
                               .min = -1e5,
                               .max = 1e5,
                               .speed = 0.5,
                               .format = "%.1f°"};
  return field;
}

const FieldInfo& medianRotateAxisField() {
  static const FieldInfo field{.key = "rotate_axis",
                               .label = "Axis",
                               .tooltip = "The axis the median turns about (any length; z by default)",
                               .min = -limits::kMaxCoordinate,
                               .max = limits::kMaxCoordinate,
                               .speed = 0.01};
  return field;
}

const FieldInfo& transitionWeightField() {
  static const FieldInfo field{.key = "transitions",
                               .label = "Transition weight",
                               .tooltip = "How likely the column's function is to follow the row's (0 forbids it)",
                               .min = 0.0,
                               .max = 1e9,
                               .speed = 0.01,
                               .format = "%.3g"};
  return field;
}

const SettingTableOf<Placement>& placementTable() {
  static const SettingTableOf<Placement> table{{{
      setting<&Placement::translate>(
          {.key = "translate",
           .label = "Translate",
           .tooltip = "Where the grid sits in the common initial grid; also: drag it in the IFS view"}),
      setting<&Placement::rotate>({.key = "rotate",
                                   .label = "Rotate",
                                   .tooltip = "Turns the grid about its centre",
                                   .speed = 0.5,
                                   .format = "%.1f°"}),
      setting<&Placement::scale>({.key = "scale", .label = "Scale", .tooltip = "Scales the grid about its centre"}),
  }}};
  return table;
}

}  // namespace gridifs
