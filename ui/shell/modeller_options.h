#pragma once
// Command-line options of the modeller window, mainly for deterministic captures and tests:
//   --screenshot OUT.png   render, read the window back, write OUT.png (OpenImageIO), exit 0
//   --frames N             frames before the screenshot (default 30)
//   --wait-points N        also wait (up to 60 s) until the preview has N points
//   --size WxH             window size in screen coordinates (default: the last session's size,
//                          the first time the monitor's work area up to 1600x1000)
//   --probe FILE           write widget rectangles and state as JSON every few frames (tests)
//   --autosave-seconds S   autosave interval (default 60)
//   --stats                print frame-time statistics on exit
//   --ui-scale S           override the monitor content scale (HiDPI checks on any display)
//   --device D             preview renderer: auto (a hardware GPU when there is one), gpu or cpu
//   --osc-port P           listen for OSC on 127.0.0.1:P (off without it)
//   --midi                 open the MIDI input at start (else on the first "Bind…")
#include <cstdint>
#include <optional>
#include <string>

namespace gridifs::ui {

struct ModellerOptions {
  std::string file;
  std::string screenshot;
  int frames = 30;
  std::int64_t waitPoints = 0;
  int width = 0, height = 0;  // 0: remembered, or from the monitor's work area
  std::string probe;
  double autosaveSeconds = 60.0;
  bool stats = false;
  int renderThreads = 0;        // 0: hardware threads minus one (the UI keeps a core)
  float uiScale = 0.0f;         // 0: the monitor's content scale
  std::string device = "auto";  // auto | gpu | cpu
  int oscPort = 0;              // 0: no OSC
  bool midi = false;
};

/// Parses argv (argv[0] is the program; a leading FILE argument is skipped when it equals
/// `file`). Returns an error sentence for a bad option, else nullopt.
std::optional<std::string> parseModellerOptions(int argc, char** argv, ModellerOptions& out);

}  // namespace gridifs::ui
