// Analysing a song for "audio:B" bindings (live/audio_envelope.h): a 4-minute stereo 44.1 kHz
// WAV (a kick, a swelling chord and hiss, like a song's bands), three bands at 24 fps. Goal:
// at most 2 s. Reports wall and CPU seconds of the whole analysis (reading, mixing, 5760 FFTs).
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <vector>

#include "live/audio_envelope.h"
#include "tests/bench/process_cpu_time.h"
#include "tests/support/sound_file.h"

namespace gridifs {
namespace {

std::filesystem::path songFile() {
  static const std::filesystem::path file = [] {
    const auto path = std::filesystem::temp_directory_path() / "gridifs-bench-song.wav";
    const int rate = 44100, seconds = 240;
    std::vector<float> stereo(std::size_t(2) * rate * seconds);
    std::mt19937 noise(5);
    std::normal_distribution<float> hiss(0.0f, 0.05f);
    for (int i = 0; i < rate * seconds; ++i) {
      const double t = double(i) / rate;
      const double kick = std::sin(2 * M_PI * 60 * t) * std::exp(-std::fmod(t, 0.5) * 12);
      const double chord = (std::sin(2 * M_PI * 440 * t) + std::sin(2 * M_PI * 660 * t)) * (0.5 - 0.5 * std::cos(t));
      stereo[2 * std::size_t(i)] = float(0.4 * kick + 0.2 * chord + hiss(noise));
      stereo[2 * std::size_t(i) + 1] = float(0.4 * kick - 0.2 * chord);
    }
    test_support::writeWav(path, stereo, rate, 2);
    return path;
  }();
  return file;
}

void BM_AnalyseFourMinuteSong(benchmark::State& state) {
  const auto file = songFile();
  double cpu = 0.0;
  std::int64_t frames = 0;
  for (auto _ : state) {
    const double cpu0 = processCpuSeconds();
    const AudioEnvelope e = analyseAudio(file, {{20, 200}, {200, 2000}, {2000, 12000}}, 24.0);
    cpu += processCpuSeconds() - cpu0;
    frames = e.frames();
    benchmark::DoNotOptimize(e.energy.data());
  }
  state.counters["frames"] = double(frames);
  state.counters["cpu_seconds"] = cpu / double(state.iterations());
}
BENCHMARK(BM_AnalyseFourMinuteSong)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

}  // namespace
}  // namespace gridifs

BENCHMARK_MAIN();
