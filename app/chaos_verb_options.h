#pragma once
// The options every chaos-game verb (render, export-points) declares alike: the project, the
// output, --samples, --seed, --threads, --device and --quiet.
#include <CLI/CLI.hpp>
#include <memory>
#include <string>

#include "app/render_setup.h"

namespace gridifs::cli {

struct ChaosVerbArgs {
  std::string file, out;
  RenderOverrides overrides;
  bool quiet = false;
};

/// Declares the shared options on `app`; the help texts that differ between the verbs are given.
/// The returned arguments are filled when CLI11 parses.
std::shared_ptr<ChaosVerbArgs> addChaosVerbOptions(CLI::App& app, const std::string& outputHelp,
                                                   const std::string& samplesHelp, const std::string& threadsHelp);

}  // namespace gridifs::cli
