// A walk over the project's schema: every field of every table (a function's own numbers, each
// operation's parameters, the camera, the render, flame, shading and volume settings, the
// timeline) has a parameter path; every number of every example project and of a project that
// holds every optional block round-trips through the file; and a value a file could not hold gets
// the same sentence from a file being loaded, from an edit of the Document and from the command
// line's --set.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>

#include "anim/track_path.h"
#include "edit/document.h"
#include "edit/project_edit.h"
#include "io/parameter_paths.h"
#include "io/project_io.h"
#include "run_command.h"
#include "schema/operation_table.h"
#include "schema/project_parameter.h"
#include "schema/settings_tables.h"

namespace gridifs {
namespace {

namespace fs = std::filesystem;
using test_support::quote;
using test_support::runGridifs;

/// A project that holds every optional block the format has: a stereo pair, a shaded render with
/// its lights, a volume render with a transfer function, a timeline, a density volume with a field
/// layer, restricted transitions, post maps of both kinds, a final function, and one operation of
/// every type.
Project everyBlock() {
  Project p = defaultNewProject();
  p.camera.stereo = StereoSettings{};
  p.render.mode = DisplayMode::Shaded;
  p.render.quality = 20.0;
  p.render.shading.dof.focus = 4.0;
  p.render.volume = VolumeRenderSettings{};
  p.render.volume->transfer = {{0.0, Vec3(1.0), 0.0}, {1.0, Vec3(0.5), 1.0}};
  p.animation = AnimationSettings{};
  p.volume = VolumeSettings{};
  p.volume->field = VolumeDensityField{};
  p.functions.push_back(p.functions[0]);
  p.functions[1].sampling_error = 0.01;
  p.functions[1].post = PostTransform{};  // a post map by placement
  p.functions[1].post->placement.scale = Vec3(0.9);
  p.functions.push_back(p.functions[0]);  // and one by its 3×4 matrix
  p.functions[2].post = PostTransform{};
  p.functions[2].post->matrix = {{{0.9, 0.0, 0.0, 0.1}, {0.0, 0.9, 0.0, 0.0}, {0.0, 0.0, 0.9, 0.0}}};
  p.transitions = {{1.0, 0.5, 0.5}, {0.5, 1.0, 0.5}, {0.5, 0.5, 1.0}};
  p.final_function = p.functions[0];
  p.functions[0].ops.clear();
  for (const OperationSpec& spec : operationTable()) {
    if (!spec.addable) continue;
    Operation op;
    op.params = spec.defaults;
    p.functions[0].ops.push_back(op);
  }
  validateProject(p);
  return p;
}

/// "functions[0].ops[3].k" → "functions[].ops[twist].k": what kind of number a path names.
std::string kindOf(const Project& project, const std::string& path) {
  static const std::regex op(R"(^(functions\[(\d+)\]|final)\.ops\[(\d+)\])");
  std::string rest = path, head;
  std::smatch m;
  if (std::regex_search(path, m, op)) {
    const Function& f = m[2].matched ? project.functions[std::stoul(m[2].str())] : *project.final_function;
    head = std::string(m[2].matched ? "functions[]" : "final") + ".ops[" +
           operationSpec(f.ops[std::stoul(m[3].str())].params).type + "]";
    rest = m.suffix();
  }
  return head + std::regex_replace(rest, std::regex(R"(\[\d+\])"), "[]");
}

/// "functions[0].ops[1].k" → "/functions/0/ops/1/k".
nlohmann::json::json_pointer pointerOf(const std::string& path) {
  std::string pointer;
  for (char c : path) {
    if (c == '.' || c == '[')
      pointer += '/';
    else if (c != ']')
      pointer += c;
  }
  return nlohmann::json::json_pointer("/" + pointer);
}

std::string show(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

/// What loading `project`'s file with `value` at `path` says; "accepted" when it loads.
std::string fileSays(const Project& project, const std::string& path, double value) {
  nlohmann::json file = nlohmann::json::parse(serializeProject(project));
  file[pointerOf(path)] = value;
  try {
    parseProject(file.dump());
  } catch (const ModelError& e) {
    return e.what();
  }
  return "accepted";
}

/// What the Document says to the edit; "accepted" when it takes it.
std::string editSays(const Project& project, const std::string& path, double value) {
  Document document(project);
  try {
    document.apply(SetParameter{path, value});
  } catch (const ModelError& e) {
    EXPECT_EQ(document.project(), project) << path << ": a refused edit changes nothing";
    return e.what();
  }
  return "accepted";
}

/// Values a file cannot hold at most paths: past the slider's range, then past any coordinate,
/// then a fraction where a whole number is expected.
std::vector<double> outOfRange(const ProjectParameter& parameter) {
  const ParameterSpan span = parameter.span();
  std::vector<double> values;
  if (span.lo < span.hi) {
    values.push_back(span.hi + std::max(1.0, std::abs(span.hi)) * 1e3);
    values.push_back(span.lo - std::max(1.0, std::abs(span.lo)) * 1e3);
  }
  values.insert(values.end(), {1e300, -1e300, 0.5});
  return values;
}

/// Values a file may hold: inside the slider's range, or near the current value.
std::vector<double> inRange(const ProjectParameter& parameter, double current) {
  const ParameterSpan span = parameter.span();
  std::vector<double> values;
  for (double t : {0.375, 0.625, 0.9})
    if (span.lo < span.hi) values.push_back(span.lo + t * (span.hi - span.lo));
  values.insert(values.end(), {current * 0.5 + 0.125, current + 1.0, current * 0.5});
  if (parameter.wholeNumber())
    for (double& v : values) v = std::round(v);
  return values;
}

struct Source {
  Project project;
  fs::path file;  // the file the command line reads
};

TEST(SchemaWalk, EveryFieldOfEveryTableHasAParameterPath) {
  const Project p = everyBlock();
  const struct {
    const SettingTable& table;
    std::string group;
  } groups[] = {
      {functionTable(), "functions[1]"},
      {functionTable(), "final"},
      {placementTable(), "functions[1].placement"},
      {placementTable(), "final.placement"},
      {cameraTable(), "camera"},
      {stereoTable(), "camera.stereo"},
      {renderSettingsTable(), "render"},
      {flameSettingsTable(), "render.flame"},
      {shadingSettingsTable(), "render.shading"},
      {shadingLightTable(), "render.shading.lights[0]"},
      {ambientOcclusionTable(), "render.shading.ao"},
      {fogTable(), "render.shading.fog"},
      {depthOfFieldTable(), "render.shading.dof"},
      {volumeRenderTable(), "render.volume"},
      {transferStopTable(), "render.volume.transfer[1]"},
      {animationSettingsTable(), "animation"},
      {volumeSettingsTable(), "volume"},
  };
  auto expectLookup = [&](const std::string& path, FieldType type) {
    const bool number = type == FieldType::Number || type == FieldType::Integer || type == FieldType::Count ||
                        type == FieldType::Seed || type == FieldType::OptionalNumber || type == FieldType::Vector;
    const std::string at = type == FieldType::Vector ? path + "[0]" : path;
    const auto parsed = TrackPath::parse(at);
    ASSERT_TRUE(parsed) << at;
    EXPECT_EQ(findParameter(p, *parsed, ParameterScope::Edit).lookup,
              number ? ParameterLookup::Number : ParameterLookup::NotANumber)
        << at;
  };
  int fields = 0;
  for (const auto& g : groups)
    for (const SettingSpec& s : g.table.fields) {
      expectLookup(g.group + "." + s.key, s.type);
      ++fields;
    }
  // Each operation's numbers, at its place in function 0's stack.
  const Function& f = p.functions[0];
  for (std::size_t o = 0; o < f.ops.size(); ++o)
    for (const ParamSpec& param : operationSpec(f.ops[o].params).params) {
      const std::string path = "functions[0].ops[" + std::to_string(o) + "]." + param.key;
      ++fields;
      if (param.type == ParamType::CalculatorVars)
        expectLookup(path + ".v1.value", FieldType::Number);
      else if (param.type != ParamType::MorphPairs && param.type != ParamType::NodeMoves)
        expectLookup(path, param.type);
    }
  EXPECT_GT(fields, 100);
}

TEST(SchemaWalk, EveryNumberRoundTripsAndIsRefusedInOneSentenceEverywhere) {
  const fs::path dir = fs::temp_directory_path() / ("gridifs-schema-walk-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::vector<Source> sources;
  sources.push_back({everyBlock(), dir / "every_block.gridifs"});
  saveProject(sources.back().project, sources.back().file);
  std::vector<fs::path> examples;
  for (const auto& entry : fs::recursive_directory_iterator(GRIDIFS_ASSETS))
    if (entry.path().extension() == ".gridifs") examples.push_back(entry.path());
  std::sort(examples.begin(), examples.end());
  for (const fs::path& file : examples) sources.push_back({loadProject(file), file});

  std::set<std::string> seen;
  std::vector<std::string> unchanged;  // kinds whose every new value broke a rule across fields
  int kinds = 0, refused = 0, commandLine = 0;
  for (const Source& source : sources) {
    const Project& project = source.project;
    for (const std::string& path : parameterPaths(project)) {
      const std::string kind = kindOf(project, path);
      if (!seen.insert(kind).second) continue;
      ++kinds;
      const ProjectParameter parameter = findParameter(project, *TrackPath::parse(path)).parameter;
      const double current = parameter.get(project);

      // The number round-trips through the file: its value, and a new one when the project's
      // rules across fields allow it.
      bool changed = false;
      for (double value : inRange(parameter, current)) {
        if (value == current || editSays(project, path, value) != "accepted") continue;
        Project edited = project;
        applyEdit(edited, SetParameter{path, value});
        const Project read = parseProject(serializeProject(edited));
        EXPECT_EQ(parameterValue(read, path), value) << path;
        changed = true;
        break;
      }
      if (!changed) unchanged.push_back(kind);
      EXPECT_EQ(parameterValue(parseProject(serializeProject(project)), path), current) << path;

      // A value the file cannot hold: the same sentence from the file, the edit and --set.
      for (double value : outOfRange(parameter)) {
        const std::string edit = editSays(project, path, value);
        if (edit == "accepted") continue;
        ++refused;
        EXPECT_EQ(fileSays(project, path, value), edit) << path << " = " << show(value);
        const auto cli = runGridifs("info " + quote(source.file.string()) + " --parameters --set " +
                                    quote(path + "=" + show(value)));
        ++commandLine;
        EXPECT_EQ(cli.exitCode, 2) << path;
        EXPECT_NE(cli.err.find("--set: " + edit), std::string::npos) << path << "\n" << cli.err << "\n" << edit;
        break;
      }
    }
  }
  fs::remove_all(dir);
  // Every kind of number but the playhead's time (any finite second) refuses some value.
  EXPECT_GE(refused, kinds - 1) << kinds << " kinds";
  EXPECT_GT(kinds, 150);
  EXPECT_EQ(commandLine, refused);
  std::string list;
  for (const std::string& k : unchanged) list += k + "\n";
  EXPECT_LE(unchanged.size(), 10u) << "numbers no new value of which survives the project's rules:\n" << list;
  std::printf("%d kinds of numbers, %d refused values, %zu kept their value:\n%s", kinds, refused, unchanged.size(),
              list.c_str());
}

}  // namespace
}  // namespace gridifs
