#pragma once
// A sound file's band energies, one value per animation frame: frame k's window
// is the sound from k/fps to (k+1)/fps, mixed to mono, weighted by a Hann window and transformed
// (FFTW, zero-padded to a power of two); band B's energy is the sum of |X(f)|² over the bins
// whose frequency f lies in [low, high), divided by the band's largest over the file, so
// silence gives exactly 0 and the loudest frame 1.
//
// Thread-safety: an AudioEnvelope is a plain value; analyseAudio may run on any thread.
#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

namespace gridifs {

struct AudioEnvelope {
  double fps = 24.0;
  double sampleRate = 0.0;
  std::int64_t sampleCount = 0;  // per channel
  /// energy[b][k]: band b's normalized energy in frame k, in [0, 1].
  std::vector<std::vector<float>> energy;
  /// The sound mixed to mono, as min/max pairs of peaks per frame (the timeline's waveform).
  std::vector<std::array<float, 2>> peaks;
  /// The sound mixed to mono at sampleRate (what the modeller plays), shared between copies.
  std::shared_ptr<const std::vector<float>> samples;

  double seconds() const { return sampleRate > 0.0 ? double(sampleCount) / sampleRate : 0.0; }
  std::int64_t frames() const { return energy.empty() ? 0 : std::int64_t(energy.front().size()); }
  /// Band `band`'s energy curve smoothed over `smooth` seconds: a one-pole low-pass whose time
  /// constant is `smooth` (0: none), starting from silence, so silence stays exactly 0.
  std::vector<float> smoothed(int band, double smooth) const;
};

/// The frame whose window holds time t (k/fps ≤ t < (k+1)/fps); frame f's time f/fps gives f.
std::int64_t envelopeFrameAt(double t, double fps);

/// Reads `file` (any format libsndfile reads: WAV, FLAC, Ogg, AIFF, ...) and measures `bands`
/// (Hz) per frame at `fps`. Throws IoError naming the file when it cannot be read, is empty or
/// longer than six hours.
AudioEnvelope analyseAudio(const std::filesystem::path& file, const std::vector<std::array<double, 2>>& bands,
                           double fps);

}  // namespace gridifs
