// gridifs farm FILE -o OUT [--frames A:B] --parts N --dir JOBDIR [--submit] [--sbatch ARG]...:
// a render split into parts on a Slurm cluster (core/farm/farm_job.h, docs/FARM.md). Writes the
// job folder and its batch scripts; with --submit, submits the render array for the parts that
// are missing or invalid, the merge array (afterok) and the video job. `--status JOBDIR` says what
// is done. The same command again finishes an interrupted render.
#include <unistd.h>

#include <cstdio>
#include <optional>

#include "app/cli.h"
#include "app/render_parts.h"
#include "app/render_sequence.h"
#include "app/render_setup.h"
#include "base/command_line_executable.h"
#include "farm/farm_job.h"
#include "model/flame_settings.h"

namespace gridifs::cli {
namespace {

struct FarmArgs {
  std::string file, out, dir;
  std::optional<std::string> frames, status, assembleVideo, video;
  std::int64_t parts = 0;
  bool submit = false;
  std::vector<std::string> sbatch;
  // Options of every render task (as `gridifs render` takes them).
  std::optional<int> width, height, motionBlur, bitDepth;
  std::optional<std::string> samples, mode, palette, device;
  std::optional<std::uint64_t> seed;
  std::optional<double> time;
  bool transparent = false;
};

std::filesystem::path thisExecutable() {
  std::error_code ec;
  const auto self = commandLineExecutable(ec);
  if (ec) throw CliError(kFailure, "cannot find the gridifs executable for the batch scripts: " + ec.message());
  return self;
}

int showStatus(const std::string& dir) {
  try {
    for (const std::string& line : describeFarmStatus(readFarmStatus(dir))) std::printf("%s\n", line.c_str());
  } catch (const FarmError& e) {
    throw CliError(kBadInput, e.what());
  }
  return kSuccess;
}

/// The video job's work: the merged frames into the video, as `render --frames --video` does.
int assembleFarmVideo(const std::string& dir) {
  FarmRequest r;
  try {
    r = readFarmRequest(dir);
  } catch (const FarmError& e) {
    throw CliError(kBadInput, e.what());
  }
  if (!r.video || !r.firstFrame) throw CliError(kBadInput, dir + " has no video to assemble");
  const Project project = loadForVerb(r.project);
  const AnimationSettings animation = project.animation.value_or(AnimationSettings{});
  assembleVideo(r.output, FrameRange{*r.firstFrame, *r.lastFrame}, animation.fps, *r.video,
                audioFileOf(project, r.project));
  return kSuccess;
}

FarmRequest requestOf(const FarmArgs& a) {
  FarmRequest r;
  r.project = a.file;
  r.output = a.out;
  r.parts = a.parts;
  r.dir = a.dir;
  r.sbatchOptions = a.sbatch;
  r.executable = thisExecutable();
  loadForVerb(a.file);  // a bad project fails here, not on the cluster
  if (a.frames) {
    const FrameRange range = parseFrameRange(*a.frames);
    r.firstFrame = range.first;
    r.lastFrame = range.last;
    checkFramePattern(a.out);
  }
  checkOutputPath(a.out, {"png", "exr", "tif", "tiff"}, "the output image");
  if (a.video) {
    if (!a.frames) throw CliError(kBadInput, "--video needs a frame sequence: add --frames A:B");
    checkVideoOutput(*a.video);
    r.video = *a.video;
  }
  auto add = [&](const char* option, const std::string& value) {
    r.renderOptions.insert(r.renderOptions.end(), {option, value});
  };
  if (a.width) add("--width", std::to_string(*a.width));
  if (a.height) add("--height", std::to_string(*a.height));
  if (a.samples) add("--samples", std::to_string(parseSamples(*a.samples, limits::kMaxRenderSamples)));
  if (a.seed) add("--seed", std::to_string(*a.seed));
  if (a.time) {
    if (a.frames) throw CliError(kBadInput, "--time and --frames exclude each other: a frame's time is f/fps");
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", *a.time);
    add("--time", text);
  }
  if (a.mode) {
    DisplayMode mode;
    if (!parseDisplayMode(*a.mode, mode))
      throw CliError(kBadInput, "--mode must be zbuffer, flame or shaded, not \"" + *a.mode + "\"");
    add("--mode", *a.mode);
  }
  if (a.palette) add("--palette", *a.palette);
  if (a.motionBlur) add("--motion-blur", std::to_string(*a.motionBlur));
  if (a.device) {
    if (*a.device != "auto" && *a.device != "gpu" && *a.device != "cpu")
      throw CliError(kBadInput, "--device must be auto, gpu or cpu, not \"" + *a.device + "\"");
    add("--device", *a.device);
  }
  if (a.bitDepth) r.mergeOptions.insert(r.mergeOptions.end(), {"--bit-depth", std::to_string(*a.bitDepth)});
  if (a.transparent) r.mergeOptions.push_back("--transparent");
  return r;
}

int runFarm(const FarmArgs& a) {
  if (a.status) return showStatus(*a.status);
  if (a.assembleVideo) return assembleFarmVideo(*a.assembleVideo);
  if (a.file.empty() || a.out.empty() || a.dir.empty() || a.parts == 0)
    throw CliError(kBadInput, "farm needs FILE, -o OUT, --parts N and --dir JOBDIR (or --status JOBDIR)");
  if (a.parts < 1 || a.parts > kMaxFarmParts)
    throw CliError(kBadInput, "--parts must be between 1 and " + std::to_string(kMaxFarmParts));
  const FarmRequest request = requestOf(a);
  FarmPlan plan;
  try {
    writeFarmJob(request);
    // Every part's data is checked here: one damaged since it was written is rendered again.
    const FarmStatus status = readFarmStatus(request.dir, false, PartCheck::WholeData);
    plan = planFarm(status);
  } catch (const FarmError& e) {
    throw CliError(kBadInput, e.what());
  }
  const std::string dir = std::filesystem::absolute(request.dir).string();
  if (plan.renderTasks.empty() && plan.mergeFrames.empty() && !plan.video) {
    std::printf("%s: every part is rendered and every frame merged; nothing to submit\n", dir.c_str());
    return kSuccess;
  }
  std::printf("%s: %zu render task%s, %zu frame%s to merge%s\n", dir.c_str(), plan.renderTasks.size(),
              plan.renderTasks.size() == 1 ? "" : "s", plan.mergeFrames.size(), plan.mergeFrames.size() == 1 ? "" : "s",
              plan.video ? ", then the video" : "");
  if (!a.submit) {
    std::printf("submit with --submit, or by hand:\n");
    for (const std::string& line : farmSubmitCommands(request.dir, plan)) std::printf("  %s\n", line.c_str());
    return kSuccess;
  }
  try {
    for (const std::string& job : submitFarm(request.dir, plan)) std::printf("submitted job %s\n", job.c_str());
  } catch (const FarmError& e) {
    throw CliError(kFailure, e.what());
  }
  return kSuccess;
}

const VerbRegistration kFarm{
    {"farm",
     "FILE -o OUT [--frames A:B] --parts N --dir JOBDIR [--submit] [--sbatch=ARG]... [render options] | "
     "--status JOBDIR: a render split into parts on a Slurm cluster",
     [](CLI::App& app) {
       auto a = std::make_shared<FarmArgs>();
       app.add_option("FILE", a->file, "project file (.gridifs)");
       app.add_option("-o,--output", a->out, "the image, or with --frames a printf pattern such as out_%04d.png");
       app.add_option("--frames", a->frames, "frames A to B (A:B), frame f at time f/fps");
       app.add_option("--parts", a->parts, "parts per frame, each one render task");
       app.add_option("--dir", a->dir, "the job folder (on a filesystem the cluster's nodes share)");
       app.add_flag("--submit", a->submit, "submit the jobs with sbatch and print their ids");
       app.add_option("--sbatch", a->sbatch,
                      "an sbatch option for the jobs, e.g. --sbatch=--partition=render --sbatch=--time=2:00:00 "
                      "--sbatch=--gres=gpu:1 (GPU requests go to the render tasks only)")
           ->allow_extra_args(false);
       app.add_option("--status", a->status, "print the state of a job folder: parts, failed tasks, merged frames");
       app.add_option("--assemble-video", a->assembleVideo, "(used by the video job) assemble the merged frames")
           ->group("");
       app.add_option("--video", a->video, "also assemble the frames into this video (a job after the merges)");
       app.add_option("--width", a->width, "image width (default: the project's)");
       app.add_option("--height", a->height, "image height (default: the project's)");
       app.add_option("--samples", a->samples, "chaos-game iterations per frame, e.g. 1e9 (default: the project's)");
       app.add_option("--seed", a->seed, "random seed (default: the project's)");
       app.add_option("--time", a->time, "a still at this time in seconds");
       app.add_option("--mode", a->mode, "zbuffer, flame or shaded (default: the project's)");
       app.add_option("--palette", a->palette, "flame palette (as render)");
       app.add_option("--motion-blur", a->motionBlur, "time samples per frame (as render)");
       app.add_option("--device", a->device,
                      "auto, gpu or cpu for the render tasks (with gpu, add --sbatch=--gres=gpu:1)");
       app.add_option("--bit-depth", a->bitDepth, "flame mode: bits of the merged images (as render)");
       app.add_flag("--transparent", a->transparent, "flame mode: merged PNG/TIFF with alpha (as render)");
       return [a] { return runFarm(*a); };
     },
     /*hugePageHeap=*/true}};

}  // namespace
}  // namespace gridifs::cli
