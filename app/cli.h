#pragma once
// The command line: one executable, one verb per file, exit codes
// 0 success, 1 failure while working, 2 bad usage or bad input file.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

#include "edit/document.h"

namespace gridifs::cli {

enum ExitCode { kSuccess = 0, kFailure = 1, kBadInput = 2 };

/// Thrown by verbs: printed as one sentence to stderr, mapped to its exit code.
class CliError : public std::runtime_error {
 public:
  CliError(int code, const std::string& message) : std::runtime_error(message), code_(code) {}
  int code() const { return code_; }

 private:
  int code_;
};

/// A verb: fills a CLI11 app with its options and returns the action to run after parsing.
struct Verb {
  const char* name;
  const char* summary;
  std::function<std::function<int()>(CLI::App&)> setup;
  /// Runs with glibc's heap on huge pages (app/huge_page_heap.h): the verbs that render, or write
  /// images, volumes and meshes, whose buffers and image library cost their process most of its
  /// system time in page faults. Off for the quick verbs, where starting again would cost more.
  bool hugePageHeap = false;
};

/// Registers a verb at static-initialisation time (each verb_*.cpp registers itself).
struct VerbRegistration {
  explicit VerbRegistration(Verb verb);
};

/// Opens the modeller on a file (or none) with the process's arguments: openModeller below for the
/// executable. A parameter, so that the verbs link into the Python module without the modeller.
using ModellerOpener = int (*)(const std::string& file, int argc, char** argv);

/// Runs the verb that argv names, or opens the modeller; returns the exit code.
int run(int argc, char** argv, ModellerOpener openModeller);

/// Whether `word` names a verb (the first argument of a command, not of the modeller).
bool isVerb(const char* word);

/// Whether `word` names a verb that runs with the huge-page heap (Verb::hugePageHeap).
bool verbWantsHugePageHeap(const char* word);

/// Loads a project for a verb; bad content → CliError(2), unreadable → CliError(2) too
/// (an unreadable input file is bad input), each naming the file. The numbers given with --set
/// are then set, in order, as edits would set them.
Project loadForVerb(const std::filesystem::path& file);

/// Declares `--set PATH=VALUE` (repeatable) on a verb that reads a project: the number at that
/// parameter path ("functions[0].weight", "render.flame.gamma", the paths of keyframe tracks) is
/// set before the verb works, checked as the project file checks it. A value a file could not
/// hold there → CliError(2) with the file reader's sentence.
void addSetOption(CLI::App& app);

/// Declares `--time T` (seconds) on a verb that reads a project: the project as it stands at T.
void addTimeOption(CLI::App& app, std::optional<double>& time);

/// loadForVerb, then the project at `time` (default: its stored "time") with every keyframe track
/// evaluated there, as the modeller shows it. A track that no longer fits → CliError(2).
Project loadForVerbAt(const std::filesystem::path& file, std::optional<double> time);

/// The project `loaded` from `file` at `time` (default: its stored time), tracks evaluated.
Project projectForVerbAt(const Project& loaded, const std::filesystem::path& file, std::optional<double> time);
/// The project's sound ("audio.file", relative to the project file's folder), or an empty path.
std::filesystem::path audioFileOf(const Project& project, const std::filesystem::path& file);

/// Resolves "--function" (an index 0..n-1 as in JSON paths, or a function name).
std::size_t resolveFunction(const Project& project, const std::string& which, const std::filesystem::path& file);

/// Evaluates function `index`, reporting model errors as CliError(2) naming the file.
std::shared_ptr<const Grid> evaluateForVerb(const Document& document, std::size_t index,
                                            const std::filesystem::path& file);

/// A message as one sentence: newlines joined, a full stop at the end (how errors are printed).
std::string oneSentence(std::string text);

/// Whether stderr is an interactive terminal (progress bars only then).
bool stderrIsTerminal();

/// Opens the interactive modeller (or, without a GUI build or display, explains why).
int openModeller(const std::string& file, int argc, char** argv);

}  // namespace gridifs::cli
