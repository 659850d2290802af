// gridifs export-mesh FILE -o OUT.(ply|obj|stl|off) --depth D [--base cube|sphere|MESH] [--subdivide S]:
// the deterministic algorithm F^D(base) (Gröller & Wegenkittl 1994, §3.2) written through OpenMesh.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "app/cli.h"
#include "app/progress_bar.h"
#include "app/set_iterate_output.h"
#include "io/project_io.h"
#include "mesh/deterministic_ifs.h"
#include "mesh/mesh_io.h"
#include "volume/condensation_mesh.h"
#include "volume/measure_attractor.h"

namespace gridifs::cli {
namespace {

struct ExportMeshArgs {
  std::string file, output, base = "cube";
  int depth = 0, subdivide = 0, threads = 0;
  bool smooth = false, fit = false, ascii = false;
  std::uint64_t maxFaces = DeterministicLimits{}.maxFaces;
  std::optional<double> time;
};

BaseMeshSpec baseSpec(const ExportMeshArgs& a, MeshFormat format) {
  const BaseShape shape = a.base == "cube" ? BaseShape::Cube : a.base == "sphere" ? BaseShape::Sphere : BaseShape::File;
  return baseMeshSpec(shape, a.base, a.subdivide, a.smooth, a.fit, format);
}

bool outsideCube(const IfsMesh& mesh) {
  constexpr float kSlack = 1e-4f;
  for (auto vh : mesh.vertices()) {
    const auto& p = mesh.point(vh);
    for (int d = 0; d < 3; ++d)
      if (std::fabs(p[d]) > 1.0f + kSlack) return true;
  }
  return false;
}

int runExportMesh(const ExportMeshArgs& a) {
  const auto start = std::chrono::steady_clock::now();
  const std::filesystem::path output = a.output;
  // Everything that can be checked before the work is checked first: nothing is written on
  // bad input, and a long computation never ends in "cannot write".
  try {
    checkMeshOutputPath(output);
  } catch (const ModelError& e) {
    throw CliError(kBadInput, e.what());
  }
  const MeshFormat format = *meshFormatFromPath(output);
  if (usesSetIteration(loadForVerbAt(a.file, a.time))) {
    // Median functions map voxel sets (Sokolov & Gentil, §3.2): the deterministic algorithm runs
    // over sets from volume.start, and the mesh is the iso-surface of A_D.
    if (a.base != "cube" || a.subdivide || a.smooth || a.fit)
      throw CliError(kBadInput, a.file +
                                    ": with median functions A_D starts from the project's volume.start set, so "
                                    "--base, --subdivide, --smooth and --fit do not apply");
    SetIterateRequest r;
    r.file = a.file;
    r.out = a.output;
    r.depth = a.depth;
    r.threads = a.threads > 0 ? std::optional<int>(a.threads) : std::nullopt;
    r.time = a.time;
    r.ascii = a.ascii;
    return runSetIterates(r);
  }
  Document document(loadForVerbAt(a.file, a.time));
  DeterministicIfs ifs;
  try {
    ifs = snapshotDeterministicIfs(document.project(), document.evaluation());
  } catch (const ModelError& e) {
    throw CliError(kBadInput, a.file + ": " + e.what());
  }
  try {
    // Condensation sets enter A_n = C ∪ F(A_{n−1}) as their surface meshes.
    const std::filesystem::path project = a.file;
    loadCondensationMeshes(ifs, document.project(),
                           project.parent_path().empty() ? std::filesystem::path(".") : project.parent_path());
  } catch (const ModelError& e) {
    throw CliError(kBadInput, a.file + ": " + e.what());
  }

  const BaseMeshSpec spec = baseSpec(a, format);
  DeterministicOptions options;
  options.depth = a.depth;
  options.threads = a.threads;
  options.limits.maxFaces = a.maxFaces;
  IfsMesh coarse;
  DeterministicPlan plan;
  try {
    coarse = loadCoarseBase(spec);  // messages name the base mesh file
    plan = planDeterministic(ifs, predictBaseCounts(coarse, spec), options);
  } catch (const ModelError& e) {
    throw CliError(kBadInput, e.path() == "functions" ? a.file + ": " + e.message() : e.message());
  }
  if (plan.overLimit) throw CliError(kBadInput, a.file + ": " + plan.message);
  if (plan.overBudget) std::fprintf(stderr, "warning: %s.\n", plan.message.c_str());
  if (spec.shape == BaseShape::File && !spec.fitToCube && outsideCube(coarse))
    std::fprintf(stderr,
                 "warning: %s reaches outside X = [-1, 1]^3, where the functions clamp points onto the cube's "
                 "surface; --fit scales it into X.\n",
                 spec.file.c_str());
  if (!formatHasVertexColors(format))
    std::fprintf(stderr, "note: %s files carry no vertex colors; write .ply for colors.\n", meshFormatName(format));

  ProgressBar bar("export-mesh", false);
  try {
    const IfsMesh base = refineBase(std::move(coarse), spec);
    // Initialised in place: OpenMesh meshes copy on assignment (no move), which would double
    // the peak memory of a large result.
    const DeterministicMesh result =
        buildDeterministicMesh(ifs, base, options, [&](double f) { return bar.fraction(f); });
    bar.message("writing " + output.string());
    writeMeshFile(result.mesh, output, MeshWriteOptions{!a.ascii, true});
  } catch (const ModelError& e) {
    bar.finish();
    throw CliError(kBadInput, e.message());
  } catch (const IoError& e) {
    bar.finish();
    throw CliError(kFailure, e.what());
  }
  bar.finish();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (plan.condensationCopies == 0)
    std::printf("%s: F^%d(%s) = %llu copies x %llu faces = %llu faces, %llu vertices (%.2f s)\n", output.c_str(),
                a.depth, a.base.c_str(), static_cast<unsigned long long>(plan.copies),
                static_cast<unsigned long long>(plan.base.faces), static_cast<unsigned long long>(plan.total.faces),
                static_cast<unsigned long long>(plan.total.vertices), seconds);
  else
    std::printf(
        "%s: A_%d = %llu copies x %llu faces of %s + %llu copies x %llu faces of the condensation sets = %llu "
        "faces, %llu vertices (%.2f s)\n",
        output.c_str(), a.depth, static_cast<unsigned long long>(plan.copies),
        static_cast<unsigned long long>(plan.base.faces), a.base.c_str(),
        static_cast<unsigned long long>(plan.condensationCopies),
        static_cast<unsigned long long>(
            plan.condensationCopies == 0 ? 0 : plan.condensation.faces / plan.condensationCopies),
        static_cast<unsigned long long>(plan.total.faces), static_cast<unsigned long long>(plan.total.vertices),
        seconds);
  return kSuccess;
}

const VerbRegistration kExportMesh{
    {"export-mesh", "FILE -o OUT.(ply|obj|stl|off) --depth D: the deterministic algorithm F^D(base) as a mesh",
     [](CLI::App& app) {
       auto a = std::make_shared<ExportMeshArgs>();
       app.add_option("FILE", a->file, "project file (.gridifs)")->required();
       app.add_option("-o,--output", a->output,
                      "mesh to write: .ply (binary, vertex colors and a per-face 'address'), .off (colors), "
                      ".obj or .stl (triangulated)")
           ->required();
       addTimeOption(app, a->time);
       addSetOption(app);
       app.add_option("--depth", a->depth, "n in F^n(A): N^n copies of the base mesh")
           ->required()
           ->check(CLI::Range(0, kMaxDeterministicDepth));
       app.add_option("--base", a->base,
                      "the initial shape A: cube (X = [-1,1]^3), sphere, or a .obj/.ply/.stl/.off file")
           ->capture_default_str();
       app.add_option("--subdivide", a->subdivide,
                      "subdivision levels of the base (about 4x faces each) so nonlinear functions bend its edges; "
                      "1-3 for nonlinear IFSs")
           ->capture_default_str()
           ->check(CLI::Range(0, kMaxSubdivision));
       app.add_flag("--smooth", a->smooth, "subdivide with Loop / Catmull-Clark smoothing (rounds the base)");
       app.add_flag("--fit", a->fit, "scale and center a mesh file uniformly into X = [-1,1]^3");
       app.add_flag("--ascii", a->ascii, "write ASCII PLY/STL instead of binary");
       app.add_option("--threads", a->threads, "worker threads (0: all cores)")
           ->capture_default_str()
           ->check(CLI::NonNegativeNumber);
       app.add_option("--max-faces", a->maxFaces, "refuse results with more faces than this")
           ->capture_default_str()
           ->check(CLI::PositiveNumber);
       return [a] { return runExportMesh(*a); };
     },
     /*hugePageHeap=*/true}};

}  // namespace
}  // namespace gridifs::cli
