// Merging a split render (gridifs merge, docs/FARM.md): 64 part files of a 1920×1080 flame render
// of assets/twisted_functions.gridifs (supersample as in the project: 1, with the flame gutter),
// each from a real render of its chunks (2 chunks a part, 8.4 M samples in all), written with the
// render verb's own writer (app/render_parts.cpp). Then:
//   BM_MergeReadAndSum  reading every part and summing it into one accumulation, as the merge verb
//                       does (RenderPartReader + addImagePart: the same code);
//   BM_MergeVerb        `gridifs merge` on the 64 files: the above plus developing the flame and
//                       writing the PNG, in a process of its own;
//   BM_PartFileSize4K   the size of one 3840×2160 flame part (meant to stay within 100 MB)
//                       and the time to write it, for a sparse part (1/64 of a quality-25 render,
//                       3.2 M samples) and a dense one (a whole quality-25 render, 207 M samples,
//                       as one part), of twisted_functions (~5 % of the frame hit) and of the
//                       imported flame swirl_spherical (~45 %);
//   BM_PartFileSize4KFullFrame  the same for a synthetic worst case: every pixel of the frame hit
//                       (20–60 hits with palette-like colour sums, a depth gradient with noise),
//                       which no real attractor fills, as an upper bound of the size.
// Counters: "part MB" the file, "raw MB" the buffers it holds (hit counts and colour sums: a
// flame part leaves out the z-buffer keys, which developing a flame never reads).
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/render_parts.h"
#include "io/project_io.h"
#include "render/chaos_renderer.h"
#include "render/compiled_ifs.h"
#include "render/flame_render.h"
#include "tone/palette.h"

