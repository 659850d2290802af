#pragma once
// What drives a project's bound numbers at a moment (schema/live_binding.h): the audio bindings'
// curves, analysed once from the project's sound, and the last values live input (OSC, MIDI)
// sent. applyBindings writes them over what the tracks say.
//
// Thread-safety: a LiveDrive is a plain value; const methods may run on any thread.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "live/audio_envelope.h"
#include "model/project.h"
#include "schema/live_binding.h"

namespace gridifs {

class LiveDrive {
 public:
  LiveDrive() = default;
  /// Analyses the sound of `project`'s "audio" (its file relative to `folder`) when an audio
  /// binding reads it, at the project's frame rate. Throws IoError when the sound cannot be read.
  static LiveDrive forProject(const Project& project, const std::filesystem::path& folder);
  /// The same from a sound already analysed for `project`'s audio (or none): only the bindings'
  /// curves are made.
  static LiveDrive fromEnvelope(const Project& project, std::optional<AudioEnvelope> envelope);

  /// The sound's analysis, when the project has audio bindings.
  const std::optional<AudioEnvelope>& envelope() const { return envelope_; }
  /// The value in [0, 1] binding `index` reads at time t: an audio band's smoothed energy in the
  /// frame at t (0 past the sound's end), or the last live value sent to its source (nothing when
  /// none came yet: the parameter keeps its track's value).
  std::optional<double> valueAt(const Project& project, std::size_t index, double t) const;

  /// A live source's new value (v in [0, 1]; "osc:/knob1", "midi:cc:7", "midi:1:cc:7").
  void setLive(const std::string& source, double v) { live_[source] = v; }
  /// Whether a binding of `project` reads `source` (an OSC address or MIDI controller).
  static bool bound(const Project& project, const std::string& source);

  /// Sets every bound number of `at` (the project at time t) that has a value. Throws ModelError
  /// naming the binding when the result is not a valid project.
  void applyBindings(Project& at, double t) const;

 private:
  std::optional<AudioEnvelope> envelope_;
  /// Per binding index: the audio curve, smoothed as the binding asks (empty for live sources).
  std::vector<std::vector<float>> curves_;
  std::map<std::string, double> live_;
};

}  // namespace gridifs
