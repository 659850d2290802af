#pragma once
// The modeller's sound while the timeline plays (SDL2's audio): the project's sound from the
// playhead on, whose played samples are the playback's clock, so picture and sound stay together.
// Where the machine has no audio output, open() says why and the timeline keeps its silent clock.
//
// Thread-safety: SDL's audio thread reads the samples; the other methods belong to the UI thread.
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace gridifs {

class SoundOutput {
 public:
  /// The default audio output, or null with `why` saying in one sentence why there is none.
  static std::unique_ptr<SoundOutput> open(std::string& why);
  ~SoundOutput();
  SoundOutput(const SoundOutput&) = delete;
  SoundOutput& operator=(const SoundOutput&) = delete;

  /// SDL's name of the output's driver ("pulseaudio", "alsa", ...).
  const std::string& driver() const { return driver_; }
  /// Plays `samples` (mono at `sampleRate`) from `fromSeconds` on.
  void play(std::shared_ptr<const std::vector<float>> samples, double sampleRate, double fromSeconds);
  void stop();
  bool playing() const { return playing_; }
  /// The sound's time played so far (its clock), in seconds of the sound.
  double seconds() const;

 private:
  SoundOutput() = default;
  static void fill(void* self, std::uint8_t* stream, int bytes);

  std::uint32_t device_ = 0;
  int deviceRate_ = 0;
  std::string driver_;
  bool playing_ = false;
  std::shared_ptr<const std::vector<float>> samples_;
  double step_ = 1.0;                  // sound samples per device sample
  std::atomic<double> position_{0.0};  // in sound samples
  double sampleRate_ = 0.0;
};

}  // namespace gridifs
