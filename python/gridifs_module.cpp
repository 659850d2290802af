// The Python module `gridifs`: projects, parameters, renders, points, volumes and meshes, with the
// command line's code and sentences. docs/PYTHON.md is its guide; the docstrings are its manual.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "app/cli.h"
#include "base/atomic_file.h"
#include "base/errors.h"
#include "io/flame_genome.h"
#include "io/flame_import.h"
#include "live/audio_envelope.h"
#include "python/python_explore.h"
#include "python/python_project.h"
#include "tone/palette.h"

namespace py = pybind11;
using gridifs::python::PythonError;
using gridifs::python::PythonProject;

namespace {

std::unique_ptr<PythonProject> importFlame(const std::string& path, const std::string& genome,
                                           const std::string& paletteFile, int resolution, bool grids) {
  using namespace gridifs;
  if (resolution < 2 || resolution > limits::kMaxResolution)
    throw PythonError("import_flame(): resolution must be between 2 and " + std::to_string(limits::kMaxResolution) +
                      ", not " + std::to_string(resolution) + ".");
  std::vector<FlameGenome> genomes;
  try {
    genomes = loadFlameFile(path);
  } catch (const FlameError& e) {
    throw PythonError(cli::oneSentence(path + ": " + e.what()));
  } catch (const IoError& e) {
    throw PythonError(cli::oneSentence("cannot read " + path + ": " + e.what()));
  }
  const std::filesystem::path flame(path);
  const std::filesystem::path palette = paletteFile.empty()
                                            ? flame.parent_path() / (flame.stem().string() + ".palette.json")
                                            : std::filesystem::path(paletteFile);
  FlameImportOptions options;
  options.resolution = resolution;
  options.sampleOntoGrids = grids;
  options.inlinePaletteReference = "file:" + palette.filename().string();
  FlameImport imported;
  try {
    imported = importFlameGenome(selectGenome(genomes, genome), options);
    // The genome's own colours go beside the project, where its reference finds them.
    if (imported.palette) writeFileAtomically(palette, serializePaletteJson(*imported.palette));
  } catch (const FlameError& e) {
    throw PythonError(cli::oneSentence(path + ": " + e.what()));
  } catch (const IoError& e) {
    throw PythonError(cli::oneSentence(e.what()));
  }
  for (const std::string& w : imported.warnings) PyErr_WarnEx(PyExc_UserWarning, (path + ": " + w).c_str(), 1);
  return std::make_unique<PythonProject>(std::move(imported.project), palette.parent_path(),
                                         flame.stem().string() + ".gridifs");
}

/// The band energies `render --frames` gives "audio:B" bindings (live/audio_envelope.h) as a
/// bands × frames float32 array.
py::array_t<float> audioEnvelope(const std::string& path, const std::vector<std::array<double, 2>>& bands, double fps) {
  using namespace gridifs;
  if (!(fps > 0.0 && fps <= 1000.0)) throw PythonError("audio_envelope(): fps must be above 0 and at most 1000.");
  if (bands.empty()) throw PythonError("audio_envelope(): give at least one band [low, high] in Hz.");
  for (const auto& band : bands)
    if (!(band[0] >= 0.0 && band[1] > band[0]))
      throw PythonError("audio_envelope(): a band is [low, high] in Hz with 0 <= low < high.");
  AudioEnvelope envelope;
  try {
    py::gil_scoped_release release;
    envelope = analyseAudio(path, bands, fps);
  } catch (const IoError& e) {
    throw PythonError(cli::oneSentence(e.what()));
  }
  const auto frames = py::ssize_t(envelope.frames());
  py::array_t<float> out({py::ssize_t(bands.size()), frames});
  auto view = out.mutable_unchecked<2>();
  for (py::ssize_t b = 0; b < py::ssize_t(bands.size()); ++b)
    for (py::ssize_t k = 0; k < frames; ++k) view(b, k) = envelope.energy[std::size_t(b)][std::size_t(k)];
  return out;
}

}  // namespace

