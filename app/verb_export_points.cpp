// gridifs export-points FILE -o OUT.ply --samples N: the chaos-game points the renderer would plot
// (same worker streams, skip and final function; not culled to the frame) as a binary
// little-endian PLY with x y z float and red green blue uchar.
#include "app/chaos_verb_options.h"
#include "app/cli.h"
#include "app/progress_bar.h"
#include "app/render_device_option.h"
#include "app/render_setup.h"
#include "io/point_cloud_export.h"
#include "io/project_io.h"

namespace gridifs::cli {
namespace {

/// 15 bytes per point: a billion points is a 15 GB file, which is plenty.
constexpr std::int64_t kMaxExportSamples = 1'000'000'000;
constexpr std::int64_t kDefaultExportSamples = 1'000'000;

int runExportPoints(const std::string& file, const std::string& out, RenderOverrides overrides, bool quiet) {
  checkOutputPath(out, {"ply"}, "the point file");
  const std::string device = checkedDevice(overrides.device);
  if (!overrides.samples) overrides.samples = std::to_string(kDefaultExportSamples);
  const PreparedRender setup = preparePointsOf(file, overrides, kMaxExportSamples);
  const std::string description = pointCloudDescription(std::filesystem::path(file).filename().string(), setup.output);
  std::string used;
  const PointGenerator generator = pointGeneratorOn(device, used);
  ProgressBar bar("export-points", quiet);
  try {
    writePointCloud(
        *setup.ifs, setup.output, out, description, [&](const RenderStats& s) { return bar.report(s); }, generator);
  } catch (const ModelError& e) {
    throw CliError(kBadInput, file + ": " + e.message());
  } catch (const IoError& e) {
    throw CliError(kFailure, e.what());
  }
  bar.finish();
  printDeviceNote();
  return kSuccess;
}

const VerbRegistration kExportPoints{
    {"export-points",
     "FILE -o OUT.ply [--samples N --seed S --threads T --device auto|gpu|cpu]: chaos-game points with colours",
     [](CLI::App& app) {
       const auto a = addChaosVerbOptions(app, "output point cloud (.ply, binary little-endian)",
                                          "chaos-game iterations, e.g. 1e6 (default 1000000)",
                                          "number of worker streams to reproduce (default: all cores, like render)");
       return [=] { return runExportPoints(a->file, a->out, a->overrides, a->quiet); };
     },
     /*hugePageHeap=*/true}};

}  // namespace
}  // namespace gridifs::cli
