// gridifs export-field FILE [--op PATH] [-o terrain.ply] [--image field.png] --size N: a field
// operation or the volume's field layers as a heightfield mesh (Colonna, "Animation of fractal
// objects": fractal mountains and the earthquake of fig. 5) and as a colour-mapped picture (his
// fig. 2; the field blended with a shape, fig. 3; mountains under clouds, fig. 6).
#include <cstdio>
#include <regex>

#include "app/cli.h"
#include "app/render_setup.h"
#include "mesh/field_heightfield.h"
#include "mesh/field_layer_mesh.h"
#include "mesh/mesh_io.h"
#include "render/field_image.h"
#include "schema/field_layer.h"
#include "tone/palette.h"

namespace gridifs::cli {
namespace {

struct ExportFieldArgs {
  std::string file, op, output, image, palette = "gray";
  int size = 256;
  std::optional<int> octaves;
  bool ascii = false;
  std::optional<double> time;
};

/// The field op named by `path` ("functions[0].ops[1]" or "final.ops[0]"), or null for a path
/// of another form.
const FieldOp* findFieldOp(const Project& project, const std::string& path, const std::string& file) {
  static const std::regex kPath(R"(^(?:functions\[(\d{1,6})\]|(final))\.ops\[(\d{1,6})\]$)");
  std::smatch m;
  if (!std::regex_match(path, m, kPath)) return nullptr;
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
  return field;
}

/// The layers `path` names: "volume.field" all of them, "volume.field[i]" one; empty for a path of
/// another form.
std::vector<const VolumeDensityField*> findLayers(const Project& project, const std::string& path,
                                                  const std::string& file) {
  static const std::regex kPath(R"(^volume\.field(?:\[(\d{1,6})\])?$)");
  std::smatch m;
  if (!std::regex_match(path, m, kPath)) return {};
  const std::vector<const VolumeDensityField*> layers =
      project.volume ? fieldLayers(*project.volume) : std::vector<const VolumeDensityField*>{};
  if (layers.empty()) throw CliError(kBadInput, file + " has no volume.field, so " + path + " does not exist");
  if (!m[1].matched) return layers;
  const std::size_t index = std::stoul(m[1].str());
  if (index >= layers.size())
    throw CliError(kBadInput,
                   file + " has " + std::to_string(layers.size()) + " field layers, so " + path + " does not exist");
  return {layers[index]};
}

/// What --op names, as field layers: a field operation becomes the layer of its z displacement,
/// F_{S+2} on the z = 0 plane, which is what raises its heightfield.
struct ChosenField {
  const FieldOp* op = nullptr;
  std::vector<const VolumeDensityField*> layers;
  std::vector<VolumeDensityField> owned;  // the op's layer, or the layers --octaves cut
  FieldOp opOctaves;                      // the op --octaves cut
};

ChosenField chooseField(const Project& project, std::string path, const std::string& file) {
  if (path.empty()) {
    // Without --op: the volume's layers, else the project's only field operation.
    if (project.volume && project.volume->field) {
      path = "volume.field";
    } else {
      std::vector<std::string> ops;
      const auto collect = [&](const Function& f, const std::string& name) {
        for (std::size_t o = 0; o < f.ops.size(); ++o)
          if (std::holds_alternative<FieldOp>(f.ops[o].params)) ops.push_back(name + ".ops[" + std::to_string(o) + "]");
      };
      for (std::size_t f = 0; f < project.functions.size(); ++f)
        collect(project.functions[f], "functions[" + std::to_string(f) + "]");
      if (project.final_function) collect(*project.final_function, "final");
      if (ops.size() != 1)
        throw CliError(kBadInput, file + " has " + std::to_string(ops.size()) +
                                      " field operations and no volume.field: name one with --op");
      path = ops.front();
    }
  }
  ChosenField chosen;
  if ((chosen.op = findFieldOp(project, path, file))) {
    VolumeDensityField layer;
    layer.field = *chosen.op;
    layer.field.seed += 2;  // axis 2 of seed S is axis 0 of seed S + 2
    chosen.owned.push_back(layer);
    chosen.layers.push_back(&chosen.owned.back());
    return chosen;
  }
  chosen.layers = findLayers(project, path, file);
  if (chosen.layers.empty())
    throw CliError(kBadInput,
                   "--op must name a field like functions[0].ops[1], final.ops[0], volume.field or "
                   "volume.field[1], not \"" +
                       path + "\"");
  return chosen;
}

/// --octaves K: the sum of the first K meshes alone, M_1 + … + M_K (Colonna's fig. 2 shows the
/// first three such sums and the whole field). The weights p(k) ∝ gain^k are normalised over the
/// meshes kept, which scales the sum but leaves its picture unchanged.
void keepOctaves(ChosenField& chosen, int octaves) {
  if (octaves < 1 || octaves > FractalFieldParams::kMaxOctaves)
    throw CliError(kBadInput, "--octaves must be between 1 and " + std::to_string(FractalFieldParams::kMaxOctaves));
  std::vector<VolumeDensityField> owned;
  for (const VolumeDensityField* layer : chosen.layers) {
    owned.push_back(*layer);
    owned.back().field.octaves = std::min(octaves, layer->field.octaves);
  }
  chosen.owned = std::move(owned);
  chosen.layers.clear();
  for (const VolumeDensityField& layer : chosen.owned) chosen.layers.push_back(&layer);
  if (chosen.op) {
    chosen.opOctaves = *chosen.op;
    chosen.opOctaves.octaves = std::min(octaves, chosen.op->octaves);
    chosen.op = &chosen.opOctaves;
  }
}

/// An EXR channel's name: "layer00_terrain", … (OpenEXR stores channels sorted by name, so the
/// two-digit index keeps them in the layers' order).
std::string layerChannel(std::size_t index, FieldRole role) {
  char name[32];
  std::snprintf(name, sizeof name, "layer%02zu_%s", index, toString(role));
  return name;
}

Palette imagePalette(const std::string& name) {
  try {
    return builtinPalette(name);
  } catch (const PaletteError& e) {
    throw CliError(kBadInput, e.what());
  }
}

void writeImage(const ExportFieldArgs& a, const ChosenField& chosen, double t, const Palette& palette) {
  std::vector<FieldPlane> planes;
  for (std::size_t i = 0; i < chosen.layers.size(); ++i) {
    const VolumeDensityField& layer = *chosen.layers[i];
    planes.push_back({fieldLayerPlane(layer, a.size, fieldLayerPlaneHeight(layer), t), layer.role, layer.strength,
                      chosen.layers.size() == 1 ? std::string("Y") : layerChannel(i, layer.role)});
  }
  try {
    writeFieldImage(a.image, planes, a.size, palette);
  } catch (const IoError& e) {
    throw CliError(kFailure, e.what());
  }
}

int runExportField(const ExportFieldArgs& a) {
  if (a.size < kMinHeightfieldSize || a.size > kMaxHeightfieldSize)
    throw CliError(kBadInput, "--size must be between " + std::to_string(kMinHeightfieldSize) + " and " +
                                  std::to_string(kMaxHeightfieldSize) + " vertices per side");
  if (a.output.empty() && a.image.empty())
    throw CliError(kBadInput, "export-field needs -o OUT for a mesh, --image OUT.png for a picture, or both");
  if (!a.output.empty()) {
    try {
      checkMeshOutputPath(a.output);
    } catch (const ModelError& e) {
      throw CliError(kBadInput, e.what());
    }
  }
  if (!a.image.empty()) checkOutputPath(a.image, {"png", "exr", "tif", "tiff", "jpg", "jpeg"}, "--image");
  const Palette palette = imagePalette(a.palette);
  const Project project = loadForVerbAt(a.file, a.time);
  ChosenField chosen = chooseField(project, a.op, a.file);
  if (a.octaves) keepOctaves(chosen, *a.octaves);
  if (!a.output.empty()) {
    const IfsMesh mesh = chosen.op ? fieldHeightfield(FractalField(*chosen.op), project.time, a.size)
                                   : fieldLayerSheets(chosen.layers, project.time, a.size);
    try {
      writeMeshFile(mesh, a.output, MeshWriteOptions{!a.ascii, true});
    } catch (const ModelError& e) {
      throw CliError(kBadInput, e.what());
    } catch (const IoError& e) {
      throw CliError(kFailure, e.what());
    }
  }
  if (!a.image.empty()) writeImage(a, chosen, project.time, palette);
  return kSuccess;
}

const VerbRegistration kExportField{
    {"export-field",
     "FILE [--op PATH] [-o OUT.(ply|obj|stl|off)] [--image OUT.(png|exr)] [--size N --palette NAME --octaves K "
     "--time T --ascii]: a field operation or the volume's field layers as a heightfield mesh and a colour-mapped "
     "image",
     [](CLI::App& app) {
       auto a = std::make_shared<ExportFieldArgs>();
       app.add_option("FILE", a->file, "project file (.gridifs)")->required();
       app.add_option("--op", a->op,
                      "the field: an operation (functions[0].ops[1], final.ops[0]), volume.field (every layer) or "
                      "volume.field[i] (one layer); default: volume.field, else the only field operation");
       app.add_option("-o,--output", a->output, "output mesh: .ply, .obj, .stl or .off");
       app.add_option("--image", a->image,
                      "output image: the field over [-1, 1]² colour-mapped (.png, .tif, .jpg) or raw values (.exr)");
       app.add_option("--size", a->size, "vertices (mesh) and pixels (image) per side of the square (default 256)");
       app.add_option("--palette", a->palette, "the image's palette: a built-in name (default gray)");
       app.add_option("--octaves", a->octaves, "only the first K meshes of each field, M_1 + ... + M_K");
       addTimeOption(app, a->time);
       addSetOption(app);
       app.add_flag("--ascii", a->ascii, "ASCII PLY or STL instead of binary");
       return [=] { return runExportField(*a); };
     },
     /*hugePageHeap=*/true}};

}  // namespace
}  // namespace gridifs::cli
