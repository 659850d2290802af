#pragma once
// Keyframe tracks: a numeric parameter of the project, addressed by its path in the project file
// ("functions[0].ops[1].k", "camera.yaw"; anim/track_path.h), animated by keys {t, v, interp}. A key's
// interpolation governs the segment from it to the next key: `step` holds its value,
// `linear` blends, `smooth` is a cubic Hermite segment with Catmull-Rom tangents (finite
// differences over the neighbouring keys, so uneven key spacing stays smooth). Before the first
// key and after the last the end value holds.
//
// Thread-safety: plain values; evaluate from any thread.
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace gridifs {

enum class KeyInterpolation { Step, Linear, Smooth };

const char* toString(KeyInterpolation interpolation);
/// Parses "step", "linear" or "smooth"; returns false for anything else.
bool parseKeyInterpolation(const std::string& text, KeyInterpolation& out);

struct Keyframe {
  double t = 0.0;  // seconds
  double v = 0.0;
  KeyInterpolation interp = KeyInterpolation::Linear;
  bool operator==(const Keyframe&) const = default;
};

struct KeyframeTrack {
  std::vector<Keyframe> keys;  // strictly increasing t
  bool operator==(const KeyframeTrack&) const = default;

  /// The track's value at time t. Expects at least one key.
  double valueAt(double t) const;
  /// ∫ from t0 to t1 of valueAt(τ) dτ (negative when t1 < t0), exact for every interpolation: the
  /// segments are constant, linear or cubic polynomials and the ends hold constant values.
  double integral(double t0, double t1) const;
  /// Throws ModelError (path "[i].t", "[i].v") for an empty track, keys out of time order or
  /// duplicated, and non-finite times or values.
  void validate() const;
  /// Sets (or replaces, at the same time) a key and keeps the keys ordered.
  void setKey(const Keyframe& key);
  /// Removes the key at time t (within `tolerance`); false when there is none.
  bool removeKey(double t, double tolerance = 1e-9);
};

/// All tracks of a project, by parameter path (ordered, so files save in a stable order).
using KeyframeTracks = std::map<std::string, KeyframeTrack>;

/// Keeps the tracks on the elements of the list at `listPath` ("functions",
/// "functions[2].ops") when that list is reordered: the tracks of the element at old index i
/// move to `newIndex(i)`, or are dropped with it when that is negative.
void remapTrackIndices(KeyframeTracks& tracks, const std::string& listPath, const std::function<int(int)>& newIndex);

/// The project's timeline: "animation": {"fps", "start", "end", "loop"} (seconds). Its ranges,
/// file reading and validation are the table schema/settings_tables.h animationSettingsTable().
struct AnimationSettings {
  double fps = 24.0;  // in (0, 1000]
  double start = 0.0;
  double end = 4.0;  // not before start
  bool loop = true;
  /// Motion blur (Draves & Reckase, "The fractal flame algorithm", §motion blur): the fraction of
  /// the frame interval the time samples of one frame spread over, centred on the frame's time.
  /// 0.5 is film's 180° shutter.
  double shutter = 0.5;
  /// Time samples per frame for renders of the animation (1: no motion blur); the command line's
  /// --motion-blur overrides it.
  int motion_blur = 1;
  /// Directional motion blur (Draves & Reckase 2003, §9): earlier time samples are drawn dimmer,
  /// sample i of n weighted by ((i + 1) / n)^motion_fade (normalised to average 1). 0: uniform.
  double motion_fade = 0.0;
  bool operator==(const AnimationSettings&) const = default;
};

}  // namespace gridifs
