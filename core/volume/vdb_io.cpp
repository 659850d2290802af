#include "volume/vdb_io.h"

#include <mutex>

#include "base/errors.h"
#include "base/plugin_library.h"
#include "vdb_io_abi.h"

namespace gridifs::vdb_io {
namespace {

constexpr const char* kPluginFile = "libgridifs_vdb_io.so";

struct Plugin {
  std::string problem;  // why it could not be loaded
  decltype(&gridifs_vdb_io_write_volume) writeVolume = nullptr;
  decltype(&gridifs_vdb_io_mesh_voxels) meshVoxels = nullptr;
  decltype(&gridifs_vdb_io_grid_voxels) gridVoxels = nullptr;
  decltype(&gridifs_vdb_io_grid_mesh) gridMesh = nullptr;
};

/// The plugin, loaded once (on first use, from any thread); throws IoError when it cannot be.
const Plugin& plugin() {
  static Plugin loaded;
  static std::once_flag once;
  std::call_once(once, [] {
    const PluginLibrary library =
        loadPluginLibrary(kPluginFile, "GRIDIFS_VDB_IO", GRIDIFS_VDB_IO_BUILD_DIR, "gridifs_vdb_io_abi_version",
                          GRIDIFS_VDB_IO_ABI_VERSION, "the OpenVDB library");
    if (!library.handle) {
      loaded.problem = library.problem;
      return;
    }
    loaded.writeVolume = reinterpret_cast<decltype(loaded.writeVolume)>(library.symbol("gridifs_vdb_io_write_volume"));
    loaded.meshVoxels = reinterpret_cast<decltype(loaded.meshVoxels)>(library.symbol("gridifs_vdb_io_mesh_voxels"));
    loaded.gridVoxels = reinterpret_cast<decltype(loaded.gridVoxels)>(library.symbol("gridifs_vdb_io_grid_voxels"));
    loaded.gridMesh = reinterpret_cast<decltype(loaded.gridMesh)>(library.symbol("gridifs_vdb_io_grid_mesh"));
    if (!loaded.writeVolume || !loaded.meshVoxels || !loaded.gridVoxels || !loaded.gridMesh)
      loaded.problem = std::string("the OpenVDB library (") + kPluginFile + ") is from another version of GridIFS";
  });
  if (!loaded.problem.empty()) throw IoError(loaded.problem);
  return loaded;
}

struct VoxelCollector {
  const VoxelLattice* lattice;
  std::vector<std::uint32_t> voxels;
  static void add(void* context, const std::int32_t* ijk, std::size_t count) {
    auto& self = *static_cast<VoxelCollector*>(context);
    for (std::size_t v = 0; v < count; ++v)
      self.voxels.push_back(self.lattice->index(ijk[3 * v], ijk[3 * v + 1], ijk[3 * v + 2]));
  }
};

/// The ModelError of a grid that could not be read, as the project file's author needs it.
[[noreturn]] void gridFailure(int status, const std::string& message, const std::filesystem::path& file,
                              const std::string& grid, const std::string& jsonPath) {
  switch (status) {
    case GRIDIFS_VDB_NO_SUCH_GRID:
      throw ModelError(jsonPath + ".grid",
                       "the VDB file " + file.string() + " has no grid named \"" + grid.substr(0, 64) + "\"");
    case GRIDIFS_VDB_NOT_FLOAT_GRID:
      throw ModelError(jsonPath + ".grid",
                       "the grid \"" + grid.substr(0, 64) + "\" of " + file.string() + " is not a float grid");
    default:
      throw ModelError(jsonPath + ".vdb", "cannot read the VDB file " + file.string() + ": " + message);
  }
}

void requireFile(const std::filesystem::path& file, const std::string& jsonPath) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    throw ModelError(jsonPath + ".vdb", "the VDB file " + file.string() + " does not exist");
}

}  // namespace

void requirePlugin() { plugin(); }

void writeVolume(const std::filesystem::path& file, const VoxelLattice& lattice, const std::vector<float>& density,
                 const std::vector<float>& color) {
  const Plugin& p = plugin();
  char message[1024] = {};
  if (p.writeVolume(file.c_str(), lattice.n, density.data(), color.empty() ? nullptr : color.data(), message,
                    sizeof message) != GRIDIFS_VDB_OK)
    throw IoError(std::string(message));
}

std::vector<std::uint32_t> meshVoxels(const FaceLists& mesh, const VoxelLattice& lattice, bool solid,
                                      float halfDiagonal, const std::string& jsonPath) {
  const Plugin& p = plugin();
  VoxelCollector out{&lattice, {}};
  char message[1024] = {};
  if (p.meshVoxels(lattice.n, mesh.points.data(), mesh.points.size() / 3, mesh.triangles.data(),
                   mesh.triangles.size() / 3, mesh.quads.data(), mesh.quads.size() / 4, solid ? 1 : 0, halfDiagonal,
                   &VoxelCollector::add, &out, message, sizeof message) != GRIDIFS_VDB_OK)
    throw ModelError(jsonPath + ".mesh", std::string("cannot voxelize the mesh: ") + message);
  return std::move(out.voxels);
}

std::vector<std::uint32_t> gridVoxels(const std::filesystem::path& file, const std::string& grid,
                                      const VoxelLattice& lattice, float threshold, const std::string& jsonPath) {
  requireFile(file, jsonPath);
  const Plugin& p = plugin();
  VoxelCollector out{&lattice, {}};
  char message[1024] = {};
  if (const int status = p.gridVoxels(file.c_str(), grid.c_str(), lattice.n, threshold, &VoxelCollector::add, &out,
                                      message, sizeof message);
      status != GRIDIFS_VDB_OK)
    gridFailure(status, message, file, grid, jsonPath);
  return std::move(out.voxels);
}

FaceLists gridIsoSurface(const std::filesystem::path& file, const std::string& grid, float threshold,
                         const std::string& jsonPath) {
  requireFile(file, jsonPath);
  const Plugin& p = plugin();
  FaceLists out;
  auto receive = [](void* context, const float* points, std::size_t pointCount, const std::uint32_t* triangles,
                    std::size_t triangleCount, const std::uint32_t* quads, std::size_t quadCount) {
    auto& lists = *static_cast<FaceLists*>(context);
    lists.points.assign(points, points + 3 * pointCount);
    lists.triangles.assign(triangles, triangles + 3 * triangleCount);
    lists.quads.assign(quads, quads + 4 * quadCount);
  };
  char message[1024] = {};
  if (const int status = p.gridMesh(file.c_str(), grid.c_str(), threshold, receive, &out, message, sizeof message);
      status != GRIDIFS_VDB_OK)
    gridFailure(status, message, file, grid, jsonPath);
  return out;
}

}  // namespace gridifs::vdb_io
