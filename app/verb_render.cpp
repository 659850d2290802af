// gridifs render FILE -o OUT.(png|exr|tif): the stochastic renderer headlessly through
// OpenImageIO. PNG/TIFF: 8-bit RGB with the background composited. EXR: float
// R G B A (linear, premultiplied, A = coverage) plus a Z channel with the view depth, so
// compositors can use it.

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "app/chaos_verb_options.h"
#include "app/cli.h"
#include "app/heap_warmup.h"
#include "app/progress_bar.h"
#include "app/render_device_option.h"
#include "app/render_parts.h"
#include "app/render_sequence.h"
#include "app/render_setup.h"
#include "app/render_volume.h"
#include "io/project_io.h"
#include "job/frame_output.h"
#include "render/flame_render.h"
#include "render/image_file.h"
#include "render/motion_blur.h"
#include "schema/settings_tables.h"

namespace gridifs::cli {
namespace {

std::atomic<bool> gInterrupted{false};

extern "C" void onInterrupt(int) { gInterrupted.store(true); }

/// Ctrl-C stops the render cleanly (the temporary output is removed) instead of killing it.
struct InterruptGuard {
  void (*previous)(int);
  InterruptGuard() : previous(std::signal(SIGINT, onInterrupt)) { gInterrupted.store(false); }
  ~InterruptGuard() { std::signal(SIGINT, previous); }
};

/// Writes the frame through core's frame step (job/frame_output.h), with the command line's exit
/// codes: 1 when the file cannot be written, 2 when the project cannot develop the image.
void writeFrameFile(const RenderImage& image, const PreparedRender& frame, const std::string& file,
                    const std::string& out, const FlameOptions& flame) {
  FrameOutput output;
  output.file = out;
  output.source = std::filesystem::path(file).filename().string();
  output.bitDepth = flame.bitDepth.value_or(0);
  output.transparent = flame.transparent;
  try {
    writeFrame(image, frame.project, frame.output, frame.job, output);
  } catch (const IoError& e) {
    throw CliError(kFailure, e.what());
  } catch (const ModelError& e) {
    throw CliError(kBadInput, file + ": " + e.what());
  } catch (const std::invalid_argument& e) {
    throw CliError(kBadInput, file + ": " + e.what());
  }
}

/// Where a frame's accumulation goes or comes from. Rendered and developed (the default); rendered
/// and written as a part file (`part`: render --part); or taken from merged parts (`merged`:
/// gridifs merge), developed exactly as a render would.
struct FrameSource {
  struct PartTarget {
    RenderPart part;
    std::optional<std::int64_t> frame;
    std::string options;  // the finishing options as JSON (mode, motion blur, shutter)
    /// The flame display develops from hit counts and colour sums alone: its parts leave out the
    /// z-buffer keys (a quarter of a part's bytes), and a merge develops the same image.
    bool withoutKeys = false;
  };
  std::optional<PartTarget> part;
  const std::vector<Accumulation>* merged = nullptr;
};

/// Where one frame's samples sit in the progress of a whole sequence (one bar over all frames).
struct FrameProgress {
  ProgressBar* bar = nullptr;                             // null: the frame draws its own bar
  std::int64_t before = 0;                                // samples of the frames already rendered
  std::int64_t total = 0;                                 // samples of every frame of the sequence
  const std::function<bool(double)>* observer = nullptr;  // RenderOverrides::observer, when given
  /// --threads was given: at most that many threads run at once, so nothing runs beside the
  /// workers (the image library loads before them, and the heap is not warmed).
  bool threadsBounded = false;
};

/// The project as a part stores it: as rendered at the frame's time, with the job's size, samples
/// and seed in its render settings, so that `merge` rebuilds the same job from it alone.
std::string partProject(const PreparedRender& frame) {
  Project p = frame.project;
  p.render.width = frame.output.width;
  p.render.height = frame.output.height;
  p.render.samples = frame.output.samples;
  p.render.quality.reset();  // the samples above are the count rendered
  p.render.seed = frame.output.seed;
  return serializeProject(p);
}

/// Runs the time samples of one frame (core's prepareTimeSamples: each with its own camera, share
/// of the samples and seed) to completion on `device` (app/render_device_option.h) with a progress
/// bar (interruptible with Ctrl-C), and merges them. With source.part it writes the accumulations
/// as a part file and returns nothing; with source.merged it renders nothing and develops the
/// merged accumulations instead (`samples` then holds the one prepareDevelop made).
/// Throws CliError when interrupted or when at least half of the points were unusable (nothing is
/// written then).
std::optional<RenderImage> renderWithProgress(const std::vector<TimeSample>& samples, const std::string& file,
                                              const std::string& out, bool quiet, const std::string& device,
                                              FrameProgress progress, const FrameSource& source, double motionFade) {
  ProgressBar ownBar(source.merged ? "merge" : "render", quiet || source.merged);
  ProgressBar& bar = progress.bar ? *progress.bar : ownBar;
  const PreparedRender& frame = samples.front().render;
  const std::int64_t count = std::int64_t(samples.size());
  if (!progress.bar) {
    // A part's bar runs over its own share (on the CPU: its chunks of every time sample).
    progress.total = 0;
    for (const TimeSample& sample : samples)
      progress.total +=
          source.part ? rangeSamples(sample.render.job.samples, chunksOf(sample.render.job.samples, &source.part->part))
                      : sample.render.job.samples;
  }
  std::optional<InterruptGuard> interrupt;
  if (!progress.observer) interrupt.emplace();  // an observer's caller handles Ctrl-C itself
  std::int64_t done = 0;
  std::vector<Accumulation> accumulations;
  std::string used = "cpu";
  // The command line renders once and exits, so it keeps freed memory for the output image; a
  // caller with an observer (the Python module) lives on, and its process keeps malloc's habits.
  bool warmed = source.part.has_value() || progress.observer || progress.threadsBounded;
  if (!warmed) keepFreedMemory();
  if (progress.threadsBounded && !source.part && !source.merged) loadImageWriterNow();
  for (const TimeSample& sample : samples) {
    if (source.merged) break;
    RenderJob job = sample.render.job;
    if (source.part) job.part = source.part->part;
    try {
      accumulations.push_back(accumulateOnDevice(
          device, sample.render.ifs, job,
          [&](const RenderStats& s) {
            // The image library loads on a second core while the chaos game runs, started once the
            // workers run: dlopen holds the dynamic loader's lock while it maps and relocates
            // OpenImageIO's ~230 libraries (0.2 s), and started earlier it kept the main thread
            // waiting on that lock before the workers could start.
            if (!source.part) {
              startLoadingImageWriter();
              // Once the library is in, the main thread has nothing to do until the chaos game
              // ends: it prepares the memory the output will need (app/heap_warmup.h).
              if (!warmed && imageWriterLoaded()) {
                warmHeap(renderOutputBytes(job.width, job.height, job.accumulateColor));
                warmed = true;
              }
            }
            bar.update(progress.before + done + s.samples, progress.total, s.pointsPerSecond);
            if (progress.observer && progress.total > 0 &&
                !(*progress.observer)(
                    std::min(1.0, double(progress.before + done + s.samples) / double(progress.total))))
              return false;
            return !gInterrupted.load();
          },
          used));
    } catch (const RenderCancelled&) {
      bar.finish();
      throw CliError(kFailure, "render of " + file + " interrupted; " + out + " was not written");
    }
    done += job.samples;
  }
  if (source.part) {
    if (!progress.bar) bar.finish();
    RenderPartHeader header;
    header.kind = "image";
    header.part = source.part->part.index;
    header.parts = source.part->part.count;
    header.device = used;
    RenderJob first = frame.job;
    first.samples = frame.output.samples / count;
    first.part = source.part->part;
    const ChunkRange chunks = playedRange(used, first);
    header.chunkBegin = chunks.begin;
    header.chunkEnd = chunks.end;
    header.frame = source.part->frame;
    header.source = file;
    header.project = partProject(frame);
    header.options = source.part->options;
    header.digest = partDigest(header.kind, header.project, header.options, header.parts, header.device, header.frame);
    if (source.part->withoutKeys)
      for (Accumulation& a : accumulations) {
        std::vector<std::uint64_t>().swap(a.keys);
        std::vector<std::uint32_t>().swap(a.keys32);
      }
    try {
      writeImagePart(out, header, accumulations);
    } catch (const IoError& e) {
      throw CliError(kFailure, e.what());
    }
    return std::nullopt;
  }
  // Draves & Reckase 2003, §9: the time samples add into one histogram; with a motion fade the
  // earlier ones are drawn dimmer (directional motion blur, core/render/motion_blur.h).
  RenderImage image = mergeTimeSamples(source.merged ? *source.merged : accumulations, frame.display, motionFade);
  if (!progress.bar) bar.finish();
  const RenderStats& s = image.stats;
  if (s.badFraction() >= 0.5)
    throw CliError(kBadInput, file + ": " + std::to_string(int(std::lround(100 * s.badFraction()))) +
                                  "% of the chaos-game points were non-finite or escaped, so the IFS has no usable "
                                  "attractor; " +
                                  out + " was not written");
  return image;
}

/// One image: the project at overrides.time (or its own time) in the display mode (--mode, or the
/// project's), or, with `blur` > 1, at `blur` times spread evenly over `shutter` seconds centred on
/// that time, merged (Draves & Reckase 2003, §9). Core prepares the time samples
/// (job/frame_output.h) and writes the frame with every output its mode has:
/// - flame (§4–8): the chaos game at supersample× the size with palette colour sums, developed by
///   log-density tone mapping and the filters; PNG/TIFF RGB over the background (RGBA with
///   --transparent), 8 or 16 bits; EXR premultiplied RGBA, float or half;
/// - shaded: the camera's z-buffer and one depth buffer per shadowed light (with depth of field
///   when the aperture is above 0), developed with the lights, occlusion and fog; always on the
///   CPU, whose chaos game fills the shadow maps;
/// - z-buffer: PNG/TIFF 8-bit RGB, EXR float RGBA + Z + P.
int renderFrame(const Project& loaded, const std::string& file, const std::string& out,
                const RenderOverrides& overrides, bool quiet, const FlameOptions& flameOptions, int blur,
                double shutter, FrameProgress progress, bool warn, FrameSource source = {}) {
  const std::string device = checkedDevice(overrides.device);
  if (overrides.observer) progress.observer = &overrides.observer;
  progress.threadsBounded = overrides.threads.has_value();
  FlameOptions flame = flameOptions;
  flame.motionFade = flame.motionFadeOption.value_or(loaded.animation ? loaded.animation->motion_fade : 0.0);
  DisplayMode mode = loaded.render.mode;
  if (flame.mode && !parseDisplayMode(*flame.mode, mode))
    throw CliError(kBadInput, "--mode must be zbuffer, flame, shaded or volume, not \"" + *flame.mode + "\"");
  if (flame.anyFlameSetting() && mode != DisplayMode::Flame)
    throw CliError(kBadInput,
                   "--palette, --hue, --supersample, --density-display and the filter and estimator options apply "
                   "to --mode flame only");
  if (mode != DisplayMode::Flame && (flame.bitDepth || flame.transparent))
    throw CliError(kBadInput, "--bit-depth and --transparent apply to --mode flame only");
  if (mode == DisplayMode::Flame && !source.part) {
    const bool exr = lowerExtension(out) == "exr";
    const int bits = flame.bitDepth.value_or(exr ? 32 : 8);
    if (exr ? (bits != 16 && bits != 32) : (bits != 8 && bits != 16))
      throw CliError(kBadInput, std::string("--bit-depth must be ") +
                                    (exr ? "16 (half) or 32 (float) for EXR" : "8 or 16 for PNG and TIFF"));
  }
  if (mode == DisplayMode::Shaded && blur > 1)
    throw CliError(kBadInput, "--motion-blur applies to the zbuffer and flame modes, not to shaded renders");
  const double time = overrides.time.value_or(loaded.time);
  RenderJobOptions options = renderJobOptions(file, overrides, limits::kMaxRenderSamples, time);
  // One cache of evaluated grids for every time sample (it is keyed by each function's content)
  // and for the contractivity warnings.
  const EvaluationCache evaluation;
  options.evaluation = &evaluation;
  // The mode and the flame options become the project's settings at every time sample, over what
  // its tracks say, so that a part carries them to its merge and the frame step writes the mode's
  // outputs.
  const auto quality = options.adjust;
  options.adjust = [quality, mode, &flame](Project& p) {
    if (quality) quality(p);
    p.render.mode = mode;
    p.render.flame = flame.applied(p.render.flame);
  };
  std::vector<TimeSample> samples;
  try {
    if (source.merged) {
      // The parts' project is the one rendered, with the job's settings in it: nothing to compile.
      RenderJobOptions develop = options;
      develop.time.reset();
      samples.push_back(TimeSample{prepareDevelop(loaded, develop), time});
    } else {
      samples = prepareTimeSamples(loaded, options, blur, shutter);
    }
  } catch (const RenderJobError& e) {
    throw CliError(kBadInput, file + ": " + e.what());
  }
  if (warn && !source.merged && !overrides.volume) warnIfNotContractive(samples.front().render, evaluation, file);
  const PreparedRender& frame = samples.front().render;
  if (source.part) {
    // The part's project says how to finish it: the mode and palette as rendered.
    nlohmann::json partOptions = {
        {"mode", std::string(displayModeName(mode))}, {"motion_blur", blur}, {"shutter", shutter}};
    if (flame.motionFade != 0.0) partOptions["motion_fade"] = flame.motionFade;
    source.part->options = partOptions.dump();
    // The flame display develops from hit counts and colour sums alone.
    source.part->withoutKeys = mode == DisplayMode::Flame;
  }
  if (mode == DisplayMode::Shaded && device == "gpu" && !source.merged)
    std::fprintf(stderr,
                 "note: the shaded display renders on the CPU (its shadow maps and depth of field are "
                 "filled by the CPU chaos game).\n");
  const std::optional<RenderImage> rendered =
      renderWithProgress(samples, file, out, quiet, mode == DisplayMode::Shaded ? "cpu" : device, progress, source,
                         mode == DisplayMode::Shaded ? 0.0 : flame.motionFade);
  if (!rendered) return kSuccess;  // a part: written as it is
  const RenderImage& image = *rendered;
  const RenderStats& s = image.stats;
  if (mode == DisplayMode::ZBuffer && s.badSamples > 0)
    std::fprintf(stderr,
                 "warning: %s: %lld samples (%.3g%%) were non-finite or escaped and were replaced by fresh points.\n",
                 file.c_str(), static_cast<long long>(s.badSamples), 100.0 * s.badFraction());
  // Hit counts, not the z-buffer: merged flame parts carry no keys.
  const bool empty = mode == DisplayMode::Flame ? std::all_of(image.density.begin(), image.density.end(),
                                                              [](std::uint32_t n) { return n == 0; })
                                                : image.hitPixels == 0;
  if (empty)
    std::fprintf(stderr, "warning: %s: no point landed in the %dx%d frame; check the camera.\n", file.c_str(),
                 frame.output.width, frame.output.height);
  writeFrameFile(image, frame, file, out, flame);
  if (!progress.bar || mode == DisplayMode::Flame) printDeviceNote();
  return kSuccess;
}

/// `--frames A:B`: frame f at t = f / fps, each written atomically to the pattern formatted with f,
/// one progress bar over all frames. Everything that can be checked is checked before the first
/// frame is written: the range, the pattern, ffmpeg for --video, and the project at every frame.
int renderSequence(const std::string& file, const std::string& pattern, const RenderOverrides& overrides, bool quiet,
                   const FlameOptions& flame, const SequenceOptions& sequence, std::optional<RenderPart> part) {
  const FrameRange frames = parseFrameRange(*sequence.frames);
  checkFramePattern(pattern);
  if (overrides.time) throw CliError(kBadInput, "--time and --frames exclude each other: a frame's time is f/fps");
  if (sequence.video) checkVideoOutput(*sequence.video);
  if (sequence.video && part)
    throw CliError(kBadInput,
                   "--video needs whole frames: merge the parts first (gridifs merge), or let gridifs farm do it");
  const Project loaded = loadForVerb(file);
  const AnimationSettings animation = loaded.animation.value_or(AnimationSettings{});
  auto frameTime = [&](std::int64_t f) { return double(f) / animation.fps; };
  if (!loaded.tracks.empty() || !loaded.bindings.empty())
    for (std::int64_t f = frames.first; f <= frames.last; ++f) projectForVerbAt(loaded, file, frameTime(f));
  if (sequence.video && loaded.audio) {
    std::error_code ec;
    const std::filesystem::path audio = audioFileOf(loaded, file);
    if (!std::filesystem::is_regular_file(audio, ec))
      throw CliError(kBadInput,
                     file + ": its audio file " + audio.string() + " is not there, so --video cannot carry it");
  }
  std::int64_t samplesPerFrame = 0;
  try {
    samplesPerFrame =
        frameSampleCount(loaded, renderJobOptions(file, overrides, limits::kMaxRenderSamples, frameTime(frames.first)));
  } catch (const RenderJobError& e) {
    throw CliError(kBadInput, file + ": " + e.what());
  }
  ProgressBar bar("render " + std::to_string(frames.count()) + " frames", quiet);
  for (std::int64_t f = frames.first; f <= frames.last; ++f) {
    RenderOverrides at = overrides;
    at.time = frameTime(f);
    const FrameProgress progress{&bar, (f - frames.first) * samplesPerFrame, frames.count() * samplesPerFrame};
    FrameSource source;
    if (part) source.part = FrameSource::PartTarget{*part, f, ""};
    renderFrame(loaded, file, frameFileName(pattern, f), at, quiet, flame,
                sequence.motionBlur.value_or(animation.motion_blur), animation.shutter / animation.fps, progress,
                f == frames.first, source);
  }
  bar.finish();
  if (sequence.video) {
    if (!quiet) std::fprintf(stderr, "assembling %s with ffmpeg\n", sequence.video->c_str());
    assembleVideo(pattern, frames, animation.fps, *sequence.video, audioFileOf(loaded, file));
  }
  printDeviceNote();
  return kSuccess;
}

/// --motion-blur and --motion-fade within their ranges (CliError, exit 2).
void checkMotionOptions(const FlameOptions& flame, std::optional<int> motionBlur) {
  if (motionBlur && (*motionBlur < 1 || *motionBlur > kMaxMotionBlurSamples))
    throw CliError(kBadInput, "--motion-blur must be between 1 and " + std::to_string(kMaxMotionBlurSamples) +
                                  " time samples per frame");
  if (flame.motionFadeOption && !(*flame.motionFadeOption >= 0.0 && *flame.motionFadeOption <= 16.0))
    throw CliError(kBadInput, "--motion-fade must be between 0 (uniform motion blur) and 16");
}

int runRender(const std::string& file, const std::string& out, const RenderOverrides& overrides, bool quiet,
              const FlameOptions& flame, const SequenceOptions& sequence, const std::optional<std::string>& partText,
              std::optional<int> volumeResolution) {
  if (flame.mode && *flame.mode == "volume") {
    if (partText || sequence.frames || sequence.motionBlur || sequence.video)
      throw CliError(kBadInput,
                     "--mode volume renders one image: leave out --part, --frames, --motion-blur and --video");
    if (flame.anyFlameSetting() || flame.bitDepth || flame.transparent || flame.motionFadeOption)
      throw CliError(kBadInput, "the flame options apply to --mode flame, not to --mode volume");
    return runVolumeRender(file, out, overrides, volumeResolution, quiet);
  }
  if (volumeResolution) throw CliError(kBadInput, "--resolution applies to --mode volume only");
  std::optional<RenderPart> part;
  if (partText) {
    part = parsePart(*partText);
    checkOutputPath(out, {"gpart"}, "a render part");
  } else {
    checkOutputPath(out, {"png", "exr", "tif", "tiff"}, "the output image");
  }
  checkMotionOptions(flame, sequence.motionBlur);
  if (!sequence.frames) {
    if (sequence.video) throw CliError(kBadInput, "--video needs a frame sequence: add --frames A:B");
    const Project loaded = loadForVerb(file);
    const AnimationSettings animation = loaded.animation.value_or(AnimationSettings{});
    FrameSource source;
    if (part) source.part = FrameSource::PartTarget{*part, std::nullopt, ""};
    return renderFrame(loaded, file, out, overrides, quiet, flame, sequence.motionBlur.value_or(animation.motion_blur),
                       animation.shutter / animation.fps, {}, true, source);
  }
  return renderSequence(file, out, overrides, quiet, flame, sequence, part);
}

}  // namespace

FlameSettings FlameOptions::applied(FlameSettings settings) const {
  if (palette) settings.palette = *palette, settings.palette_keys.clear();
  if (densityDisplay) settings.density_display = *densityDisplay;
  if (supersample) settings.supersample = *supersample;
  if (hue) settings.hue = *hue;
  if (filterRadius) settings.filter_radius = *filterRadius;
  if (estimatorRadius) settings.estimator_radius = *estimatorRadius;
  if (estimatorMinimum) settings.estimator_minimum = *estimatorMinimum;
  if (estimatorCurve) settings.estimator_curve = *estimatorCurve;
  try {
    validateSettings(flameSettingsTable(), settings, "render.flame");
  } catch (const ModelError& e) {
    // Name the option, not the project field: "render.flame.filter_radius" → "--filter-radius".
    std::string option = e.path().substr(e.path().rfind('.') + 1);
    std::replace(option.begin(), option.end(), '_', '-');
    throw CliError(kBadInput, "--" + option + ": " + e.message());
  }
  return settings;
}

int finishMergedFrame(const Project& project, const std::string& file, const std::string& out,
                      const std::string& optionsJson, const std::vector<Accumulation>& sums,
                      std::optional<int> bitDepth, bool transparent) {
  FlameOptions flame;
  int blur = 1;
  double shutter = 0.0;
  try {
    const nlohmann::json options = nlohmann::json::parse(optionsJson);
    flame.mode = options.at("mode").get<std::string>();
    blur = options.at("motion_blur").get<int>();
    shutter = options.at("shutter").get<double>();
    flame.motionFadeOption = options.value("motion_fade", 0.0);
  } catch (const nlohmann::json::exception&) {
    throw CliError(kBadInput, "the parts' render options are damaged");
  }
  if (blur != int(sums.size())) throw CliError(kBadInput, "the parts' time samples do not match their motion blur");
  DisplayMode mode = DisplayMode::ZBuffer;
  parseDisplayMode(*flame.mode, mode);
  if (mode == DisplayMode::Flame) {
    flame.bitDepth = bitDepth;
    flame.transparent = transparent;
  } else if (bitDepth || transparent) {
    throw CliError(kBadInput, "--bit-depth and --transparent apply to parts of a flame render only");
  }
  FrameSource source;
  source.merged = &sums;
  RenderOverrides overrides;
  overrides.device = "cpu";
  return renderFrame(project, file, out, overrides, true, flame, blur, shutter, {}, false, source);
}

int renderImageOf(const Project& loaded, const std::string& file, const std::string& out,
                  const RenderOverrides& overrides, bool quiet) {
  return renderFrame(loaded, file, out, overrides, quiet, FlameOptions{}, 1, 0.0, {}, false);
}

int renderImageOf(const Project& loaded, const std::string& file, const std::string& out,
                  const RenderOverrides& overrides, const FlameOptions& flame, std::optional<int> motionBlur,
                  bool quiet) {
  checkMotionOptions(flame, motionBlur);
  const AnimationSettings animation = loaded.animation.value_or(AnimationSettings{});
  return renderFrame(loaded, file, out, overrides, quiet, flame, motionBlur.value_or(animation.motion_blur),
                     animation.shutter / animation.fps, {}, true);
}

namespace {

/// The help of a flame-display option that overrides field `key` of "render.flame": the table's
/// tooltip and range.
std::string flameOptionHelp(const char* key) {
  const SettingSpec& field = flameSettingsTable().field(key);
  std::string tooltip = field.tooltip;
  if (!tooltip.empty()) tooltip[0] = char(std::tolower(static_cast<unsigned char>(tooltip[0])));
  std::ostringstream help;
  help << "flame mode: " << tooltip << " (" << field.min << " to " << field.max
       << "; default: the project's render.flame." << key << ")";
  return help.str();
}

const VerbRegistration kRender{
    {"render",
     "FILE -o OUT.(png|exr|tif) [--width W --height H --samples N --seed S --threads T "
     "--device auto|gpu|cpu --time T --quality Q] [--frames A:B --motion-blur N --motion-fade F --video OUT.mp4] "
     "[--mode zbuffer|flame|shaded|volume --resolution N --palette P --hue H --density-display log|linear|binary "
     "--supersample S "
     "--filter-radius R --estimator-radius R --estimator-minimum M --estimator-curve C --bit-depth B "
     "--transparent]: render headlessly",
     [](CLI::App& app) {
       const auto a =
           addChaosVerbOptions(app, "output image: .png or .tif (8-bit RGB) or .exr (float RGBA + Z)",
                               "chaos-game iterations in total, e.g. 2e7 (default: the project's)",
                               "render threads; at most T run at once, the image library loading before them (default: "
                               "all cores, with the loading beside them; the image does not depend on it)");
       app.add_option("--width", a->overrides.width, "image width in pixels (default: the project's)");
       app.add_option("--height", a->overrides.height, "image height in pixels (default: the project's)");
       auto flame = std::make_shared<FlameOptions>();
       app.add_option("--mode", flame->mode,
                      "zbuffer (nearest surface), flame (log density, palette colors) or shaded "
                      "(lights, shadows, occlusion, fog; EXR adds N.x N.y N.z AO shadow) or volume (the density "
                      "volume ray-marched from render.volume, lit or X-ray; PNG/EXR with alpha, EXR adds Z); "
                      "default: the project's render.mode");
       auto volumeResolution = std::make_shared<std::optional<int>>();
       app.add_option(
           "--resolution", *volumeResolution,
           "volume mode: voxels per axis of the density volume, 16 to 512 (default: render.volume.resolution, "
           "or 128)");
       app.add_option("--palette", flame->palette,
                      "flame palette: a built-in name (ember, ice, ...), flam3:N, "
                      "flam3:NAME or file:PATH.json (default: the project's)");
       app.add_option("--bit-depth", flame->bitDepth,
                      "flame mode: 8 or 16 bits for PNG/TIFF, 16 (half) or 32 "
                      "(float) for EXR");
       app.add_flag("--transparent", flame->transparent, "flame mode: PNG/TIFF with alpha instead of the background");
       auto sequence = std::make_shared<SequenceOptions>();
       app.add_option("--frames", sequence->frames,
                      "render frames A to B (A:B) as a numbered sequence, frame f at time f/fps; -o needs a "
                      "printf pattern such as out_%04d.png");
       app.add_option("--motion-blur", sequence->motionBlur,
                      "time samples per frame, spread over the animation's shutter (default 0.5 of the frame "
                      "interval); 1 = none (default: the project's animation.motion_blur, 1)");
       app.add_option("--motion-fade", flame->motionFadeOption,
                      "directional motion blur: earlier time samples drawn dimmer, weight ((i+1)/n)^FADE; "
                      "0 = uniform (default: the project's animation.motion_fade)");
       app.add_option("--quality", a->overrides.quality,
                      "samples per output pixel (flam3's quality): sets the sample count from the image size; "
                      "overrides the project's render.quality and render.samples; excludes --samples");
       app.add_option("--hue", flame->hue, flameOptionHelp("hue"));
       app.add_option("--density-display", flame->densityDisplay,
                      "flame mode: log (log density), linear (hits over the densest pixel's) or binary (hit or not)");
       app.add_option("--supersample", flame->supersample, flameOptionHelp("supersample"));
       app.add_option("--filter-radius", flame->filterRadius, flameOptionHelp("filter_radius"));
       app.add_option("--estimator-radius", flame->estimatorRadius,
                      flameOptionHelp("estimator_radius") + "; 0 turns density estimation off");
       app.add_option("--estimator-minimum", flame->estimatorMinimum, flameOptionHelp("estimator_minimum"));
       app.add_option("--estimator-curve", flame->estimatorCurve, flameOptionHelp("estimator_curve"));
       app.add_option("--video", sequence->video,
                      "with --frames: also assemble the frames into this video with ffmpeg");
       auto part = std::make_shared<std::optional<std::string>>();
       app.add_option("--part", *part,
                      "render part K of N (K/N, 0 ≤ K < N) of the sample budget and write its accumulation to "
                      "-o OUT.gpart (with --frames: a pattern, one part file per frame); gridifs merge "
                      "makes the image");
       return [=] {
         return runRender(a->file, a->out, a->overrides, a->quiet, *flame, *sequence, *part, *volumeResolution);
       };
     },
     /*hugePageHeap=*/true}};

}  // namespace
}  // namespace gridifs::cli
