#pragma once
// MIDI controllers for live bindings ("midi:cc:N", "midi:CH:cc:N"; docs/LIVE.md) through RtMidi:
// a virtual input port named "gridifs:midi-in" that controllers and sequencers connect to. The
// ALSA sequencer where the machine has one (/dev/snd/seq), else a running JACK server (JACK's
// dummy driver needs no sound hardware). Control changes are queued for the UI thread.
//
// Thread-safety: RtMidi's callback thread queues; take() may be called from any thread.
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

class RtMidiIn;

namespace gridifs {

struct MidiControl {
  int channel = 1;     // 1..16
  int controller = 0;  // 0..127
  int value = 0;       // 0..127
};

class MidiInput {
 public:
  /// Opens the virtual port; `wake` is called after each queued control change. Throws IoError
  /// with one sentence when there is no MIDI system to open it in.
  explicit MidiInput(std::function<void()> wake = {});
  ~MidiInput();
  MidiInput(const MidiInput&) = delete;
  MidiInput& operator=(const MidiInput&) = delete;

  /// "ALSA" or "JACK".
  const std::string& system() const { return system_; }
  /// The control changes since the last call, oldest first.
  std::vector<MidiControl> take();
  /// Messages received that were no control change (notes, clock, ...): not used, counted.
  std::int64_t ignored() const;

  /// A control change from a raw MIDI message, or false.
  static bool decode(const std::vector<unsigned char>& message, MidiControl& out);

 private:
  static void received(double, std::vector<unsigned char>* message, void* self);

  std::unique_ptr<RtMidiIn> in_;
  std::string system_;
  std::function<void()> wake_;
  mutable std::mutex lock_;
  std::vector<MidiControl> queue_;
  std::int64_t ignored_ = 0;
};

}  // namespace gridifs