PYBIND11_MODULE(gridifs, m) {
  m.doc() =
      "GridIFS: nonlinear 3D iterated function systems from distorted grids.\n\n"
      "Load or build a project, read and set its numbers by their parameter paths, and render it\n"
      "exactly as the command line `gridifs render` does; point clouds, density volumes and meshes\n"
      "come back as numpy arrays. Errors raise gridifs.Error with the command line's sentence.\n\n"
      "    import gridifs\n"
      "    p = gridifs.Project.load('assets/twisted_functions.gridifs')\n"
      "    p.set('functions[0].ops[0].angle', 45)\n"
      "    image = p.render(width=512, height=512, samples='2e6')   # 512x512x4 uint8\n";

  static py::exception<PythonError> error(m, "Error");
  error.doc() =
      "A project, a parameter or an option GridIFS refuses, or work that failed; str(e) is the\n"
      "sentence `gridifs` prints on the command line.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const PythonError& e) {
      error(e.what());
    }
  });

  py::class_<PythonProject>(m, "Project",
                            "A GridIFS project (.gridifs) with its undo history.\n\n"
                            "Relative paths in it (palettes, condensation sets) start from the folder it\n"
                            "was loaded from. Several projects may render at once from several threads;\n"
                            "one project runs one call at a time.")
      .def(py::init([](const std::string& folder) {
             return std::make_unique<PythonProject>(gridifs::Project{}, folder, "<new>");
           }),
           py::arg("folder") = "",
           "Project(folder='') -> the modeller's default project (File > New); relative paths start\n"
           "from `folder` (default: the working folder).")
      .def_static("load", &PythonProject::load, py::arg("path"),
                  "load(path) -> Project: reads a .gridifs file (and the files its construction tree\n"
                  "names), checked as `gridifs info` checks it.")
      .def_static("from_json", &PythonProject::fromJson, py::arg("text"), py::arg("folder") = "",
                  "from_json(text, folder='') -> Project: a project from the file format's JSON text;\n"
                  "relative paths start from `folder`.")
      .def("save", &PythonProject::save, py::arg("path"),
           "save(path): writes the project atomically (the old file is kept as path~).")
      .def("to_json", &PythonProject::toJson, "to_json() -> str: the project as its file holds it.")
      .def("get", &PythonProject::get, py::arg("path"),
           "get(path) -> float: the number at a parameter path, as the file holds it, e.g.\n"
           "'functions[0].weight', 'functions[1].ops[0].k', 'camera.yaw', 'render.flame.gamma'.")
      .def("set", &PythonProject::set, py::arg("path"), py::arg("value"),
           "set(path, value): sets the number at a parameter path as one undo step. The value is\n"
           "checked as the file reader checks it (same range, same sentence); a refused value\n"
           "raises gridifs.Error and leaves the project as it was. A keyframed number is keyed at\n"
           "the project's time, as in the modeller.")
      .def("undo", &PythonProject::undo, "undo() -> bool: takes back the last set(); False when none is left.")
      .def("redo", &PythonProject::redo, "redo() -> bool: does the last undone set() again.")
      .def("paths", &PythonProject::paths,
           "paths() -> list[str]: every parameter path of this project (the numbers its file holds,\n"
           "each one get() reads, set() sets and a keyframe track can drive).")
      .def("render", &PythonProject::render,
           "render(**options) -> numpy array H x W x 4.\n\n"
           "Renders as `gridifs render FILE -o OUT` does with the same options and returns the pixels\n"
           "it would write: uint8 RGBA (the PNG's pixels; alpha 255 unless transparent=True), or with\n"
           "hdr=True float32 RGBA (the EXR's linear, premultiplied R, G, B, A).\n\n"
           "Options (None keeps the project's own): width, height, samples (int or '2e7'),\n"
           "quality, seed, threads, device ('auto', 'gpu', 'cpu'), time (seconds), mode ('zbuffer',\n"
           "'flame', 'shaded', 'volume'), and as the command line's flags: palette, hue, supersample,\n"
           "density_display, filter_radius, estimator_radius, estimator_minimum, estimator_curve,\n"
           "transparent, motion_blur, motion_fade, resolution (mode='volume'), hdr.\n"
           "progress=callable(fraction) is called now and then with the fraction done; an exception\n"
           "it raises, or Ctrl+C, stops the render and is raised again. The GIL is released while\n"
           "the render runs.")
      .def("points", &PythonProject::points, py::arg("n"), py::kw_only(), py::arg("seed") = py::none(),
           py::arg("threads") = 0, py::arg("time") = py::none(), py::arg("progress") = py::none(),
           "points(n, seed=None, threads=0, time=None, progress=None) -> (positions, colours): the\n"
           "chaos-game points of n samples at `time` (seconds; default: the project's own) as m x 3\n"
           "float32 arrays, m <= n: the points `gridifs export-points --device cpu` writes (those that\n"
           "turned non-finite or escaped are left out, as there); colours in [0, 1]. threads: the\n"
           "worker streams to reproduce (0: every core, as render).")
      .def("volume", &PythonProject::volume, py::arg("resolution") = 128, py::kw_only(),
           py::arg("samples") = py::none(), py::arg("seed") = py::none(), py::arg("threads") = 0,
           py::arg("time") = py::none(), py::arg("progress") = py::none(),
           "volume(resolution=128, samples=None, seed=None, threads=0, time=None, progress=None)\n"
           "-> R x R x R float32: the measure attractor's density in [0, 1] over X = [-1, 1]^3, indexed [z, y, x],\n"
           "as `gridifs volume` computes it (samples as an int or '1e8').")
      .def("volume_file", &PythonProject::volumeFile, py::arg("path"), py::arg("resolution") = 128, py::kw_only(),
           py::arg("samples") = py::none(), py::arg("seed") = py::none(), py::arg("threads") = 0,
           py::arg("time") = py::none(), py::arg("progress") = py::none(),
           "volume_file(path, resolution=128, samples=None, seed=None, threads=0, time=None, progress=None):\n"
           "writes the density volume to an OpenVDB file (a float grid 'density'), as `gridifs volume` does;\n"
           "Blender opens it as a Volume object.")
      .def("mesh", &PythonProject::mesh, py::arg("depth") = 3, py::kw_only(), py::arg("base") = "cube",
           py::arg("threads") = 0, py::arg("time") = py::none(), py::arg("progress") = py::none(),
           "mesh(depth=3, base='cube', threads=0, time=None, progress=None) -> (vertices, faces): the\n"
           "deterministic algorithm F^depth(base) of `gridifs export-mesh` as V x 3 float32 vertices\n"
           "and F x 3 int32 triangles; base is 'cube', 'sphere' or a mesh file.")
      .def_property_readonly("source", &PythonProject::source, "The file the project came from ('<json>', '<new>').")
      .def_property_readonly("folder", &PythonProject::folder, "The folder its relative paths start from.")
      .def("__repr__", &PythonProject::repr);

  m.def("random", &gridifs::python::randomProject, py::kw_only(), py::arg("style") = "grid",
        py::arg("seed") = py::none(), py::arg("functions") = 0,
        "random(style='grid', seed=None, functions=0) -> Project: a new world worth looking at, as\n"
        "`gridifs random` draws it: style 'grid', 'flame', 'free-form' or 'volume'; the same seed gives\n"
        "the same project (None: a seed from the clock, kept in the project's lineage); functions 0\n"
        "lets the style choose (3 to 5).");
  m.def("mutate", &gridifs::python::mutatedProject, py::arg("project"), py::kw_only(), py::arg("seed") = py::none(),
        py::arg("strength") = 0.5, py::arg("keep") = std::vector<std::string>{}, py::arg("mate") = nullptr,
        "mutate(project, seed=None, strength=0.5, keep=[], mate=None) -> Project: a child near\n"
        "`project`, as `gridifs mutate` draws it. strength in (0, 1]; keep names what stays byte-equal\n"
        "('ops', 'placement', 'colors', 'variations', 'palette', 'camera', 'tracks'); with mate, the\n"
        "child draws its functions from both projects.");
  m.def("audio_envelope", &audioEnvelope, py::arg("path"), py::arg("bands"), py::kw_only(), py::arg("fps") = 24.0,
        "audio_envelope(path, bands, fps=24.0) -> bands x frames float32: what \"audio:B\" bindings\n"
        "read. Frame k's window is the sound from k/fps to (k+1)/fps mixed to mono, Hann-weighted and\n"
        "zero-padded to a power of two; band [low, high) Hz sums |X(f)|^2 over its bins, divided by\n"
        "the band's largest over the file (silence: exactly 0).");
  m.def("import_flame", &importFlame, py::arg("path"), py::kw_only(), py::arg("genome") = "0",
        py::arg("palette_file") = "", py::arg("resolution") = 64, py::arg("grids") = false,
        "import_flame(path, genome='0', palette_file='', resolution=64, grids=False) -> Project:\n"
        "a genome of a .flame file (flam3, Apophysis, JWildfire, Fractorium) as `gridifs\n"
        "import-flame` makes it; genome is an index or a name. A genome with its own colours has\n"
        "them written to palette_file (default: NAME.palette.json beside the .flame), which the\n"
        "project refers to from its folder.");
}