namespace gridifs {
namespace {

namespace fs = std::filesystem;

constexpr int kParts = 64;
constexpr int kThreads = 2;

/// A temporary folder, removed at exit.
struct Scratch {
  fs::path path;
  Scratch() {
    path = fs::temp_directory_path() / ("gridifs-bench-merge-" + std::to_string(::getpid()));
    fs::create_directories(path);
  }
  ~Scratch() { fs::remove_all(path); }
};

Scratch& scratch() {
  static Scratch s;
  return s;
}

/// The project at `width`×`height` as a part stores it (verb_render.cpp's partProject), with the
/// flame job that renders it.
struct FlameRender {
  Project project;
  std::shared_ptr<const CompiledIfs> ifs;
  RenderJob job;  // the supersampled flame histogram's job
  RenderPartHeader header;
};

const char* const kTwisted = "twisted_functions.gridifs";     // covers ~5 % of a 16:9 frame
const char* const kSwirl = "flames/swirl_spherical.gridifs";  // an imported flame: ~45 % of the frame

FlameRender flameRender(int width, int height, std::int64_t samples, const std::string& asset = kTwisted) {
  FlameRender r;
  const fs::path file = fs::path(GRIDIFS_ASSETS) / asset;
  r.project = loadProject(file);
  r.project.render.width = width;
  r.project.render.height = height;
  r.project.render.samples = samples;
  r.project.render.mode = DisplayMode::Flame;
  r.ifs = compileIfs(r.project);
  const auto palette =
      std::make_shared<const Palette>(resolvePalette(r.project.render.flame.palette, file.parent_path()));
  r.job = flameRenderJob(r.project, palette, kThreads);
  RenderPartHeader& h = r.header;
  h.kind = "image";
  h.parts = kParts;
  h.device = "cpu";
  h.source = file.string();
  h.project = serializeProject(r.project);
  h.options = nlohmann::json{{"mode", "flame"}, {"motion_blur", 1}, {"shutter", 0.0}}.dump();
  h.digest = cli::partDigest(h.kind, h.project, h.options, h.parts, h.device, std::nullopt);
  return r;
}

struct Written {
  std::uintmax_t bytes = 0;
  double seconds = 0.0;  // writing only
};

/// Writes `acc` as part k of `parts` of the render (as render --part does).
Written writeAccumulation(const FlameRender& r, const Accumulation& acc, std::int64_t k, std::int64_t parts,
                          const fs::path& out) {
  RenderJob job = r.job;
  job.part = RenderPart{k, parts};
  RenderPartHeader header = r.header;
  header.part = k;
  header.parts = parts;
  const ChunkRange chunks = chunksOf(job.samples, &*job.part);
  header.chunkBegin = chunks.begin;
  header.chunkEnd = chunks.end;
  header.digest = cli::partDigest(header.kind, header.project, header.options, parts, header.device, std::nullopt);
  // As render --part writes a flame part: without the z-buffer keys.
  Accumulation keyless = acc;
  std::vector<std::uint64_t>().swap(keyless.keys);
  std::vector<std::uint32_t>().swap(keyless.keys32);
  const auto start = std::chrono::steady_clock::now();
  cli::writeImagePart(out, header, {keyless});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return {fs::file_size(out), seconds};
}

/// Renders part k of the render's chunks and writes it as a part file.
Written writePart(const FlameRender& r, std::int64_t k, std::int64_t parts, const fs::path& out) {
  RenderJob job = r.job;
  job.part = RenderPart{k, parts};
  return writeAccumulation(r, accumulateToCompletion(r.ifs, job), k, parts, out);
}

struct PartSet {
  std::vector<fs::path> files;
  std::uintmax_t bytes = 0;
  double rawBytes = 0.0;  // the buffers, as read back
  double renderAndWriteSeconds = 0.0, writeSeconds = 0.0;
};

/// The 64 parts of the 1920×1080 render, written once.
const PartSet& parts1080() {
  static const PartSet set = [] {
    PartSet s;
    const FlameRender r = flameRender(1920, 1080, std::int64_t(2) * kParts * kChunkSamples);
    for (int k = 0; k < kParts; ++k) {
      const fs::path file = scratch().path / ("part_" + std::to_string(k) + ".gpart");
      const auto start = std::chrono::steady_clock::now();
      const Written w = writePart(r, k, kParts, file);
      s.renderAndWriteSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      s.bytes += w.bytes;
      s.writeSeconds += w.seconds;
      s.files.push_back(file);
    }
    s.rawBytes = double(kParts) * double(r.job.width) * double(r.job.height) * (4 + 32);  // hit counts and colour sums
    std::printf(
        "64 parts of a %d×%d flame histogram (1920×1080 + gutter): %.1f MB in all, %.2f MB a part "
        "(%.0f MB of buffers each); rendering them and writing them took %.1f s, of which writing "
        "%.1f s (%.2f s a part)\n",
        r.job.width, r.job.height, double(s.bytes) / 1e6, double(s.bytes) / 1e6 / kParts, s.rawBytes / kParts / 1e6,
        s.renderAndWriteSeconds, s.writeSeconds, s.writeSeconds / kParts);
    return s;
  }();
  return set;
}

void BM_MergeReadAndSum(benchmark::State& state) {
  const PartSet& set = parts1080();
  for (auto _ : state) {
    // One thread, as the merge verb reads each of its threads' parts: buffers reused from part to part.
    std::vector<Accumulation> sums, part;
    for (const fs::path& file : set.files) {
      RenderPartReader reader(file);
      cli::readImagePart(reader, sums.empty() ? sums : part);
      reader.finish();
      if (&file != &set.files.front()) cli::addImageParts(sums, part);
    }
    benchmark::DoNotOptimize(sums.front().colorSums.data());
    state.counters["samples"] = double(sums.front().samples);
  }
  state.counters["parts/s"] = benchmark::Counter(kParts, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["file MB/s"] =
      benchmark::Counter(double(set.bytes) / 1e6, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["raw MB/s"] = benchmark::Counter(set.rawBytes / 1e6, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["files MB"] = double(set.bytes) / 1e6;
}
BENCHMARK(BM_MergeReadAndSum)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(3);

void BM_MergeVerb(benchmark::State& state) {
  const PartSet& set = parts1080();
  std::string command = std::string("'") + GRIDIFS_EXE + "' merge";
  for (const fs::path& file : set.files) command += " '" + file.string() + "'";
  const fs::path out = scratch().path / "merged.png";
  command += " -o '" + out.string() + "'";
  for (auto _ : state) {
    if (std::system(command.c_str()) != 0) {
      state.SkipWithError("gridifs merge failed");
      break;
    }
  }
  state.counters["parts/s"] = benchmark::Counter(kParts, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_MergeVerb)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(3);

void reportPart(benchmark::State& state, const FlameRender& r, const Accumulation& acc, const Written& w) {
  const double pixels = double(r.job.width) * double(r.job.height);
  state.counters["part MB"] = double(w.bytes) / 1e6;
  state.counters["raw MB"] = double(acc.density.size() * 4 + acc.colorSums.size() * 8) / 1e6;
  state.counters["write s"] = w.seconds;
  state.counters["bytes/pixel"] = double(w.bytes) / pixels;
  state.counters["hits/pixel"] = double(acc.plotted) / pixels;
  state.counters["hit pixels %"] =
      100.0 * double(std::count_if(acc.density.begin(), acc.density.end(), [](std::uint32_t d) { return d > 0; })) /
      pixels;
}

void BM_PartFileSize4K(benchmark::State& state) {
  const std::int64_t samples = state.range(0), parts = state.range(1);
  const FlameRender r = flameRender(3840, 2160, samples * parts, state.range(2) ? kSwirl : kTwisted);
  const fs::path file = scratch().path / "part_4k.gpart";
  RenderJob job = r.job;
  job.part = RenderPart{0, parts};
  Accumulation acc;
  Written w;
  for (auto _ : state) {
    acc = accumulateToCompletion(r.ifs, job);
    w = writeAccumulation(r, acc, 0, parts, file);
  }
  reportPart(state, r, acc, w);
  fs::remove(file);
}
// Arguments: samples of the part, parts, the project (0: twisted_functions, 1: swirl_spherical).
BENCHMARK(BM_PartFileSize4K)
    ->Args({3'240'000, 64, 0})   // 1/64 of a quality-25 render (207 M samples)
    ->Args({207'360'000, 1, 0})  // the whole quality-25 render as one part
    ->Args({3'240'000, 64, 1})
    ->Args({207'360'000, 1, 1})
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(1);

void BM_PartFileSize4KFullFrame(benchmark::State& state) {
  const FlameRender r = flameRender(3840, 2160, 207'360'000);
  const std::size_t width = std::size_t(r.job.width), height = std::size_t(r.job.height), n = width * height;
  // Every pixel hit: 20–60 hits, colour sums of palette colours in 16-bit fixed point, the nearest
  // point's key (view depth bits over a gradient with noise, packed colour) as the z-buffer has it.
  Accumulation acc;
  acc.width = r.job.width;
  acc.height = r.job.height;
  acc.keys.resize(n);
  acc.density.resize(n);
  acc.colorSums.resize(4 * n);
  std::uint64_t x = 88172645463325252ull;
  auto next = [&] {
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
    return x;
  };
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t hits = 20 + std::uint32_t(next() % 41);
    acc.density[i] = hits;
    const double row = double(i / width) / double(height), col = double(i % width) / double(width);
    const float depth = float(4.0 + 1.5 * row + 0.5 * col + double(next() % 1000) * 1e-5);
    std::uint32_t depthBits;
    std::memcpy(&depthBits, &depth, 4);
    std::uint64_t packed = 0;
    for (int c = 0; c < 4; ++c) {
      const double mean = 0.5 + 0.4 * std::sin(6.0 * row + 2.0 * c + 3.0 * col);
      const double jitter = double(next() % 2000) / 2000.0 * 0.1;
      acc.colorSums[4 * i + std::size_t(c)] = std::uint64_t(double(hits) * (mean + jitter - 0.05) * kColorFixedScale);
      if (c < 3) packed |= std::uint64_t(std::uint8_t(255.0 * mean)) << (8 * c);
    }
    acc.keys[i] = std::uint64_t(depthBits) << 32 | packed;
    acc.plotted += hits;
  }
  acc.samples = acc.plotted;
  const fs::path file = scratch().path / "part_4k_full.gpart";
  Written w;
  for (auto _ : state) w = writeAccumulation(r, acc, 0, 1, file);
  reportPart(state, r, acc, w);
  fs::remove(file);
}
BENCHMARK(BM_PartFileSize4KFullFrame)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

}  // namespace
}  // namespace gridifs

BENCHMARK_MAIN();
