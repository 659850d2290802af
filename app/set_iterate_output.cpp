#include "app/set_iterate_output.h"

#include <cstdio>
#include <memory>

#include "app/cli.h"
#include "app/progress_bar.h"
#include "app/render_sequence.h"
#include "app/render_setup.h"
#include "base/text_format.h"
#include "mesh/mesh_io.h"
#include "volume/set_iterates.h"
#include "volume/vdb_volume_file.h"
#include "volume/voxel_set_mesh.h"

namespace gridifs::cli {
namespace {

enum class SetOutput { Volume, Image, Mesh };

SetOutput outputKind(const std::string& out) {
  const std::string ext = lowerExtension(out);
  if (ext == "vdb") return SetOutput::Volume;
  if (ext == "png" || ext == "exr" || ext == "tif" || ext == "tiff") return SetOutput::Image;
  return SetOutput::Mesh;
}

/// One set to one file: its density volume (1 inside, 0 outside), its points through the renderer
/// in the project's display mode, or the iso-surface of its density at 1/2.
void writeSet(const VoxelSet& set, const Project& project, const SetIterateRequest& r, const std::string& path) {
  try {
    switch (outputKind(r.out)) {
      case SetOutput::Volume:
        writeVdbVolume(setDensityVolume(set), path);
        return;
      case SetOutput::Mesh:
        writeMeshFile(voxelSetMesh(set), path, MeshWriteOptions{!r.ascii, false});
        return;
      case SetOutput::Image: {
        if (set.empty())
          throw CliError(kFailure, "cannot write " + path + ": the set is empty, so there is nothing to draw");
        RenderOverrides overrides;
        overrides.threads = r.threads;
        overrides.device = "cpu";
        overrides.volume = std::make_shared<const DensityVolume>(setDensityVolume(set));
        renderImageOf(project, r.file, path, overrides, true);
        return;
      }
    }
  } catch (const IoError& e) {
    throw CliError(kFailure, e.what());
  }
}

}  // namespace

int runSetIterates(const SetIterateRequest& r) {
  checkOutputPath(r.out, {"vdb", "png", "exr", "tif", "tiff", "obj", "ply", "stl", "off"},
                  "a set iterate (a volume, an image or a mesh)");
  if (r.pages) checkFramePattern(r.out);
  if (r.depth < 0 || r.depth > kMaxSetDepth)
    throw CliError(kBadInput, "--depth must be between 0 and " + std::to_string(kMaxSetDepth) + ", not " +
                                  std::to_string(r.depth));
  const SetOutput kind = outputKind(r.out);
  try {
    if (kind != SetOutput::Image) requireVdbVolumeWriter();  // meshes are OpenVDB's iso-surfaces
  } catch (const IoError& e) {
    throw CliError(kFailure, e.what());
  }
  const std::filesystem::path file(r.file);
  const Project project = loadForVerbAt(file, r.time);
  int resolution = project.volume ? project.volume->resolution : VolumeSettings{}.resolution;
  if (r.resolution) {
    if (*r.resolution < kMinVolumeResolution || *r.resolution > kMaxVolumeResolution)
      throw CliError(kBadInput, "--resolution must be between " + std::to_string(kMinVolumeResolution) + " and " +
                                    std::to_string(kMaxVolumeResolution) + ", not " + std::to_string(*r.resolution));
    resolution = *r.resolution;
  }
  const std::filesystem::path folder = file.parent_path().empty() ? std::filesystem::path(".") : file.parent_path();
  const VoxelLattice lattice{resolution};
  SetSystem system;
  VoxelSet start;
  try {
    system = buildSetSystem(project, lattice, folder);
    start = startSet(project, lattice, folder);
  } catch (const ModelError& e) {
    throw CliError(kBadInput, file.string() + ": " + e.what());
  }
  const int threads = r.threads.value_or(0);
  ProgressBar bar(r.pages ? "book of drawings" : "set iterate", r.quiet);
  auto progress = [&](double done) { bar.fraction(done); };
  if (r.pages) {
    const std::int64_t pages = bookPageCount(system.functions.size(), r.depth, kMaxBookPages);
    if (pages < 0)
      throw CliError(kBadInput, file.string() + ": a book of depth " + std::to_string(r.depth) + " with " +
                                    std::to_string(system.functions.size()) + " functions has more than " +
                                    std::to_string(kMaxBookPages) + " pages; lower --depth");
    forEachBookPage(
        system, start, r.depth, threads,
        [&](std::int64_t number, const VoxelSet& set) { writeSet(set, project, r, frameFileName(r.out, number)); },
        progress);
    bar.finish();
    if (!r.quiet)
      std::fprintf(stderr, "%lld pages, numbered by their address in base %zu\n", static_cast<long long>(pages),
                   system.functions.size());
    return kSuccess;
  }
  const VoxelSet set = iterateSets(system, start, r.depth, threads, progress);
  if (set.empty())
    throw CliError(kFailure, file.string() + ": the set iterate A_" + std::to_string(r.depth) +
                                 " is empty (every function sent the set out of X)");
  bar.message("writing " + r.out);
  writeSet(set, project, r, r.out);
  bar.finish();
  return kSuccess;
}

}  // namespace gridifs::cli
