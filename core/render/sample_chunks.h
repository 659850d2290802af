#pragma once
// The chaos game's sample budget cut into fixed chunks. Chunk c plays its own chains from the
// random stream (seed, c), so what a chunk plots depends on (project, options, c) only: workers
// and render parts take whole chunks, and because every buffer sums exactly (integer hit counts,
// fixed-point colour sums, the nearest point by an order-free key), an image is the same bit for
// bit for any thread count and any split into parts.
#include <algorithm>
#include <cstdint>
#include <string>

namespace gridifs {

/// Samples (chaos-game iterations) per chunk. Every chunk restarts its kLanes chains and skips
/// their first `skip` iterations: at the default skip of 20 that is 80 of 65536 iterations
/// (0.12 %), while a chunk still takes only ~10 ms on one core, so workers finish together and a
/// render of 10^6 samples still splits into 16 parts.
inline constexpr std::int64_t kChunkSamples = std::int64_t(1) << 16;

/// A half-open range of chunk indices [begin, end).
struct ChunkRange {
  std::int64_t begin = 0, end = 0;
  std::int64_t size() const { return end > begin ? end - begin : 0; }
  bool operator==(const ChunkRange&) const = default;
};

/// Part `index` of `count` of a render (gridifs render --part K/N): which share of the work it does.
struct RenderPart {
  std::int64_t index = 0, count = 1;
  bool operator==(const RenderPart&) const = default;
};

/// The number of chunks of a budget (the last one may be short).
inline std::int64_t chunkCount(std::int64_t samples) {
  return samples <= 0 ? 0 : (samples + kChunkSamples - 1) / kChunkSamples;
}

/// The samples of chunk `c` of a budget of `samples`.
inline std::int64_t chunkSize(std::int64_t samples, std::int64_t c) {
  return std::clamp<std::int64_t>(samples - c * kChunkSamples, 0, kChunkSamples);
}

/// The samples of the chunks in `range` of a budget of `samples`.
inline std::int64_t rangeSamples(std::int64_t samples, ChunkRange range) {
  if (range.size() == 0) return 0;
  return std::min(samples, range.end * kChunkSamples) - std::min(samples, range.begin * kChunkSamples);
}

/// Part `part` of `parts` of `chunks` chunks: the contiguous share [⌊K·C/N⌋, ⌊(K+1)·C/N⌋), so the
/// parts cover every chunk exactly once and differ in size by at most one chunk.
inline ChunkRange partChunks(std::int64_t chunks, std::int64_t part, std::int64_t parts) {
  const auto at = [&](std::int64_t k) {
    return std::int64_t((unsigned __int128)(std::uint64_t(chunks)) * std::uint64_t(k) / std::uint64_t(parts));
  };
  return ChunkRange{at(part), at(part + 1)};
}

/// The chunks of a budget of `samples` that `part` plays (all of them without a part).
inline ChunkRange chunksOf(std::int64_t samples, const RenderPart* part) {
  const std::int64_t chunks = chunkCount(samples);
  return part ? partChunks(chunks, part->index, part->count) : ChunkRange{0, chunks};
}

}  // namespace gridifs
