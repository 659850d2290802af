#include "ui/panels/timeline_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "base/errors.h"
#include "schema/settings_tables.h"
#include "ui/base/widgets.h"
#include "ui/panels/key_button.h"

namespace gridifs::ui {
namespace {

long frameOf(double t, double fps) { return std::lround(t * fps); }

/// Moves the playhead now (outside the UI build, or from an `after` action); a track whose value
/// the project does not accept at that time stops playback with the reason.
void setTime(ModellerState& state, double t) {
  if (t == state.document.project().time) return;
  try {
    state.document.applyUnrecorded(SetTime{t});
  } catch (const ModelError& e) {
    state.playback.playing = false;
    state.error(e.what());
  }
}

void setTimeAfterEdits(ModellerState& state, EditQueue& edits, double t) {
  edits.after([&state, t] { setTime(state, t); });
}

/// Continues the row when `width` still fits in it (a narrow preview wraps the timeline's row).
void sameLineIfRoom(float width) {
  ImGui::SameLine(0, 2);
  if (ImGui::GetContentRegionAvail().x < width) ImGui::NewLine();
}

/// Every key time of the project, for the ticks on the scrub bar.
std::set<double> keyTimes(const Project& project) {
  std::set<double> times;
  for (const auto& [path, track] : project.tracks)
    for (const Keyframe& k : track.keys) times.insert(k.t);
  return times;
}

void scrubBar(ModellerState& state, EditQueue& edits, const AnimationSettings& a) {
  const Project& project = state.document.project();
  const float width = std::max(ImGui::GetContentRegionAvail().x, 32.0f);
  const float height = ImGui::GetFrameHeight() * 1.25f;
  const ImVec2 p0 = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("##scrub", ImVec2(width, height));
  state.probe.item("timeline.scrub");
  const bool active = ImGui::IsItemActive();
  if (ImGui::IsItemHovered())
    state.contextHelp = "Drag to scrub through the animation (the preview follows); diamonds mark keys";
  const float pad = ImGui::GetFontSize() * 0.5f;
  const float x0 = p0.x + pad, x1 = p0.x + width - pad;
  const long first = frameOf(a.start, a.fps), last = std::max(frameOf(a.end, a.fps), first + 1);
  auto xOfTime = [&](double t) { return x0 + float((t * a.fps - double(first)) / double(last - first)) * (x1 - x0); };

  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(p0, ImVec2(p0.x + width, p0.y + height), IM_COL32(30, 32, 38, 255), 3.0f);
  // The project's sound under the ticks: each column's loudest peaks over the frames it covers.
  if (state.sound && state.sound->frames() > 0) {
    const AudioEnvelope& sound = *state.sound;
    const float mid = p0.y + height * 0.5f, half = height * 0.42f;
    for (float x = x0; x < x1; x += 1.0f) {
      const double t0 = (double(first) + double(x - x0) / double(x1 - x0) * double(last - first)) / a.fps;
      const double t1 = (double(first) + double(x + 1.0f - x0) / double(x1 - x0) * double(last - first)) / a.fps;
      std::int64_t k0 = envelopeFrameAt(t0, sound.fps), k1 = std::max(k0, envelopeFrameAt(t1, sound.fps) - 1);
      if (k0 < 0 || k0 >= sound.frames()) continue;
      k1 = std::min(k1, sound.frames() - 1);
      float lo = 0.0f, hi = 0.0f;
      for (std::int64_t k = k0; k <= k1; ++k) {
        lo = std::min(lo, sound.peaks[std::size_t(k)][0]);
        hi = std::max(hi, sound.peaks[std::size_t(k)][1]);
      }
      draw->AddLine(ImVec2(x, mid - hi * half), ImVec2(x, mid - lo * half + 1.0f), IM_COL32(70, 120, 105, 255));
    }
  }
  // Frame ticks: every frame when there is room, else every 5th, 10th, ...
  long step = 1;
  while (float(step) * (x1 - x0) / float(last - first) < 6.0f && step < 100000000) step *= (step % 2 == 1 ? 5 : 2);
  for (long f = first; f <= last; f += step) {
    const float x = xOfTime(double(f) / a.fps);
    const bool major = (f - first) % (step * 5) == 0;
    draw->AddLine(ImVec2(x, p0.y + height * (major ? 0.45f : 0.7f)), ImVec2(x, p0.y + height),
                  IM_COL32(110, 115, 125, 255));
  }
  // Keys: small diamonds along the top.
  const float r = height * 0.16f, ky = p0.y + r + 2.0f;
  for (const double t : keyTimes(project)) {
    if (t < a.start - 1e-9 || t > a.end + 1e-9) continue;
    const float x = xOfTime(t);
    draw->AddQuadFilled(ImVec2(x, ky - r), ImVec2(x + r, ky), ImVec2(x, ky + r), ImVec2(x - r, ky),
                        IM_COL32(240, 200, 70, 255));
  }
  // The playhead.
  const float px = std::clamp(xOfTime(project.time), x0, x1);
  draw->AddLine(ImVec2(px, p0.y), ImVec2(px, p0.y + height), IM_COL32(90, 170, 255, 255), 2.0f);

  if (active) {
    state.playback.playing = false;
    const float mx = std::clamp(ImGui::GetIO().MousePos.x, x0, x1);
    const long f = first + std::lround(double(mx - x0) / double(x1 - x0) * double(last - first));
    const double t = double(f) / a.fps;  // scrubbing lands on frames, as renders do
    if (t != project.time) setTimeAfterEdits(state, edits, t);
  }
}

}  // namespace

AnimationSettings timelineOf(const Project& project) { return project.animation.value_or(AnimationSettings{}); }

float timelinePanelHeight(const ModellerState& state) {
  if (state.timelineHeight > 0.0f) return state.timelineHeight;
  const ImGuiStyle& style = ImGui::GetStyle();
  return ImGui::GetFrameHeight() * 2.25f + style.ItemSpacing.y * 2.0f;
}

void togglePlayback(ModellerState& state, EditQueue& edits) {
  edits.after([&state] { togglePlaybackNow(state); });
}

void togglePlaybackNow(ModellerState& state) {
  ModellerState::Playback& play = state.playback;
  if (play.playing) {
    play.playing = false;
    return;
  }
  const Project& project = state.document.project();
  const AnimationSettings a = timelineOf(project);
  double from = project.time;
  // Play from the start when the playhead is outside the range or at its end.
  if (from < a.start || frameOf(from, a.fps) >= frameOf(a.end, a.fps)) from = double(frameOf(a.start, a.fps)) / a.fps;
  setTime(state, from);
  if (state.document.project().time != from) return;  // the tracks do not fit the project there
  play.playing = true;
  play.startTime = from;
  play.startClock = state.now;
  // The sound from the playhead on; its clock then drives the playhead. The output opens the
  // first time a project with sound plays.
  if (!state.soundOutput && state.soundOutputProblem.empty() && state.sound && state.sound->samples)
    state.soundOutput = SoundOutput::open(state.soundOutputProblem);
  if (state.soundOutput && state.sound && state.sound->samples)
    state.soundOutput->play(state.sound->samples, state.sound->sampleRate, from);
}

void advancePlayback(ModellerState& state) {
  ModellerState::Playback& play = state.playback;
  SoundOutput* sound = state.soundOutput.get();
  if (!play.playing) {
    if (sound && sound->playing()) sound->stop();  // stopped, scrubbed or stepped
    return;
  }
  const AnimationSettings a = timelineOf(state.document.project());
  const long first = frameOf(a.start, a.fps), last = std::max(frameOf(a.end, a.fps), first);
  // The clock: the sound's own where it plays (picture follows sound), else the wall's.
  const double elapsed = sound && sound->playing() ? sound->seconds() - play.startTime : state.now - play.startClock;
  long f = frameOf(play.startTime, a.fps) + long(std::floor(elapsed * a.fps + 1e-9));
  if (f > last) {
    if (a.loop) {
      f = first + (f - first) % (last - first + 1);
      // The loop starts again, and with it the sound.
      play.startTime = double(f) / a.fps;
      play.startClock = state.now;
      if (sound && sound->playing() && state.sound && state.sound->samples)
        sound->play(state.sound->samples, state.sound->sampleRate, play.startTime);
    } else {
      f = last;
      play.playing = false;
    }
  }
  setTime(state, double(f) / a.fps);
}

void stepFrames(ModellerState& state, EditQueue& edits, int frames) {
  state.playback.playing = false;
  const Project& project = state.document.project();
  const AnimationSettings a = timelineOf(project);
  setTimeAfterEdits(state, edits, double(frameOf(project.time, a.fps) + frames) / a.fps);
}

void jumpToEnd(ModellerState& state, EditQueue& edits, bool end) {
  state.playback.playing = false;
  const AnimationSettings a = timelineOf(state.document.project());
  setTimeAfterEdits(state, edits, double(frameOf(end ? a.end : a.start, a.fps)) / a.fps);
}

void drawTimelinePanel(ModellerState& state, EditQueue& edits) {
  const Project& project = state.document.project();
  const AnimationSettings a = timelineOf(project);
  ImGui::PushID("timeline");
  const float top = ImGui::GetCursorPosY();
  const float em = ImGui::GetFontSize();
  if (ImGui::Button("|<")) jumpToEnd(state, edits, false);
  contextHelp(state, "To the first frame (Shift+Left)");
  ImGui::SameLine(0, 2);
  if (ImGui::Button("<")) stepFrames(state, edits, -1);
  contextHelp(state, "One frame back (Left)");
  ImGui::SameLine(0, 2);
  if (ImGui::Button(state.playback.playing ? "Pause##play" : "Play##play", ImVec2(em * 3.2f, 0)))
    togglePlayback(state, edits);
  state.probe.item("timeline.play");
  contextHelp(state, "Play or pause the animation (Alt+A); the preview renders each frame progressively");
  ImGui::SameLine(0, 2);
  if (ImGui::Button(">")) stepFrames(state, edits, 1);
  contextHelp(state, "One frame forward (Right)");
  ImGui::SameLine(0, 2);
  if (ImGui::Button(">|")) jumpToEnd(state, edits, true);
  contextHelp(state, "To the last frame (Shift+Right)");
  ImGui::SameLine();

  // The current time, typed in seconds (not an undo step, like scrubbing).
  double t = project.time;
  ImGui::SetNextItemWidth(em * 6.5f);
  const std::string format = "%.3f s  f" + std::to_string(frameOf(project.time, a.fps));
  if (dragDouble("##time", t, 1.0 / a.fps, 0.0, 0.0, format.c_str()) && std::isfinite(t))
    setTimeAfterEdits(state, edits, t);
  state.probe.item("timeline.time");
  contextHelp(state, "Current time in seconds and its frame number; drag, or double-click to type a time");
  ImGui::SameLine();

  // The range, frame rate and loop: undoable edits of the project's timeline.
  AnimationSettings edited = a;
  auto commit = [&](const char* label, bool changed) {
    if (edited.end < edited.start) edited.end = edited.start;
    gestureItem(edits, label, changed, SetAnimation{edited});
  };
  // Ranges, formats, undo names and help come from the animation's settings table.
  const SettingTableOf<AnimationSettings>& timeline = animationSettingsTable();
  auto drag = [&](const char* key, double& value, double speed, float width) {
    const SettingSpec& spec = timeline.field(key);
    ImGui::SetNextItemWidth(em * width);
    commit(spec.label,
           dragDouble((std::string("##") + key).c_str(), value, speed, spec.sliderMin, spec.sliderMax, spec.format));
    state.probe.item(std::string("timeline.") + key);
    contextHelp(state, spec.tooltip);
  };
  drag("start", edited.start, 0.05, 3.6f);
  ImGui::SameLine(0, 2);
  drag("end", edited.end, 0.05, 3.6f);
  ImGui::SameLine(0, 2);
  drag("fps", edited.fps, 0.1, 3.4f);
  const SettingSpec& loopSpec = timeline.field("loop");
  bool loop = edited.loop;
  sameLineIfRoom(ImGui::GetFrameHeight() + ImGui::CalcTextSize(loopSpec.label).x + em);
  if (ImGui::Checkbox(loopSpec.label, &loop)) {
    edited.loop = loop;
    edits.commit(loop ? "Loop playback" : "Play once", SetAnimation{edited});
  }
  contextHelp(state, loopSpec.tooltip);
  sameLineIfRoom(ImGui::GetFrameHeight() + ImGui::CalcTextSize("Camera").x + em);
  const Camera& cam = project.camera;
  keyButton(state, edits, "camera",
            {{"camera.yaw", cam.yaw},
             {"camera.pitch", cam.pitch},
             {"camera.distance", cam.distance},
             {"camera.target[0]", cam.target.x},
             {"camera.target[1]", cam.target.y},
             {"camera.target[2]", cam.target.z}});
  ImGui::TextUnformatted("Camera");
  contextHelp(state, "The diamond keys the preview camera (yaw, pitch, distance, target) at the current time");

  scrubBar(state, edits, a);
  state.timelineHeight = ImGui::GetCursorPosY() - top;  // the preview keeps this much room next frame
  ImGui::PopID();
}

}  // namespace gridifs::ui
