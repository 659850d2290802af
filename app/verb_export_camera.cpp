// gridifs export-camera FILE -o OUT.(usda|chan) [--frames A:B]: the project's camera for
// compositing and 3D packages, animated over the frames (io/camera_export.h has the formats).
#include "app/cli.h"
#include "app/render_sequence.h"
#include "app/render_setup.h"
#include "base/atomic_file.h"
#include "base/text_format.h"
#include "io/camera_export.h"

namespace gridifs::cli {
namespace {

int runExportCamera(const std::string& file, const std::string& out, const std::optional<std::string>& frames) {
  checkOutputPath(out, {"usda", "chan"}, "the camera file");
  const Project loaded = loadForVerb(file);
  const AnimationSettings animation = loaded.animation.value_or(AnimationSettings{});
  std::vector<CameraSample> samples;
  if (frames) {
    const FrameRange range = parseFrameRange(*frames);
    for (std::int64_t f = range.first; f <= range.last; ++f)
      samples.push_back({double(f), projectForVerbAt(loaded, file, double(f) / animation.fps).camera});
  } else {
    // The camera at the project's own time, as `gridifs render` draws it.
    samples.push_back({loaded.time * animation.fps, projectForVerbAt(loaded, file, std::nullopt).camera});
  }
  const int width = loaded.render.width, height = loaded.render.height;
  std::string text;
  try {
    text = lowerExtension(out) == "usda" ? cameraUsda(samples, width, height, animation.fps)
                                         : cameraChan(samples, width, height);
  } catch (const ModelError& e) {
    throw CliError(kBadInput, file + ": " + e.what());
  }
  writeFileAtomically(out, text);  // IoError: exit 1 with its sentence
  return kSuccess;
}

const VerbRegistration kExportCamera{
    {"export-camera", "FILE -o OUT.(usda|chan) [--frames A:B]: the camera for compositing (USD or Nuke's .chan)",
     [](CLI::App& app) {
       auto file = std::make_shared<std::string>();
       auto out = std::make_shared<std::string>();
       auto frames = std::make_shared<std::optional<std::string>>();
       app.add_option("FILE", *file, "project file (.gridifs)")->required();
       addSetOption(app);
       app.add_option("-o,--output", *out, "output camera (.usda or .chan)")->required();
       app.add_option("--frames", *frames, "frames A to B (A:B), frame f at time f/fps; default: the project's time");
       return [=] { return runExportCamera(*file, *out, *frames); };
     }}};

}  // namespace
}  // namespace gridifs::cli
