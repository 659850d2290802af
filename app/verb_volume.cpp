// gridifs volume FILE -o OUT.vdb: the measure attractor as a density volume (Sokolov & Gentil,
// §3.4) in an OpenVDB file that Blender's Principled Volume and Houdini render as dropped in.
#include <cmath>
#include <optional>

#include "app/cli.h"
#include "app/progress_bar.h"
#include "app/render_device_option.h"
#include "app/render_parts.h"
#include "app/render_setup.h"
#include "app/set_iterate_output.h"
#include "io/project_io.h"
#include "schema/validation.h"
#include "volume/measure_attractor.h"
#include "volume/vdb_volume_file.h"

namespace gridifs::cli {
namespace {

struct VolumeArgs {
  std::string file, out;
  std::optional<int> resolution, iterations, threads;
  std::optional<std::string> samples, device;
  std::optional<std::uint64_t> seed;
  std::optional<double> time;
  std::optional<std::string> part;
  std::optional<int> depth;
  bool pages = false;
  bool quiet = false;
};

/// `--part K/N`: this part's chunks of the chaos-game points, binned and written undeveloped.
int runVolumePart(const VolumeArgs& a, const Project& project, VolumeJob& job, const RenderPart& part) {
  if (usesSetIteration(project))
    throw CliError(kBadInput, a.file +
                                  ": a volume of median functions is a set iteration, which runs whole; "
                                  "--part splits the chaos-game volumes of other projects");
  if (a.device && *a.device == "gpu")
    throw CliError(kBadInput, "--part renders volume parts on the CPU; leave out --device gpu");
  job.part = part;
  ProgressBar bar("volume part", a.quiet);
  job.progress = [&](double done) { bar.fraction(done); };
  VoxelAccumulation acc;
  try {
    acc = accumulateVoxels(project, job);
  } catch (const ModelError& e) {
    throw CliError(kBadInput, a.file + ": " + e.what());
  }
  bar.finish();
  RenderPartHeader header;
  header.kind = "volume";
  header.part = part.index;
  header.parts = part.count;
  header.device = "cpu";
  const ChunkRange chunks = chunksOf(job.settings.samples, &part);
  header.chunkBegin = chunks.begin;
  header.chunkEnd = chunks.end;
  header.source = a.file;
  Project rendered = project;
  rendered.volume = job.settings;  // the overrides, so that merge finishes the same volume
  header.project = serializeProject(rendered);
  header.options = "{}";
  header.digest = partDigest(header.kind, header.project, header.options, header.parts, header.device, std::nullopt);
  try {
    writeVolumePart(a.out, header, acc);
  } catch (const IoError& e) {
    throw CliError(kFailure, e.what());
  }
  return kSuccess;
}

int runVolume(const VolumeArgs& a) {
  if (a.depth || a.pages) {
    // Sokolov & Gentil, §3.3: the deterministic algorithm over sets instead of the measure attractor.
    if (!a.depth) throw CliError(kBadInput, "--pages needs --depth D: the book of drawings has N^D pages");
    if (a.part || a.iterations || a.samples || a.seed || a.device)
      throw CliError(kBadInput,
                     "--depth computes the set iterate itself; --part, --iterations, --samples, --seed and "
                     "--device are for the measure attractor");
    SetIterateRequest r;
    r.file = a.file;
    r.out = a.out;
    r.depth = *a.depth;
    r.pages = a.pages;
    r.resolution = a.resolution;
    r.threads = a.threads;
    r.time = a.time;
    r.quiet = a.quiet;
    return runSetIterates(r);
  }
  std::optional<RenderPart> part;
  if (a.part) {
    part = parsePart(*a.part);
    checkOutputPath(a.out, {"gpart"}, "a volume part");
  } else {
    checkOutputPath(a.out, {"vdb"}, "the volume");
  }
  const std::string device = checkedDevice(a.device);
  try {
    if (!part) requireVdbVolumeWriter();  // before the work, not after it
  } catch (const IoError& e) {
    throw CliError(kFailure, e.what());
  }
  const std::filesystem::path file(a.file);
  const Project project = loadForVerbAt(file, a.time);
  VolumeJob job;
  job.settings = project.volume.value_or(VolumeSettings{});
  VolumeSettings& s = job.settings;
  if (a.resolution) {
    if (*a.resolution < kMinVolumeResolution || *a.resolution > kMaxVolumeResolution)
      throw CliError(kBadInput, "--resolution must be between " + std::to_string(kMinVolumeResolution) + " and " +
                                    std::to_string(kMaxVolumeResolution) + ", not " + std::to_string(*a.resolution));
    s.resolution = *a.resolution;
  }
  if (a.iterations) {
    if (*a.iterations < 1 || *a.iterations > 1'000'000)
      throw CliError(kBadInput, "--iterations must be between 1 and 1000000, not " + std::to_string(*a.iterations));
    s.iterations = *a.iterations;
    s.skip = std::min(s.skip, s.iterations - 1);
  }
  if (a.samples) s.samples = parseSamples(*a.samples, limits::kMaxRenderSamples);
  if (a.seed) s.seed = *a.seed;
  if (a.threads) {
    if (*a.threads < 1 || *a.threads > limits::kMaxRenderThreads)
      throw CliError(kBadInput, "--threads must be between 1 and " + std::to_string(limits::kMaxRenderThreads));
    job.threads = *a.threads;
  }
  job.projectFolder = file.parent_path().empty() ? std::filesystem::path(".") : file.parent_path();
  if (part) return runVolumePart(a, project, job, *part);
  std::string used;
  job.binner = voxelBinnerOn(device, usesSetIteration(project), used);
  ProgressBar bar("volume", a.quiet);
  job.progress = [&](double done) { bar.fraction(done); };
  DensityVolume volume;
  try {
    volume = computeDensityVolume(project, job);
  } catch (const ModelError& e) {
    throw CliError(kBadInput, file.string() + ": " + e.what());
  }
  if (volume.totalMass <= 0.0)
    throw CliError(kFailure, file.string() + ": no point of the attractor fell inside X, so the volume is empty");
  bar.message("writing " + a.out);
  try {
    writeVdbVolume(volume, a.out);
  } catch (const IoError& e) {
    throw CliError(kFailure, e.what());
  }
  bar.finish();
  printDeviceNote();
  return kSuccess;
}

const VerbRegistration kVolume{
    {"volume",
     "FILE -o OUT.vdb [--resolution N --iterations K --samples S --seed S --threads T --time T --device D]: the "
     "measure attractor as an OpenVDB density volume; with --depth D [--pages]: the set iterate A_D or every page "
     "of the book of drawings, as .vdb, .png/.exr or .obj/.ply/.stl/.off",
     [](CLI::App& app) {
       auto a = std::make_shared<VolumeArgs>();
       app.add_option("FILE", a->file, "project file (.gridifs)")->required();
       app.add_option("-o,--output", a->out,
                      "output volume (.vdb): a fog-volume float grid \"density\", and a "
                      "vector grid \"color\" when the functions have different colours")
           ->required();
       app.add_option("--resolution", a->resolution, "voxels per axis, 16 to 512 (default: the project's, or 128)");
       app.add_option("--iterations", a->iterations,
                      "set iterations for an IFS with median functions (default: the project's, or 300)");
       app.add_option("--samples", a->samples,
                      "chaos-game points for any other IFS, e.g. 2e7 (default: the project's)");
       app.add_option("--seed", a->seed, "random seed (default: the project's)");
       app.add_option("--threads", a->threads, "worker threads (default: all cores)");
       addTimeOption(app, a->time);
       addSetOption(app);
       addDeviceOption(app, a->device);
       app.add_option("--part", a->part,
                      "bin part K of N (K/N) of the chaos-game points into -o OUT.gpart; gridifs merge makes "
                      "the .vdb");
       app.add_option("--depth", a->depth,
                      "the deterministic algorithm over sets: A_D = C ∪ ⋃ f_i(A_(D-1)) from volume.start "
                      "(default: all of X), 0 to 64; -o OUT.vdb (density 1 inside), OUT.png/.exr (drawn as "
                      "render draws), OUT.obj/.ply/.stl/.off (iso-surface)");
       app.add_flag("--pages", a->pages,
                    "with --depth: every page f_s1(...f_sD(start)) of the book of drawings, -o a pattern such as "
                    "page_%03d.png numbered by the address s1...sD in base N (at most 4096 pages)");
       app.add_flag("-q,--quiet", a->quiet, "no progress bar");
       return [a] { return runVolume(*a); };
     },
     /*hugePageHeap=*/true}};

}  // namespace
}  // namespace gridifs::cli
