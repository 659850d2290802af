#include "ui/panels/live_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "anim/track_path.h"
#include "base/errors.h"
#include "edit/binding_edits.h"
#include "edit/parameter_edit.h"
#include "schema/live_binding.h"
#include "schema/validation.h"

namespace gridifs::ui {

std::string LivePanel::listen(int port, std::function<void()> wake) {
  try {
    osc_ = std::make_unique<OscListener>(port, std::move(wake));
  } catch (const IoError& e) {
    return e.what();
  }
  return {};
}

std::string LivePanel::openMidi(std::function<void()> wake) {
  midiTried_ = true;
  wake_ = wake;
  try {
    midi_ = std::make_unique<MidiInput>(std::move(wake));
    midiProblem_.clear();
  } catch (const IoError& e) {
    midiProblem_ = e.what();
  }
  return midiProblem_;
}

void LivePanel::learn(ModellerState& state, const std::string& source) {
  const std::string path = state.learnPath;
  state.learnPath.clear();
  try {
    const Project& project = state.document.project();
    const FoundParameter found = findParameter(project, *TrackPath::parse(path));
    if (found.lookup != ParameterLookup::Number) throw ModelError(path, "is no number to bind");
    // The slider's range, or one either side of the value where the number has none.
    ParameterSpan span = found.parameter.span();
    const double now = found.parameter.get(project);
    if (!(span.hi > span.lo)) span = {now - 1.0, now + 1.0};
    // A range end the project refuses as a whole (a flat camera's field of view stops at 170°
    // though the number reads up to 360) is pulled in to the farthest value it accepts.
    const auto accepted = [&](double v) {
      try {
        Project probe = project;
        found.parameter.set(probe, v);
        validateProject(probe);
        return true;
      } catch (const ModelError&) {
        return false;
      }
    };
    for (double* end : {&span.lo, &span.hi}) {
      if (accepted(*end)) continue;
      double good = now, bad = *end;
      for (int i = 0; i < 40; ++i) {
        const double mid = 0.5 * (good + bad);
        (accepted(mid) ? good : bad) = mid;
      }
      // A round end where one is accepted (170, not 169.99999999999997).
      const double rounded = std::round(good * 1e6) / 1e6;
      *end = found.parameter.wholeNumber() ? std::round(good) : accepted(rounded) ? rounded : good;
    }
    state.document.apply(AddBinding{Binding{path, source, span.lo, span.hi, 0.0}});
    state.statusText = "Bound " + path + " to " + source;
    state.statusIsError = false;
  } catch (const ModelError& e) {
    state.error(std::string("cannot bind: ") + e.what());
  }
}

void LivePanel::applyMidi(ModellerState& state, std::map<std::size_t, double>& bound) {
  if (!midi_) return;
  for (const MidiControl& c : midi_->take()) {
    const std::string any = "midi:cc:" + std::to_string(c.controller);
    const std::string channel = "midi:" + std::to_string(c.channel) + ":cc:" + std::to_string(c.controller);
    const double v = double(c.value) / 127.0;
    if (!state.learnPath.empty()) {
      learn(state, channel);
      continue;
    }
    lastValues_[channel] = v;
    drive_.setLive(channel, v);
    drive_.setLive(any, v);
    const Project& project = state.document.project();
    bool listened = false;
    for (std::size_t i = 0; i < project.bindings.size(); ++i)
      if (project.bindings[i].source == any || project.bindings[i].source == channel) {
        bound[i] = v;
        listened = true;
      }
    if (listened) ++applied_;
  }
}

void LivePanel::recordValue(const Project& project, std::size_t index, double value) {
  if (!recording_ || index >= project.bindings.size()) return;
  const double fps = project.animation.value_or(AnimationSettings{}).fps;
  const long frame = std::lround(project.time * fps);
  take_[project.bindings[index].path][frame] = Keyframe{double(frame) / fps, value};
}

void LivePanel::finishTake(ModellerState& state) {
  recording_ = stopRequested_ = false;
  RecordTake edit;
  edit.start = 1e300;
  edit.end = -1e300;
  for (const auto& [path, frames] : take_)
    for (const auto& [frame, key] : frames) {
      edit.keys[path].push_back(key);
      edit.start = std::min(edit.start, key.t);
      edit.end = std::max(edit.end, key.t);
    }
  take_.clear();
  if (edit.keys.empty()) return;
  try {
    state.document.apply(edit);
  } catch (const ModelError& e) {
    state.error(std::string("the take cannot be kept: ") + e.what());
  }
}

void LivePanel::refuse(const std::string& why) {
  ++refused_;
  lastRefusal_ = why;
}

void LivePanel::refreshSound(ModellerState& state) {
  const Project& project = state.document.project();
  const double fps = project.animation.value_or(AnimationSettings{}).fps;
  const std::filesystem::path folder = state.document.path().parent_path();
  const bool soundChanged = project.audio != soundFor_ || fps != soundFps_ || folder != soundFolder_;
  if (soundChanged) {
    soundFor_ = project.audio;
    soundFps_ = fps;
    soundFolder_ = folder;
    state.sound.reset();
    std::optional<AudioEnvelope> envelope;
    if (project.audio) {
      std::filesystem::path file = project.audio->file;
      if (file.is_relative()) file = (folder.empty() ? std::filesystem::path(".") : folder) / file;
      try {
        envelope = analyseAudio(file, project.audio->bands, fps);
        state.sound = std::make_shared<const AudioEnvelope>(*envelope);
      } catch (const IoError& e) {
        state.error(e.what());
      }
    }
    drive_ = LiveDrive::fromEnvelope(project, std::move(envelope));
    driveFor_ = project.bindings;
    followedTime_.reset();
  } else if (project.bindings != driveFor_) {
    std::optional<AudioEnvelope> envelope;
    if (state.sound) envelope = *state.sound;
    drive_ = LiveDrive::fromEnvelope(project, std::move(envelope));
    driveFor_ = project.bindings;
    followedTime_.reset();
  }
}

bool LivePanel::followPlayhead(ModellerState& state) {
  const Project& project = state.document.project();
  if (project.bindings.empty() || followedTime_ == project.time) return false;
  followedTime_ = project.time;
  bool changed = false;
  for (std::size_t i = 0; i < project.bindings.size(); ++i) {
    const Project& now = state.document.project();
    if (i >= now.bindings.size()) break;
    const std::optional<double> v = drive_.valueAt(now, i, now.time);
    if (!v) continue;
    try {
      const ProjectParameter parameter = boundParameter(now, i);
      const Binding& b = now.bindings[i];
      const double value = boundValue(b, parameter, *v);
      state.document.applyLiveValue(SetParameter{b.path, value});
      // Sound is rendered from the audio itself; a take keeps what live input played.
      const auto source = parseBindingSource(b.source);
      if (source && source->kind != BindingSource::Kind::Audio) recordValue(state.document.project(), i, value);
      changed = true;
    } catch (const ModelError& e) {
      refuse(now.bindings[i].source + ": " + e.what());
    }
  }
  return changed;
}

bool LivePanel::applyInput(ModellerState& state) {
  if (stopRequested_) finishTake(state);
  refreshSound(state);
  bool changed = followPlayhead(state);
  // "Bind…" opens the MIDI input the first time, so that a controller can be learnt.
  if (!state.learnPath.empty() && !midi_ && !midiTried_) openMidi(wake_);
  Document& document = state.document;
  // Of several values for one binding in a frame, the last one counts: the preview restarts once
  // per frame anyway.
  std::map<std::size_t, double> bound;  // binding index → value to set
  applyMidi(state, bound);
  const std::vector<OscInput> inputs = osc_ ? osc_->take() : std::vector<OscInput>{};
  for (const OscInput& in : inputs) {
    if (in.isSet) {
      try {
        document.apply(SetParameter{in.path, in.value});
        ++applied_;
        changed = true;
      } catch (const ModelError& e) {
        refuse("/gridifs/set " + in.path + ": " + e.what());
      }
      continue;
    }
    const std::string source = "osc:" + in.address;
    if (!(in.value >= 0.0 && in.value <= 1.0)) {
      refuse(in.address + ": bound addresses take values from 0 to 1, not " + std::to_string(in.value));
      continue;
    }
    const Project& project = document.project();
    bool listened = false;
    for (std::size_t i = 0; i < project.bindings.size(); ++i)
      if (project.bindings[i].source == source) listened = true;
    if (!listened && !state.learnPath.empty()) {
      learn(state, source);
      continue;
    }
    if (!listened) {
      refuse(in.address + ": no binding listens to this address");
      continue;
    }
    lastValues_[source] = in.value;
    drive_.setLive(source, in.value);
    for (std::size_t i = 0; i < project.bindings.size(); ++i)
      if (project.bindings[i].source == source) bound[i] = in.value;
    ++applied_;
  }
  if (!inputs.empty() && (changed || !bound.empty())) pendingArrival_ = inputs.front().arrived;
  for (const auto& [index, v] : bound) {
    const Project& project = document.project();
    if (index >= project.bindings.size()) continue;
    try {
      const ProjectParameter parameter = boundParameter(project, index);
      const Binding& b = project.bindings[index];
      const double value = boundValue(b, parameter, v);
      document.applyLiveValue(SetParameter{b.path, value});
      recordValue(document.project(), index, value);
      changed = true;
    } catch (const ModelError& e) {
      refuse(project.bindings[index].source + ": " + e.what());
    }
  }
  return changed;
}

void LivePanel::draw(ModellerState& state) {
  const Project& project = state.document.project();
  if (osc_)
    ImGui::Text("OSC: listening on 127.0.0.1:%d", osc_->port());
  else
    ImGui::TextDisabled("OSC: off (start the modeller with --osc-port P)");
  if (osc_) {
    ImGui::Text("%lld received, %lld applied, %lld malformed, %lld refused", static_cast<long long>(osc_->received()),
                static_cast<long long>(applied_), static_cast<long long>(osc_->malformed()),
                static_cast<long long>(refused_));
    if (latencySamples_ > 0)
      ImGui::Text("From a message to the preview's restart: %.1f ms (largest %.1f ms)", lastLatencyMs_,
                  largestLatencyMs_);
    if (!lastRefusal_.empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.55f, 0.45f, 1.0f));
      ImGui::TextWrapped("Last refused: %s", lastRefusal_.c_str());
      ImGui::PopStyleColor();
    }
  }
  if (midi_)
    ImGui::Text("MIDI: port gridifs:midi-in (%s)", midi_->system().c_str());
  else if (!midiProblem_.empty())
    ImGui::TextDisabled("MIDI: %s", midiProblem_.c_str());
  else
    ImGui::TextDisabled("MIDI: opens on the first Bind... (right-click a key button)");
  if (state.soundOutput)
    ImGui::Text("Sound: plays through %s", state.soundOutput->driver().c_str());
  else if (!state.soundOutputProblem.empty())
    ImGui::TextDisabled("Sound: %s", state.soundOutputProblem.c_str());
  if (!state.learnPath.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.85f, 0.35f, 1.0f));
    ImGui::TextWrapped("Move a control to bind %s", state.learnPath.c_str());
    ImGui::PopStyleColor();
    ImGui::SameLine();
    if (ImGui::SmallButton("Cancel")) state.learnPath.clear();
  }
  ImGui::Separator();
  if (ImGui::Button(recording_ ? "Stop" : "Record")) {
    if (recording_)
      stopRequested_ = true;
    else
      recording_ = true;
  }
  state.probe.item("live.record");
  if (ImGui::IsItemHovered())
    state.contextHelp = "Record a take: live input becomes keys on the bound parameters' tracks (one undo step)";
  if (recording_) {
    std::size_t keys = 0;
    for (const auto& [path, frames] : take_) keys += frames.size();
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.3f, 1.0f), "recording: %zu keys", keys);
  }
  if (project.bindings.empty()) {
    ImGui::TextWrapped("No bindings. A project's \"bindings\" drive its numbers from sound, OSC or MIDI.");
    return;
  }
  if (ImGui::BeginTable("bindings", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
    ImGui::TableSetupColumn("Parameter");
    ImGui::TableSetupColumn("Source");
    ImGui::TableSetupColumn("Range");
    ImGui::TableSetupColumn("Value");
    ImGui::TableHeadersRow();
    for (const Binding& b : project.bindings) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(b.path.c_str());
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(b.source.c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%.4g .. %.4g", b.min, b.max);
      ImGui::TableNextColumn();
      try {
        ImGui::Text("%.4g", parameterValue(project, b.path));
      } catch (const ModelError&) {
        ImGui::TextDisabled("(gone)");
      }
    }
    ImGui::EndTable();
  }
}

void LivePanel::previewRestarted() {
  if (!pendingArrival_) return;
  lastLatencyMs_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - *pendingArrival_).count();
  largestLatencyMs_ = std::max(largestLatencyMs_, lastLatencyMs_);
  ++latencySamples_;
  pendingArrival_.reset();
}

nlohmann::json LivePanel::probeJson() const {
  nlohmann::json j;
  j["osc_port"] = osc_ ? osc_->port() : 0;
  j["received"] = osc_ ? osc_->received() : 0;
  j["malformed"] = osc_ ? osc_->malformed() : 0;
  j["applied"] = applied_;
  j["refused"] = refused_;
  j["last_refusal"] = lastRefusal_;
  j["latency_ms"] = lastLatencyMs_;
  j["largest_latency_ms"] = largestLatencyMs_;
  j["latency_samples"] = latencySamples_;
  j["midi"] = midi_ ? midi_->system() : "";
  j["midi_problem"] = midiProblem_;
  j["recording"] = recording_;
  return j;
}

}  // namespace gridifs::ui
