// gridifs export-field FILE --op PATH -o terrain.ply --size N: a field op as a heightfield mesh
// (Colonna, "Animation of fractal objects": fractal mountains and the earthquake of fig. 5).
#include <regex>

#include "app/cli.h"
#include "app/render_setup.h"
#include "mesh/field_heightfield.h"
#include "mesh/mesh_io.h"

namespace gridifs::cli {
namespace {

struct ExportFieldArgs {
  std::string file, op, output;
  int size = 256;
  bool ascii = false;
  std::optional<double> time;
};

/// The field op named by `path` ("functions[0].ops[1]" or "final.ops[0]").
const FieldOp& findFieldOp(const Project& project, const std::string& path, const std::string& file) {
  static const std::regex kPath(R"(^(?:functions\[(\d{1,6})\]|(final))\.ops\[(\d{1,6})\]$)");
  std::smatch m;
  if (!std::regex_match(path, m, kPath))
    throw CliError(kBadInput,
                   "--op must name an operation like functions[0].ops[1] or final.ops[0], not \"" + path + "\"");
  const Function* function = nullptr;
  if (m[2].matched) {
    if (!project.final_function)
      throw CliError(kBadInput, file + " has no final function, so " + path + " does not exist");
    function = &*project.final_function;
  } else {
    const std::size_t index = std::stoul(m[1].str());
    if (index >= project.functions.size())
      throw CliError(kBadInput, file + " has " + std::to_string(project.functions.size()) + " functions, so " + path +
                                    " does not exist");
    function = &project.functions[index];
  }
  const std::size_t op = std::stoul(m[3].str());
  if (op >= function->ops.size())
    throw CliError(kBadInput, file + ": " + path + " does not exist (that function has " +
                                  std::to_string(function->ops.size()) + " operations)");
  const auto* field = std::get_if<FieldOp>(&function->ops[op].params);
  if (!field)
    throw CliError(kBadInput,
                   file + ": " + path + " is a " + opTypeName(function->ops[op].params) + " operation, not a field");
  return *field;
}

int runExportField(const ExportFieldArgs& a) {
  if (a.size < kMinHeightfieldSize || a.size > kMaxHeightfieldSize)
    throw CliError(kBadInput, "--size must be between " + std::to_string(kMinHeightfieldSize) + " and " +
                                  std::to_string(kMaxHeightfieldSize) + " vertices per side");
  try {
    checkMeshOutputPath(a.output);
  } catch (const ModelError& e) {
    throw CliError(kBadInput, e.what());
  }
  const Project project = loadForVerbAt(a.file, a.time);
  const FieldOp& params = findFieldOp(project, a.op, a.file);
  const IfsMesh mesh = fieldHeightfield(FractalField(params), project.time, a.size);
  try {
    writeMeshFile(mesh, a.output, MeshWriteOptions{!a.ascii, true});
  } catch (const ModelError& e) {
    throw CliError(kBadInput, e.what());
  } catch (const IoError& e) {
    throw CliError(kFailure, e.what());
  }
  return kSuccess;
}

const VerbRegistration kExportField{
    {"export-field",
     "FILE --op PATH -o OUT.(ply|obj|stl|off) [--size N --time T --ascii]: a field operation as a heightfield mesh",
     [](CLI::App& app) {
       auto a = std::make_shared<ExportFieldArgs>();
       app.add_option("FILE", a->file, "project file (.gridifs)")->required();
       app.add_option("--op", a->op, "the field operation, e.g. functions[0].ops[1]")->required();
       app.add_option("-o,--output", a->output, "output mesh: .ply, .obj, .stl or .off")->required();
       app.add_option("--size", a->size, "vertices per side of the square [-1, 1]² sheet (default 256)");
       addTimeOption(app, a->time);
       app.add_flag("--ascii", a->ascii, "ASCII PLY or STL instead of binary");
       return [=] { return runExportField(*a); };
     }}};

}  // namespace
}  // namespace gridifs::cli
