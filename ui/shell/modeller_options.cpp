#include "ui/shell/modeller_options.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace gridifs::ui {

std::optional<std::string> parseModellerOptions(int argc, char** argv, ModellerOptions& out) {
  auto number = [](const std::string& text, double& value) {
    char* end = nullptr;
    value = std::strtod(text.c_str(), &end);
    return !text.empty() && end && *end == '\0';
  };
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto next = [&](std::string& value) -> bool {
      if (i + 1 >= argc) return false;
      value = argv[++i];
      return true;
    };
    std::string value;
    double n = 0.0;
    if (arg == "--screenshot") {
      if (!next(out.screenshot) || out.screenshot.empty()) return "--screenshot needs an output file (e.g. shot.png)";
    } else if (arg == "--frames") {
      if (!next(value) || !number(value, n) || n < 1 || n > 1e6) return "--frames needs a frame count of at least 1";
      out.frames = int(n);
    } else if (arg == "--wait-points") {
      if (!next(value) || !number(value, n) || n < 0) return "--wait-points needs a point count";
      out.waitPoints = std::int64_t(n);
    } else if (arg == "--size") {
      int w = 0, h = 0;
      if (!next(value) || std::sscanf(value.c_str(), "%dx%d", &w, &h) != 2 || w < 320 || h < 240 || w > 16384 ||
          h > 16384)
        return "--size needs WIDTHxHEIGHT, at least 320x240";
      out.width = w;
      out.height = h;
    } else if (arg == "--probe") {
      if (!next(out.probe) || out.probe.empty()) return "--probe needs an output file";
    } else if (arg == "--autosave-seconds") {
      if (!next(value) || !number(value, n) || n <= 0) return "--autosave-seconds needs a positive number";
      out.autosaveSeconds = n;
    } else if (arg == "--render-threads") {
      if (!next(value) || !number(value, n) || n < 1 || n > 64) return "--render-threads needs 1..64";
      out.renderThreads = int(n);
    } else if (arg == "--ui-scale") {
      if (!next(value) || !number(value, n) || n < 0.5 || n > 4) return "--ui-scale needs a scale between 0.5 and 4";
      out.uiScale = float(n);
    } else if (arg == "--device") {
      if (!next(out.device) || (out.device != "auto" && out.device != "gpu" && out.device != "cpu"))
        return "--device needs auto, gpu or cpu";
    } else if (arg == "--osc-port") {
      if (!next(value) || !number(value, n) || n < 1 || n > 65535 || n != std::floor(n))
        return "--osc-port needs a port number from 1 to 65535";
      out.oscPort = int(n);
    } else if (arg == "--midi") {
      out.midi = true;
    } else if (arg == "--stats") {
      out.stats = true;
    } else if (!arg.empty() && arg[0] == '-') {
      return "unknown option " + arg + " for the modeller (see 'gridifs --help')";
    } else if (i == 1 || out.file.empty()) {
      if (!out.file.empty() && out.file != arg) return "only one project file can be opened, not also " + arg;
      out.file = arg;
    } else if (arg != out.file) {
      return "only one project file can be opened, not also " + arg;
    }
  }
  return std::nullopt;
}

}  // namespace gridifs::ui
