// gridifs export-points FILE -o OUT.ply --samples N: the chaos-game points the renderer would plot
// (same worker streams, skip and final function; not culled to the frame) as a binary
// little-endian PLY with x y z float and red green blue uchar (DESIGN §4; issue 3).
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "app/cli.h"
#include "app/progress_bar.h"
#include "app/render_setup.h"

namespace gridifs::cli {
namespace {

/// 15 bytes per point: a billion points is a 15 GB file, which is plenty.
constexpr std::int64_t kMaxExportSamples = 1'000'000'000;
constexpr std::int64_t kDefaultExportSamples = 1'000'000;

/// The header is written twice: first with a zero count, then, once the number of points is known
/// (bad samples and skipped iterations are not exported), rewritten in place at the same length.
/// A comment line absorbs the difference in digits.
std::string plyHeader(std::uint64_t count, const std::string& description) {
  std::string head = "ply\nformat binary_little_endian 1.0\ncomment " + description + "\n";
  const std::string tail =
      "element vertex " + std::to_string(count) +
      "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\nproperty uchar green\n"
      "property uchar blue\nend_header\n";
  const std::size_t padTo = 24;  // digits of the largest count plus slack
  const std::string pad = "comment " + std::string(padTo - std::to_string(count).size(), '-') + "\n";
  return head + pad + tail;
}

struct File {
  std::FILE* f = nullptr;
  ~File() {
    if (f) std::fclose(f);
  }
};

void writeOrThrow(std::FILE* f, const void* data, std::size_t bytes, const std::string& out) {
  if (bytes && std::fwrite(data, 1, bytes, f) != bytes)
    throw CliError(kFailure, "cannot write " + out + ": " + std::strerror(errno));
}

int runExportPoints(const std::string& file, const std::string& out, RenderOverrides overrides, bool quiet) {
  checkOutputPath(out, {"ply"}, "the point file");
  if (!overrides.samples) overrides.samples = std::to_string(kDefaultExportSamples);
  const RenderSetup setup = prepareRender(file, overrides, kMaxExportSamples);
  const std::string description = "GridIFS export-points of " + std::filesystem::path(file).filename().string() +
                                  ": " + std::to_string(setup.job.samples) + " samples, seed " +
                                  std::to_string(setup.job.seed) + ", " + std::to_string(setup.job.threads) +
                                  " streams";
  AtomicOutput output(out);
  File handle;
  handle.f = std::fopen(output.tempPath().c_str(), "wb");
  if (!handle.f) throw CliError(kFailure, "cannot write " + out + ": " + std::strerror(errno));
  const std::string header0 = plyHeader(0, description);
  writeOrThrow(handle.f, header0.data(), header0.size(), out);

  ProgressBar bar("export-points", !quiet && stderrIsTerminal());
  std::vector<unsigned char> record;
  std::uint64_t written = 0;
  const RenderStats stats =
      generatePoints(*setup.ifs, setup.job, [&](const PointBatch& batch, const RenderStats& s) {
        record.resize(batch.count * 15);
        unsigned char* w = record.data();
        for (std::size_t i = 0; i < batch.count; ++i, w += 15) {
          for (int d = 0; d < 3; ++d) {
            std::uint32_t bits = std::bit_cast<std::uint32_t>(batch.xyz[3 * i + d]);
            if constexpr (std::endian::native == std::endian::big) bits = __builtin_bswap32(bits);
            std::memcpy(w + 4 * d, &bits, 4);
          }
          for (int c = 0; c < 3; ++c) w[12 + c] = (unsigned char)std::lround(batch.rgb[3 * i + c] * 255.0f);
        }
        writeOrThrow(handle.f, record.data(), record.size(), out);
        written += batch.count;
        bar.update(s.samples, s.budget, s.pointsPerSecond, s.done);
        return true;
      });
  bar.finish();
  if (stats.badFraction() >= 0.5)
    throw CliError(kBadInput, file + ": " + std::to_string(int(std::lround(100 * stats.badFraction()))) +
                                  "% of the chaos-game points were non-finite or escaped, so the IFS has no usable "
                                  "attractor; " + out + " was not written");
  const std::string header = plyHeader(written, description);
  if (header.size() != header0.size()) throw CliError(kFailure, "internal error: PLY header length changed");
  if (std::fseek(handle.f, 0, SEEK_SET) != 0) throw CliError(kFailure, "cannot write " + out + ": " + std::strerror(errno));
  writeOrThrow(handle.f, header.data(), header.size(), out);
  const int closed = std::fclose(handle.f);
  handle.f = nullptr;
  if (closed != 0) throw CliError(kFailure, "cannot write " + out + ": " + std::strerror(errno));
  output.commit();
  return kSuccess;
}

const VerbRegistration kExportPoints{
    {"export-points", "FILE -o OUT.ply [--samples N --seed S --threads T]: chaos-game points with colours",
     [](CLI::App& app) {
       auto file = std::make_shared<std::string>();
       auto out = std::make_shared<std::string>();
       auto o = std::make_shared<RenderOverrides>();
       auto quiet = std::make_shared<bool>(false);
       app.add_option("FILE", *file, "project file (.gridifs)")->required();
       app.add_option("-o,--output", *out, "output point cloud (.ply, binary little-endian)")->required();
       app.add_option("--samples", o->samples, "chaos-game iterations, e.g. 1e6 (default 1000000)");
       app.add_option("--seed", o->seed, "random seed (default: the project's)");
       app.add_option("--threads", o->threads,
                      "number of worker streams to reproduce (default: all cores, like render)");
       app.add_flag("-q,--quiet", *quiet, "no progress bar");
       return [=] { return runExportPoints(*file, *out, *o, *quiet); };
     }}};

}  // namespace
}  // namespace gridifs::cli
