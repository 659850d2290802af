#include "live/live_drive.h"

#include "base/errors.h"
#include "schema/validation.h"

namespace gridifs {

LiveDrive LiveDrive::forProject(const Project& project, const std::filesystem::path& folder) {
  bool audio = false;
  for (const Binding& b : project.bindings) {
    const auto source = parseBindingSource(b.source);
    audio |= source && source->kind == BindingSource::Kind::Audio;
  }
  if (!audio || !project.audio) return fromEnvelope(project, std::nullopt);
  std::filesystem::path file = project.audio->file;
  if (file.is_relative()) file = folder / file;
  const double fps = project.animation.value_or(AnimationSettings{}).fps;
  return fromEnvelope(project, analyseAudio(file, project.audio->bands, fps));
}

LiveDrive LiveDrive::fromEnvelope(const Project& project, std::optional<AudioEnvelope> envelope) {
  LiveDrive drive;
  drive.curves_.resize(project.bindings.size());
  drive.envelope_ = std::move(envelope);
  if (!drive.envelope_) return drive;
  for (std::size_t i = 0; i < project.bindings.size(); ++i) {
    const auto source = parseBindingSource(project.bindings[i].source);
    if (source && source->kind == BindingSource::Kind::Audio && source->band < int(drive.envelope_->energy.size()))
      drive.curves_[i] = drive.envelope_->smoothed(source->band, project.bindings[i].smooth);
  }
  return drive;
}

std::optional<double> LiveDrive::valueAt(const Project& project, std::size_t index, double t) const {
  const Binding& b = project.bindings.at(index);
  const auto source = parseBindingSource(b.source);
  if (!source) return std::nullopt;
  if (source->kind == BindingSource::Kind::Audio) {
    if (!envelope_ || index >= curves_.size() || curves_[index].empty()) return std::nullopt;
    const std::int64_t k = envelopeFrameAt(t, envelope_->fps);
    if (k < 0 || k >= std::int64_t(curves_[index].size())) return 0.0;  // silence before and after the sound
    return double(curves_[index][std::size_t(k)]);
  }
  if (auto it = live_.find(b.source); it != live_.end()) return it->second;
  if (source->kind == BindingSource::Kind::Midi && source->channel != 0) {
    // A value learnt on "midi:cc:N" serves "midi:CH:cc:N" too, and the other way round.
    if (auto any = live_.find("midi:cc:" + std::to_string(source->controller)); any != live_.end()) return any->second;
  }
  return std::nullopt;
}

bool LiveDrive::bound(const Project& project, const std::string& source) {
  for (const Binding& b : project.bindings)
    if (b.source == source) return true;
  return false;
}

void LiveDrive::applyBindings(Project& at, double t) const {
  if (at.bindings.empty()) return;
  for (std::size_t i = 0; i < at.bindings.size(); ++i) {
    const std::optional<double> v = valueAt(at, i, t);
    if (!v) continue;
    try {
      const ProjectParameter parameter = boundParameter(at, i);
      parameter.set(at, boundValue(at.bindings[i], parameter, *v));
    } catch (const ModelError& e) {
      throw ModelError("bindings[" + std::to_string(i) + "]", e.what());
    }
  }
  validateProject(at);
}

}  // namespace gridifs
