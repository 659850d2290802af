// Keyframe tracks: keys evaluate to their values, step/linear/smooth segments, end values
// hold, validation of key order, and the timeline settings.
#include <gtest/gtest.h>

#include <cmath>

#include "anim/keyframe_track.h"
#include "base/errors.h"
#include "schema/settings_tables.h"

using namespace gridifs;

namespace {

KeyframeTrack track(std::initializer_list<Keyframe> keys) {
  KeyframeTrack t;
  t.keys = keys;
  return t;
}

}  // namespace

TEST(KeyframeTrack, KeysEvaluateToTheirValuesWhateverTheInterpolation) {
  for (const auto interp : {KeyInterpolation::Step, KeyInterpolation::Linear, KeyInterpolation::Smooth}) {
    const KeyframeTrack t = track({{0.0, 1.0, interp}, {0.5, -2.0, interp}, {2.0, 4.0, interp}, {3.0, 3.5, interp}});
    for (const Keyframe& k : t.keys) EXPECT_DOUBLE_EQ(t.valueAt(k.t), k.v) << toString(interp);
  }
}

TEST(KeyframeTrack, EndValuesHoldOutsideTheKeys) {
  const KeyframeTrack t = track({{1.0, 5.0, KeyInterpolation::Smooth}, {2.0, 7.0, KeyInterpolation::Smooth}});
  EXPECT_EQ(t.valueAt(-10.0), 5.0);
  EXPECT_EQ(t.valueAt(0.999), 5.0);
  EXPECT_EQ(t.valueAt(2.001), 7.0);
  EXPECT_EQ(t.valueAt(1e9), 7.0);
  EXPECT_EQ(track({{3.0, 9.0}}).valueAt(0.0), 9.0);
}

TEST(KeyframeTrack, EachKeyGovernsTheSegmentAfterIt) {
  const KeyframeTrack t =
      track({{0.0, 0.0, KeyInterpolation::Step}, {1.0, 10.0, KeyInterpolation::Linear}, {3.0, 20.0}});
  EXPECT_EQ(t.valueAt(0.25), 0.0);
  EXPECT_EQ(t.valueAt(0.999), 0.0);
  EXPECT_DOUBLE_EQ(t.valueAt(2.0), 15.0);
  EXPECT_DOUBLE_EQ(t.valueAt(1.5), 12.5);
}

TEST(KeyframeTrack, SmoothReproducesLinearDataAndIsSmoothAtInteriorKeys) {
  // Keys on a line, unevenly spaced: Catmull-Rom tangents equal the slope, so the curve is the line.
  KeyframeTrack line;
  for (double t : {0.0, 0.3, 1.0, 1.1, 2.5}) line.keys.push_back({t, 2.0 * t - 1.0, KeyInterpolation::Smooth});
  for (double t = 0.0; t <= 2.5; t += 0.01) EXPECT_NEAR(line.valueAt(t), 2.0 * t - 1.0, 1e-12);
  // Curved data: the one-sided slopes at an interior key agree (C1), unlike linear segments.
  KeyframeTrack curve;
  for (double t : {0.0, 1.0, 1.5, 3.0}) curve.keys.push_back({t, std::sin(t), KeyInterpolation::Smooth});
  const double e = 1e-6;
  for (double k : {1.0, 1.5}) {
    const double left = (curve.valueAt(k) - curve.valueAt(k - e)) / e;
    const double right = (curve.valueAt(k + e) - curve.valueAt(k)) / e;
    EXPECT_NEAR(left, right, 1e-4) << "at " << k;
  }
}

TEST(KeyframeTrack, SetAndRemoveKeysKeepTheOrder) {
  KeyframeTrack t;
  t.setKey({2.0, 1.0});
  t.setKey({0.5, 3.0});
  t.setKey({1.0, 2.0});
  t.setKey({2.0, 5.0});  // replaces the key at 2
  ASSERT_EQ(t.keys.size(), 3u);
  EXPECT_EQ(t.keys[0].t, 0.5);
  EXPECT_EQ(t.keys[2].v, 5.0);
  EXPECT_NO_THROW(t.validate());
  EXPECT_TRUE(t.removeKey(1.0));
  EXPECT_FALSE(t.removeKey(1.0));
  EXPECT_EQ(t.keys.size(), 2u);
}

TEST(KeyframeTrack, RejectsKeysOutOfOrderDuplicatedOrNotFinite) {
  auto messageOf = [](const KeyframeTrack& t) {
    try {
      t.validate();
    } catch (const ModelError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(messageOf(track({{0.0, 1.0}, {2.0, 1.0}, {1.0, 0.0}})), "[2].t: keys must be in increasing time order");
  EXPECT_NE(messageOf(track({{0.0, 1.0}, {0.0, 2.0}})).find("[1].t: two keys share the time"), std::string::npos);
  EXPECT_EQ(messageOf(track({{0.0, NAN}})), "[0].v: the key's value must be a finite number");
  EXPECT_EQ(messageOf(track({{INFINITY, 1.0}})), "[0].t: the key's time must be a finite number");
  EXPECT_EQ(messageOf(KeyframeTrack{}), "a track needs at least one key");
}

TEST(AnimationSettings, Validates) {
  auto validate = [](const AnimationSettings& a) { validateSettings(animationSettingsTable(), a, "animation"); };
  AnimationSettings a;
  EXPECT_NO_THROW(validate(a));
  a.fps = 0.0;
  EXPECT_THROW(validate(a), ModelError);
  a = {};
  a.end = -1.0;
  EXPECT_THROW(validate(a), ModelError);
}

TEST(KeyframeTrack, TracksFollowTheirListWhenItIsReordered) {
  KeyframeTracks tracks;
  for (const char* path : {"functions[0].ops[0].k", "functions[0].ops[1].k", "functions[0].ops[2].strength[1]",
                           "functions[1].ops[1].k", "functions[0].weight", "camera.yaw"})
    tracks[path].keys = {{0.0, 1.0}};
  // The op at index 1 of function 0 is deleted.
  remapTrackIndices(tracks, "functions[0].ops", [](int i) { return i == 1 ? -1 : i > 1 ? i - 1 : i; });
  std::vector<std::string> paths;
  for (const auto& [path, track] : tracks) paths.push_back(path);
  EXPECT_EQ(paths, (std::vector<std::string>{"camera.yaw", "functions[0].ops[0].k", "functions[0].ops[1].strength[1]",
                                             "functions[0].weight", "functions[1].ops[1].k"}));
  // Functions 0 and 1 swap.
  remapTrackIndices(tracks, "functions", [](int i) { return 1 - i; });
  EXPECT_EQ(tracks.count("functions[1].ops[0].k"), 1u);
  EXPECT_EQ(tracks.count("functions[0].ops[1].k"), 1u);
  EXPECT_EQ(tracks.count("functions[1].weight"), 1u);
  EXPECT_EQ(tracks.count("camera.yaw"), 1u);
}
