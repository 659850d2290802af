#include "io/point_cloud_export.h"

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "base/atomic_file.h"
#include "io/project_io.h"

namespace gridifs {

namespace fs = std::filesystem;

std::string pointCloudHeader(std::uint64_t count, const std::string& description) {
  const std::size_t padTo = 24;  // digits of the largest count plus slack
  const std::string pad = "comment " + std::string(padTo - std::to_string(count).size(), '-') + "\n";
  return "ply\nformat binary_little_endian 1.0\ncomment " + description + "\n" + pad + "element vertex " +
         std::to_string(count) +
         "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\nproperty uchar green\n"
         "property uchar blue\nend_header\n";
}

std::string pointCloudDescription(const std::string& source, const RenderJob& job) {
  return "GridIFS export-points of " + (source.empty() ? std::string("untitled") : source) + ": " +
         std::to_string(job.samples) + " samples, seed " + std::to_string(job.seed) + ", " +
         std::to_string(job.threads) + " streams";
}

PointCloudResult writePointCloud(const CompiledIfs& ifs, const RenderJob& job, const fs::path& out,
                                 const std::string& description,
                                 const std::function<bool(const RenderStats&)>& progress,
                                 const PointGenerator& generator) {
  AtomicFile atomic(out);
  std::FILE* f = std::fopen(atomic.temporaryPath().c_str(), "wb");
  if (!f) throw IoError("cannot write " + out.string() + ": " + std::strerror(errno));
  struct CloseOnExit {
    std::FILE*& f;
    ~CloseOnExit() {
      if (f) std::fclose(f);
    }
  } closeOnExit{f};
  auto write = [&](const void* data, std::size_t bytes) {
    if (bytes && std::fwrite(data, 1, bytes, f) != bytes)
      throw IoError("cannot write " + out.string() + ": " + std::strerror(errno));
  };
  const std::string header0 = pointCloudHeader(0, description);
  write(header0.data(), header0.size());
  PointCloudResult result;
  std::vector<unsigned char> record;
  const PointGenerator walk = generator ? generator : PointGenerator(generatePoints);
  result.stats = walk(ifs, job, [&](const PointBatch& batch, const RenderStats& s) {
    record.resize(batch.count * 15);
    unsigned char* w = record.data();
    for (std::size_t i = 0; i < batch.count; ++i, w += 15) {
      for (int d = 0; d < 3; ++d) {
        std::uint32_t bits = std::bit_cast<std::uint32_t>(batch.xyz[3 * i + d]);
        if constexpr (std::endian::native == std::endian::big) bits = __builtin_bswap32(bits);
        std::memcpy(w + 4 * d, &bits, 4);
      }
      for (int c = 0; c < 3; ++c)
        w[12 + c] = (unsigned char)std::lround(std::clamp(batch.rgb[3 * i + c], 0.0f, 1.0f) * 255.0f);
    }
    write(record.data(), record.size());
    result.written += batch.count;
    result.cancelled = progress && !progress(s);
    return !result.cancelled;
  });
  if (result.cancelled) return result;
  if (result.stats.badFraction() >= 0.5)
    throw ModelError("", std::to_string(int(std::lround(100 * result.stats.badFraction()))) +
                             "% of the chaos-game points were non-finite or escaped, so the IFS has no usable "
                             "attractor; " +
                             out.string() + " was not written");
  const std::string header = pointCloudHeader(result.written, description);
  if (std::fseek(f, 0, SEEK_SET) != 0) throw IoError("cannot write " + out.string() + ": " + std::strerror(errno));
  write(header.data(), header.size());
  if (std::fflush(f) != 0) throw IoError("cannot write " + out.string() + ": " + std::strerror(errno));
  const int closed = std::fclose(f);
  f = nullptr;
  if (closed != 0) throw IoError("cannot write " + out.string() + ": " + std::strerror(errno));
  atomic.commit();
  return result;
}

}  // namespace gridifs
