#pragma once
// Live control in the modeller: the OSC input (`--osc-port P`, 127.0.0.1 only)
// applied between frames, and View › Live, which lists the project's bindings with their current
// values and counts what came in and what was refused.
//
// What OSC does to the project:
// - "/gridifs/set ,sf PATH VALUE" sets any parameter within its range as one undo step ("Set
//   PATH"), as Python's set() does;
// - a number in 0..1 at an address some binding listens to ("osc:ADDRESS") moves the bound
//   parameters to min + v·(max − min) without undo steps, as the playhead does: a performance,
//   not an edit.
// A malformed message, one at an address nothing listens to, a bound value outside 0..1 or a set
// the parameter refuses is counted and its reason shown, and never applied.
//
// Record turns live input into keys: while it is on, every live-bound value is noted at the
// playhead's frame (while the timeline plays, a held control leaves a key on every frame); Stop
// writes them to the parameters' tracks as one undo step ("Record take").
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "live/live_drive.h"
#include "live/midi_input.h"
#include "live/osc_listener.h"
#include "ui/base/modeller_state.h"

namespace gridifs::ui {

class LivePanel {
 public:
  /// Starts listening on 127.0.0.1:`port`; `wake` wakes the UI's event loop. Returns the problem
  /// in one sentence when the port cannot be had.
  std::string listen(int port, std::function<void()> wake);
  /// How the input threads wake the UI's event loop (before listen and openMidi).
  void setWake(std::function<void()> wake) { wake_ = std::move(wake); }
  /// Opens the MIDI input (live/midi_input.h); returns the problem in one sentence, if any.
  std::string openMidi(std::function<void()> wake);
  /// Applies the OSC messages that came since the last frame; true when the project changed.
  bool applyInput(ModellerState& state);
  /// The Live window's content.
  void draw(ModellerState& state);
  nlohmann::json probeJson() const;
  /// Called once the preview has taken the frame's project: the time from the oldest message
  /// applied this frame arriving to now is the input's latency (View › Live and the probe show
  /// the last and the largest).
  void previewRestarted();

 private:
  /// Refuses a message: counted, and its reason kept for the window.
  void refuse(const std::string& why);
  /// Analyses the project's sound again when its audio, frame rate or folder changed, and makes
  /// the bindings' curves again when they changed.
  void refreshSound(ModellerState& state);
  /// Sets the sound-bound numbers to their values at the playhead, and the live-bound ones to
  /// their last values (a time change has just put their tracks' values back).
  bool followPlayhead(ModellerState& state);

  /// Binds state.learnPath to `source` (the control just moved), as one undo step.
  void learn(ModellerState& state, const std::string& source);
  /// Applies the MIDI control changes that came since the last frame.
  void applyMidi(ModellerState& state, std::map<std::size_t, double>& bound);

  std::unique_ptr<OscListener> osc_;
  std::unique_ptr<MidiInput> midi_;
  std::function<void()> wake_;
  bool midiTried_ = false;
  std::string midiProblem_;
  std::int64_t applied_ = 0, refused_ = 0;
  std::string lastRefusal_;
  std::map<std::string, double> lastValues_;  // by source: the last value in 0..1
  std::optional<std::chrono::steady_clock::time_point> pendingArrival_;
  // The sound: what it was analysed for, and the drive made from it for the bindings.
  std::optional<AudioSettings> soundFor_;
  double soundFps_ = 0.0;
  std::filesystem::path soundFolder_;
  std::vector<Binding> driveFor_;
  LiveDrive drive_;
  std::optional<double> followedTime_;
  // A take (View › Live › Record): the live-bound values met while recording, by path and frame;
  // Stop turns them into keys as one undo step (RecordTake).
  bool recording_ = false, stopRequested_ = false;
  std::map<std::string, std::map<long, Keyframe>> take_;
  /// Notes that binding `index` has `value` at the playhead, when recording.
  void recordValue(const Project& project, std::size_t index, double value);
  /// Ends the take: its keys as one undo step.
  void finishTake(ModellerState& state);
  double lastLatencyMs_ = 0.0, largestLatencyMs_ = 0.0;
  std::int64_t latencySamples_ = 0;
};

}  // namespace gridifs::ui
