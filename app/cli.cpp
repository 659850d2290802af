#include "app/cli.h"

#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <map>

#include "base/errors.h"
#include "edit/project_edit.h"
#include "io/project_io.h"
#include "job/prepared_render.h"
#include "schema/project_time.h"
#include "schema/validation.h"

namespace gridifs::cli {
namespace {

/// The --set arguments of the verb being run (PATH=VALUE), in the order given.
std::vector<std::string>& parameterSettings() {
  static std::vector<std::string> settings;
  return settings;
}

/// Sets the --set numbers in `project` as SetParameter edits, then checks the whole project.
void applyParameterSettings(Project& project) {
  for (const std::string& setting : parameterSettings()) {
    const std::size_t equals = setting.rfind('=');
    const std::string path = setting.substr(0, equals),
                      text = equals == std::string::npos ? "" : setting.substr(equals + 1);
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (path.empty() || text.empty() || *end != '\0')
      throw CliError(kBadInput, "--set " + setting + ": expected PATH=NUMBER, such as functions[0].weight=0.5");
    try {
      applyEdit(project, SetParameter{path, value});
    } catch (const ModelError& e) {
      throw CliError(kBadInput, std::string("--set: ") + e.what());
    }
  }
  if (parameterSettings().empty()) return;
  try {
    validateProject(project);  // rules across fields (an aperture needs a focus distance)
  } catch (const ModelError& e) {
    throw CliError(kBadInput, std::string("--set: ") + e.what());
  }
}

std::map<std::string, Verb>& verbs() {
  static std::map<std::string, Verb> registry;
  return registry;
}

void printUsage(std::ostream& out) {
  out << "GridIFS — nonlinear 3D iterated function systems from distorted grids.\n\n"
         "Usage:\n  gridifs [FILE]                 open the modeller (default project without FILE)\n";
  for (const auto& [name, verb] : verbs()) {
    std::string padded = "  gridifs " + name;
    padded.resize(33, ' ');
    out << padded << verb.summary << "\n";
  }
  out << "\nRun 'gridifs VERB --help' for a verb's options. Exit codes: 0 success, 1 failure "
         "while working, 2 bad usage or bad input.\n";
}

int runVerb(const Verb& verb, int argc, char** argv) {
  CLI::App app(verb.summary, std::string("gridifs ") + verb.name);
  parameterSettings().clear();
  std::function<int()> action = verb.setup(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return kSuccess;
  } catch (const CLI::ParseError& e) {
    std::cerr << "gridifs " << verb.name << ": " << oneSentence(e.what()) << " (see 'gridifs " << verb.name
              << " --help')\n";
    return kBadInput;
  }
  return action();
}

}  // namespace

std::string oneSentence(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  for (char& c : text)
    if (c == '\n') c = ' ';
  if (!text.empty() && text.back() != '.') text += '.';
  return text;
}

VerbRegistration::VerbRegistration(Verb verb) { verbs().emplace(verb.name, std::move(verb)); }

bool stderrIsTerminal() { return ::isatty(STDERR_FILENO) == 1; }

Project loadForVerb(const std::filesystem::path& file) {
  Project project;
  try {
    project = loadProject(file);
  } catch (const ModelError& e) {
    throw CliError(kBadInput, file.string() + ": " + e.what());
  } catch (const IoError& e) {
    throw CliError(kBadInput, "cannot read " + file.string() + ": " + e.what());
  }
  applyParameterSettings(project);
  return project;
}

void addSetOption(CLI::App& app) {
  app.add_option("--set", parameterSettings(),
                 "PATH=NUMBER: set the number at a parameter path of the project before working, as an edit "
                 "would (repeatable; e.g. --set functions[0].weight=2 --set render.flame.gamma=3); 'gridifs info "
                 "FILE --parameters' lists the paths")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

void addTimeOption(CLI::App& app, std::optional<double>& time) {
  app.add_option("--time", time,
                 "the time in seconds at which to take the project: fields move and keyframed parameters "
                 "take their values (default: the project's time)");
}

std::filesystem::path audioFileOf(const Project& project, const std::filesystem::path& file) {
  if (!project.audio) return {};
  const std::filesystem::path audio = project.audio->file;
  return audio.is_relative() ? file.parent_path() / audio : audio;
}

Project projectForVerbAt(const Project& loaded, const std::filesystem::path& file, std::optional<double> time) {
  try {
    // The tracks, and the numbers bound to the sound, as every render sees them (core/job).
    return renderProjectAt(loaded, time.value_or(loaded.time), file.parent_path());
  } catch (const RenderJobError& e) {
    throw CliError(kBadInput, file.string() + ": " + e.what());
  }
}

Project loadForVerbAt(const std::filesystem::path& file, std::optional<double> time) {
  return projectForVerbAt(loadForVerb(file), file, time);
}

std::size_t resolveFunction(const Project& project, const std::string& which, const std::filesystem::path& file) {
  const std::size_t count = project.functions.size();
  char* end = nullptr;
  const long index = std::strtol(which.c_str(), &end, 10);
  if (!which.empty() && end && *end == '\0') {
    if (index < 0 || std::size_t(index) >= count)
      throw CliError(kBadInput, file.string() + " has " + std::to_string(count) + " function" +
                                    (count == 1 ? "" : "s") + ", so --function must be 0.." +
                                    std::to_string(count - 1) + ", not " + which);
    return std::size_t(index);
  }
  for (std::size_t i = 0; i < count; ++i)
    if (project.functions[i].name == which) return i;
  throw CliError(kBadInput, file.string() + " has no function named \"" + which + "\"");
}

std::shared_ptr<const Grid> evaluateForVerb(const Document& document, std::size_t index,
                                            const std::filesystem::path& file) {
  if (document.project().functions[index].kind == FunctionKind::Matrix)
    throw CliError(kBadInput, file.string() + ": function " + std::to_string(index) +
                                  " is a matrix of a free-form IFS and has no grid to evaluate");
  try {
    return document.evaluatedGrid(index);
  } catch (const ModelError& e) {
    throw CliError(kBadInput, file.string() + ": " + e.what());
  }
}

bool isVerb(const char* word) { return word && verbs().count(word) > 0; }

bool verbWantsHugePageHeap(const char* word) {
  if (!word) return false;
  const auto it = verbs().find(word);
  return it != verbs().end() && it->second.hugePageHeap;
}

int run(int argc, char** argv, ModellerOpener openModeller) {
  try {
    if (argc >= 2) {
      const std::string first = argv[1];
      if (first == "--help" || first == "-h" || first == "help") {
        printUsage(std::cout);
        return kSuccess;
      }
      if (auto it = verbs().find(first); it != verbs().end()) return runVerb(it->second, argc - 1, argv + 1);
      if (!first.empty() && first[0] == '-' && first != "--screenshot" && first != "--frames" &&
          first.rfind("--", 0) != 0) {
        std::cerr << "gridifs: unknown option " << first << " (see 'gridifs --help').\n";
        return kBadInput;
      }
    }
    std::string file;
    if (argc >= 2 && argv[1][0] != '-') {
      file = argv[1];
      // A bare word that is not a file is a mistyped or missing verb, not a project to open.
      std::error_code ec;
      if (file.find('.') == std::string::npos && file.find('/') == std::string::npos &&
          !std::filesystem::exists(file, ec)) {
        std::cerr << "gridifs: unknown command \"" << file << "\" (see 'gridifs --help').\n";
        return kBadInput;
      }
    }
    return openModeller(file, argc, argv);
  } catch (const CliError& e) {
    std::cerr << "gridifs: " << oneSentence(e.what()) << "\n";
    return e.code();
  } catch (const std::bad_alloc&) {
    std::cerr << "gridifs: out of memory.\n";
    return kFailure;
  } catch (const std::exception& e) {
    std::cerr << "gridifs: " << oneSentence(e.what()) << "\n";
    return kFailure;
  }
}

}  // namespace gridifs::cli
