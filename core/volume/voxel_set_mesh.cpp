#include "volume/voxel_set_mesh.h"

#include <unistd.h>
#include <atomic>

#include "base/atomic_file.h"
#include "volume/vdb_io.h"

namespace gridifs {

IfsMesh voxelSetMesh(const VoxelSet& set) {
  IfsMesh mesh;
  if (set.empty()) return mesh;
  std::vector<float> density(set.lattice.voxelCount(), 0.0f);
  for (std::uint32_t v : set.voxels) density[v] = 1.0f;
  // The OpenVDB plugin meshes grids read from files (vdb_io.h): the set goes through a temporary
  // file that the AtomicFile removes, never committed.
  static std::atomic<unsigned> counter{0};
  const std::filesystem::path target =
      std::filesystem::temp_directory_path() /
      ("gridifs-set-" + std::to_string(::getpid()) + "-" + std::to_string(counter.fetch_add(1)) + ".vdb");
  AtomicFile temporary(target);
  vdb_io::writeVolume(temporary.temporaryPath(), set.lattice, density, {});
  const vdb_io::FaceLists faces = vdb_io::gridIsoSurface(temporary.temporaryPath(), "density", 0.5f, "set");
  std::vector<IfsMesh::VertexHandle> vs;
  vs.reserve(faces.points.size() / 3);
  for (std::size_t p = 0; p + 2 < faces.points.size(); p += 3)
    vs.push_back(mesh.add_vertex(IfsMesh::Point(faces.points[p], faces.points[p + 1], faces.points[p + 2])));
  // volumeToMesh winds faces for a level set (inside below the iso-value); inside is 1 here.
  for (std::size_t q = 0; q + 3 < faces.quads.size(); q += 4)
    mesh.add_face(vs[faces.quads[q + 3]], vs[faces.quads[q + 2]], vs[faces.quads[q + 1]], vs[faces.quads[q]]);
  for (std::size_t t = 0; t + 2 < faces.triangles.size(); t += 3)
    mesh.add_face(vs[faces.triangles[t + 2]], vs[faces.triangles[t + 1]], vs[faces.triangles[t]]);
  return mesh;
}

}  // namespace gridifs
