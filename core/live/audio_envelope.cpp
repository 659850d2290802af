#include "live/audio_envelope.h"

#include <fftw3.h>
#include <sndfile.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>

#include "base/errors.h"

namespace gridifs {
namespace {

constexpr double kMaxSeconds = 6.0 * 3600.0;

struct SoundFile {
  SNDFILE* handle = nullptr;
  SF_INFO info{};
  ~SoundFile() {
    if (handle) sf_close(handle);
  }
};

/// The whole file mixed to mono (the channels' mean).
std::vector<float> readMono(const std::filesystem::path& file, double& sampleRate) {
  SoundFile sound;
  sound.handle = sf_open(file.c_str(), SFM_READ, &sound.info);
  if (!sound.handle) throw IoError("cannot read the audio file " + file.string() + ": " + sf_strerror(nullptr));
  const SF_INFO& info = sound.info;
  if (info.samplerate <= 0 || info.channels <= 0 || info.frames <= 0)
    throw IoError("the audio file " + file.string() + " holds no sound");
  if (double(info.frames) / info.samplerate > kMaxSeconds)
    throw IoError("the audio file " + file.string() + " is longer than six hours");
  sampleRate = info.samplerate;
  std::vector<float> mono(std::size_t(info.frames), 0.0f);
  std::vector<float> block(std::size_t(4096) * std::size_t(info.channels));
  sf_count_t done = 0;
  while (done < info.frames) {
    const sf_count_t want = std::min<sf_count_t>(4096, info.frames - done);
    const sf_count_t got = sf_readf_float(sound.handle, block.data(), want);
    if (got <= 0) break;
    for (sf_count_t i = 0; i < got; ++i) {
      float sum = 0.0f;
      for (int c = 0; c < info.channels; ++c) sum += block[std::size_t(i * info.channels + c)];
      mono[std::size_t(done + i)] = sum / float(info.channels);
    }
    done += got;
  }
  mono.resize(std::size_t(done));
  if (mono.empty()) throw IoError("the audio file " + file.string() + " holds no sound");
  return mono;
}

// FFTW's planner is not thread-safe; executing a plan is.
std::mutex& plannerLock() {
  static std::mutex lock;
  return lock;
}

}  // namespace

std::int64_t envelopeFrameAt(double t, double fps) {
  // The small allowance keeps f/fps in frame f despite rounding.
  return std::int64_t(std::floor(t * fps + 1e-6));
}

std::vector<float> AudioEnvelope::smoothed(int band, double smooth) const {
  const std::vector<float>& raw = energy.at(std::size_t(band));
  if (!(smooth > 0.0)) return raw;
  const double alpha = 1.0 - std::exp(-1.0 / (fps * smooth));
  std::vector<float> out(raw.size());
  double y = 0.0;
  for (std::size_t k = 0; k < raw.size(); ++k) {
    y += alpha * (double(raw[k]) - y);
    out[k] = float(y);
  }
  return out;
}

AudioEnvelope analyseAudio(const std::filesystem::path& file, const std::vector<std::array<double, 2>>& bands,
                           double fps) {
  AudioEnvelope envelope;
  envelope.fps = fps;
  std::vector<float> mono = readMono(file, envelope.sampleRate);
  envelope.sampleCount = std::int64_t(mono.size());
  const double samplesPerFrame = envelope.sampleRate / fps;
  const std::int64_t frames = std::max<std::int64_t>(1, std::int64_t(std::ceil(double(mono.size()) / samplesPerFrame)));
  const std::int64_t longest = std::int64_t(std::ceil(samplesPerFrame)) + 1;
  int n = 256;
  while (n < longest) n *= 2;

  float* input = fftwf_alloc_real(std::size_t(n));
  fftwf_complex* output = fftwf_alloc_complex(std::size_t(n / 2 + 1));
  fftwf_plan plan;
  {
    std::lock_guard<std::mutex> hold(plannerLock());
    plan = fftwf_plan_dft_r2c_1d(n, input, output, FFTW_ESTIMATE);
  }
  // Each band's bins: [first, last).
  std::vector<std::array<int, 2>> bins;
  for (const auto& band : bands) {
    const int first = int(std::ceil(band[0] * n / envelope.sampleRate));
    const int last = std::min(n / 2 + 1, int(std::ceil(band[1] * n / envelope.sampleRate)));
    bins.push_back({std::min(first, last), last});
  }
  envelope.energy.assign(bands.size(), std::vector<float>(std::size_t(frames), 0.0f));
  envelope.peaks.assign(std::size_t(frames), {0.0f, 0.0f});
  std::vector<double> hann;
  for (std::int64_t k = 0; k < frames; ++k) {
    const std::int64_t begin = std::int64_t(std::floor(double(k) * samplesPerFrame));
    const std::int64_t end =
        std::min<std::int64_t>(std::int64_t(mono.size()), std::int64_t(std::floor(double(k + 1) * samplesPerFrame)));
    const std::int64_t length = std::max<std::int64_t>(0, end - begin);
    if (std::int64_t(hann.size()) != length) {
      hann.resize(std::size_t(length));
      for (std::int64_t i = 0; i < length; ++i)
        hann[std::size_t(i)] = length > 1 ? 0.5 - 0.5 * std::cos(2.0 * M_PI * double(i) / double(length - 1)) : 1.0;
    }
    float lo = 0.0f, hi = 0.0f;
    for (std::int64_t i = 0; i < n; ++i) {
      const float s = i < length ? mono[std::size_t(begin + i)] : 0.0f;
      if (i < length) lo = std::min(lo, s), hi = std::max(hi, s);
      input[i] = i < length ? float(double(s) * hann[std::size_t(i)]) : 0.0f;
    }
    envelope.peaks[std::size_t(k)] = {lo, hi};
    fftwf_execute(plan);
    for (std::size_t b = 0; b < bins.size(); ++b) {
      double sum = 0.0;
      for (int i = bins[b][0]; i < bins[b][1]; ++i)
        sum += double(output[i][0]) * output[i][0] + double(output[i][1]) * output[i][1];
      envelope.energy[b][std::size_t(k)] = float(sum);
    }
  }
  {
    std::lock_guard<std::mutex> hold(plannerLock());
    fftwf_destroy_plan(plan);
  }
  fftwf_free(input);
  fftwf_free(output);
  envelope.samples = std::make_shared<const std::vector<float>>(std::move(mono));
  // Divided by the band's largest: energies in float are non-negative, silence exactly 0.
  for (std::vector<float>& band : envelope.energy) {
    const float largest = *std::max_element(band.begin(), band.end());
    if (largest > 0.0f)
      for (float& e : band) e /= largest;
  }
  return envelope;
}

}  // namespace gridifs
