#include "ui/panels/live_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "base/errors.h"
#include "edit/parameter_edit.h"
#include "model/live_binding.h"

namespace gridifs::ui {

std::string LivePanel::listen(int port, std::function<void()> wake) {
  try {
    osc_ = std::make_unique<OscListener>(port, std::move(wake));
  } catch (const IoError& e) {
    return e.what();
  }
  return {};
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
      state.document.applyLiveValue(SetParameter{b.path, boundValue(b, parameter, *v)});
      changed = true;
    } catch (const ModelError& e) {
      refuse(now.bindings[i].source + ": " + e.what());
    }
  }
  return changed;
}

bool LivePanel::applyInput(ModellerState& state) {
  refreshSound(state);
  bool changed = followPlayhead(state);
  if (!osc_) return changed;
  const std::vector<OscInput> inputs = osc_->take();
  if (inputs.empty()) return changed;
  Document& document = state.document;
  // Of several values for one bound address in a frame, the last one counts: the preview restarts
  // once per frame anyway.
  std::map<std::size_t, double> bound;  // binding index → value to set
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
    const Project& project = document.project();
    bool listened = false;
    for (std::size_t i = 0; i < project.bindings.size(); ++i)
      if (project.bindings[i].source == source) listened = true;
    if (!listened) {
      refuse(in.address + ": no binding listens to this address");
      continue;
    }
    if (!(in.value >= 0.0 && in.value <= 1.0)) {
      refuse(in.address + ": bound addresses take values from 0 to 1, not " + std::to_string(in.value));
      continue;
    }
    lastValues_[source] = in.value;
    drive_.setLive(source, in.value);
    for (std::size_t i = 0; i < project.bindings.size(); ++i)
      if (project.bindings[i].source == source) bound[i] = in.value;
    ++applied_;
  }
  if (changed || !bound.empty()) pendingArrival_ = inputs.front().arrived;
  for (const auto& [index, v] : bound) {
    const Project& project = document.project();
    if (index >= project.bindings.size()) continue;
    try {
      const ProjectParameter parameter = boundParameter(project, index);
      const Binding& b = project.bindings[index];
      document.applyLiveValue(SetParameter{b.path, boundValue(b, parameter, v)});
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
  ImGui::Separator();
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
  return j;
}

}  // namespace gridifs::ui
