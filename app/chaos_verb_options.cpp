#include "app/chaos_verb_options.h"

#include "app/cli.h"
#include "app/render_device_option.h"

namespace gridifs::cli {

std::shared_ptr<ChaosVerbArgs> addChaosVerbOptions(CLI::App& app, const std::string& outputHelp,
                                                   const std::string& samplesHelp, const std::string& threadsHelp) {
  auto a = std::make_shared<ChaosVerbArgs>();
  app.add_option("FILE", a->file, "project file (.gridifs)")->required();
  app.add_option("-o,--output", a->out, outputHelp)->required();
  app.add_option("--samples", a->overrides.samples, samplesHelp);
  app.add_option("--seed", a->overrides.seed, "random seed (default: the project's)");
  app.add_option("--threads", a->overrides.threads, threadsHelp);
  addDeviceOption(app, a->overrides.device);
  addTimeOption(app, a->overrides.time);
  addSetOption(app);
  app.add_flag("-q,--quiet", a->quiet, "no progress bar");
  return a;
}

}  // namespace gridifs::cli
