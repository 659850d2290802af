// The OpenVDB plugin: GridIFS's one use of OpenVDB (see vdb_io_abi.h for why it is a plugin).
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/LevelSetUtil.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "vdb_io_abi.h"

namespace {

void initialize() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

int failWith(int status, std::string message, char* error, std::size_t errorSize) {
  while (!message.empty() && message.back() == '\n') message.pop_back();
  if (message.empty()) message = "the OpenVDB library reported an error";
  if (error && errorSize > 0) {
    const std::size_t n = std::min(message.size(), errorSize - 1);
    std::memcpy(error, message.data(), n);
    error[n] = '\0';
  }
  return status;
}

/// Runs `body`, turning any exception into GRIDIFS_VDB_FAILED with its message.
template <class Body>
int guarded(char* error, std::size_t errorSize, Body body) {
  try {
    return body();
  } catch (const std::exception& e) {
    return failWith(GRIDIFS_VDB_FAILED, e.what(), error, errorSize);
  } catch (...) {
    return failWith(GRIDIFS_VDB_FAILED, "", error, errorSize);
  }
}

/// Grid index (i, j, k) is lattice voxel (i, j, k): voxel size 2/N, voxel 0's centre at −1 + 1/N.
openvdb::math::Transform::Ptr latticeTransform(int n) {
  auto xform = openvdb::math::Transform::createLinearTransform(2.0 / n);
  const double origin = -1.0 + 1.0 / n;
  xform->postTranslate(openvdb::Vec3d(origin, origin, origin));
  return xform;
}

/// OpenVDB writes a new random UUID into every file's header (io::Archive::writeHeader), so two
/// writes of the same volume differed in those bytes, and so did a merged volume (gridifs merge)
/// and the one `gridifs volume` writes, which must be equal byte for byte. The UUID
/// is replaced by one derived from the rest of the file: the same grids get the same UUID, other
/// grids another (what readers such as Houdini use it for). The header: magic (8 bytes), file
/// version, library major and minor (4 each), the grid-offsets flag (1), then the UUID as 36
/// characters. A file whose header does not look so is left as it is.
void replaceRandomUuid(const char* path) {
  constexpr std::size_t kAt = 21, kLength = 36;
  std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
  char header[kAt + kLength];
  if (!file.read(header, sizeof header)) return;
  for (std::size_t i = 0; i < kLength; ++i) {
    const char c = header[kAt + i];
    const bool dash = i == 8 || i == 13 || i == 18 || i == 23;
    if (dash ? c != '-' : !std::isxdigit(static_cast<unsigned char>(c))) return;
  }
  // Two independent 64-bit FNV-1a passes over everything after the UUID.
  std::uint64_t a = 0xCBF29CE484222325ull, b = 0x84222325CBF29CE4ull;
  std::vector<char> block(1 << 20);
  while (file.read(block.data(), std::streamsize(block.size())) || file.gcount() > 0) {
    for (std::streamsize i = 0; i < file.gcount(); ++i) {
      const auto c = static_cast<unsigned char>(block[std::size_t(i)]);
      a = (a ^ c) * 0x100000001B3ull;
      b = (b ^ (c + 0x9Bu)) * 0x100000001B3ull;
      b ^= b >> 29;
    }
  }
  // Version 8 (custom) and the RFC 4122 variant, as 8-4-4-4-12 hex digits.
  b = (b & ~(std::uint64_t(0xF) << 12)) | (std::uint64_t(0x8) << 12);
  a = (a & ~(std::uint64_t(0x3) << 62)) | (std::uint64_t(0x2) << 62);
  char uuid[kLength + 1];
  std::snprintf(uuid, sizeof uuid, "%08llx-%04llx-%04llx-%04llx-%012llx", static_cast<unsigned long long>(b >> 32),
                static_cast<unsigned long long>((b >> 16) & 0xFFFF), static_cast<unsigned long long>(b & 0xFFFF),
                static_cast<unsigned long long>(a >> 48), static_cast<unsigned long long>(a & 0xFFFFFFFFFFFFull));
  file.clear();
  file.seekp(std::streamoff(kAt));
  if (!file.write(uuid, std::streamsize(kLength)) || !file.flush())
    throw std::runtime_error(std::string("cannot write the header of ") + path);
}

/// Hands voxels to the caller a block at a time.
class VoxelSink {
 public:
  VoxelSink(GridifsVdbVoxels emit, void* context) : emit_(emit), context_(context) { block_.reserve(3 * kBlock); }
  ~VoxelSink() = default;
  void add(int i, int j, int k) {
    block_.insert(block_.end(), {i, j, k});
    if (block_.size() == 3 * kBlock) flush();
  }
  void flush() {
    if (!block_.empty()) emit_(context_, block_.data(), block_.size() / 3);
    block_.clear();
  }

 private:
  static constexpr std::size_t kBlock = 4096;
  GridifsVdbVoxels emit_;
  void* context_;
  std::vector<std::int32_t> block_;
};

/// The lattice voxels of the active values of `grid` (voxels and tiles) that `keep` accepts.
template <class Grid, class Keep>
void collectActive(const Grid& grid, int n, Keep keep, VoxelSink& out) {
  const openvdb::CoordBBox box(openvdb::Coord(0), openvdb::Coord(n - 1));
  for (auto it = grid.cbeginValueOn(); it; ++it) {
    if (!keep(*it)) continue;
    openvdb::CoordBBox b = it.getBoundingBox();
    b.intersect(box);
    if (b.empty()) continue;
    for (int k = b.min().z(); k <= b.max().z(); ++k)
      for (int j = b.min().y(); j <= b.max().y(); ++j)
        for (int i = b.min().x(); i <= b.max().x(); ++i) out.add(i, j, k);
  }
}

/// The float grid `name` of `path`, or a status with the message.
int readFloatGrid(const char* path, const char* name, openvdb::FloatGrid::Ptr& grid, char* error,
                  std::size_t errorSize) {
  initialize();
  openvdb::GridBase::Ptr base;
  try {
    openvdb::io::File vdb(path);
    vdb.open(false);
    if (!vdb.hasGrid(name)) {
      vdb.close();
      return failWith(GRIDIFS_VDB_NO_SUCH_GRID, "no such grid", error, errorSize);
    }
    base = vdb.readGrid(name);
    vdb.close();
  } catch (const openvdb::Exception& e) {
    return failWith(GRIDIFS_VDB_UNREADABLE, e.what(), error, errorSize);
  }
  grid = openvdb::gridPtrCast<openvdb::FloatGrid>(base);
  if (!grid) return failWith(GRIDIFS_VDB_NOT_FLOAT_GRID, "not a float grid", error, errorSize);
  return GRIDIFS_VDB_OK;
}

}  // namespace

extern "C" __attribute__((visibility("default"))) int gridifs_vdb_io_abi_version(void) {
  return GRIDIFS_VDB_IO_ABI_VERSION;
}

extern "C" __attribute__((visibility("default"))) int gridifs_vdb_io_write_volume(const char* path, int n,
                                                                                  const float* density,
                                                                                  const float* color, char* error,
                                                                                  size_t errorSize) {
  return guarded(error, errorSize, [&] {
    initialize();
    const auto xform = latticeTransform(n);
    openvdb::FloatGrid::Ptr densityGrid = openvdb::FloatGrid::create(0.0f);
    densityGrid->setName("density");
    densityGrid->setGridClass(openvdb::GRID_FOG_VOLUME);
    densityGrid->setTransform(xform);
    openvdb::Vec3SGrid::Ptr colorGrid;
    if (color) {
      colorGrid = openvdb::Vec3SGrid::create(openvdb::Vec3s(0.0f));
      colorGrid->setName("color");
      colorGrid->setTransform(xform->copy());
    }
    auto densityAccess = densityGrid->getAccessor();
    const std::size_t un = std::size_t(n);
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const std::size_t v = std::size_t(i) + un * (std::size_t(j) + un * std::size_t(k));
          const float d = density[v];
          if (d <= 0.0f) continue;
          densityAccess.setValue(openvdb::Coord(i, j, k), d);
          if (colorGrid)
            colorGrid->tree().setValue(openvdb::Coord(i, j, k),
                                       openvdb::Vec3s(color[3 * v], color[3 * v + 1], color[3 * v + 2]));
        }
    openvdb::GridPtrVec grids{densityGrid};
    if (colorGrid) grids.push_back(colorGrid);
    openvdb::io::File vdb(path);
    vdb.write(grids);
    vdb.close();
    replaceRandomUuid(path);
    return int(GRIDIFS_VDB_OK);
  });
}

extern "C" __attribute__((visibility("default"))) int gridifs_vdb_io_mesh_voxels(
    int n, const float* points, size_t pointCount, const uint32_t* triangles, size_t triangleCount,
    const uint32_t* quads, size_t quadCount, int solid, float halfDiagonal, GridifsVdbVoxels emit, void* context,
    char* error, size_t errorSize) {
  return guarded(error, errorSize, [&] {
    initialize();
    std::vector<openvdb::Vec3s> vertices(pointCount);
    for (std::size_t p = 0; p < pointCount; ++p)
      vertices[p] = openvdb::Vec3s(points[3 * p], points[3 * p + 1], points[3 * p + 2]);
    std::vector<openvdb::Vec3I> tris(triangleCount);
    for (std::size_t t = 0; t < triangleCount; ++t)
      tris[t] = openvdb::Vec3I(triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]);
    std::vector<openvdb::Vec4I> quadList(quadCount);
    for (std::size_t q = 0; q < quadCount; ++q)
      quadList[q] = openvdb::Vec4I(quads[4 * q], quads[4 * q + 1], quads[4 * q + 2], quads[4 * q + 3]);
    const openvdb::math::Transform::Ptr xform = latticeTransform(n);
    VoxelSink out(emit, context);
    if (solid) {
      const auto sdf = openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(*xform, vertices, tris, quadList, 2.0f);
      const auto interior = openvdb::tools::sdfInteriorMask(*sdf);
      collectActive(
          *interior, n, [](bool on) { return on; }, out);
    } else {
      const auto udf =
          openvdb::tools::meshToUnsignedDistanceField<openvdb::FloatGrid>(*xform, vertices, tris, quadList, 2.0f);
      collectActive(
          *udf, n, [&](float d) { return d <= halfDiagonal; }, out);
    }
    out.flush();
    return int(GRIDIFS_VDB_OK);
  });
}

extern "C" __attribute__((visibility("default"))) int gridifs_vdb_io_grid_voxels(const char* path, const char* name,
                                                                                 int n, float threshold,
                                                                                 GridifsVdbVoxels emit, void* context,
                                                                                 char* error, size_t errorSize) {
  return guarded(error, errorSize, [&] {
    openvdb::FloatGrid::Ptr grid;
    if (const int status = readFloatGrid(path, name, grid, error, errorSize); status != GRIDIFS_VDB_OK) return status;
    // Visit the source's active values, and sample the grid at the centres of the lattice voxels
    // they cover.
    const openvdb::CoordBBox lattBox(openvdb::Coord(0), openvdb::Coord(n - 1));
    const auto latt = latticeTransform(n);
    openvdb::tools::GridSampler<openvdb::FloatGrid, openvdb::tools::BoxSampler> sampler(*grid);
    VoxelSink out(emit, context);
    for (auto it = grid->cbeginValueOn(); it; ++it) {
      const openvdb::CoordBBox b = it.getBoundingBox();
      const openvdb::BBoxd world =
          grid->transform().indexToWorld(openvdb::BBoxd(b.min().asVec3d() - 0.5, b.max().asVec3d() + 0.5));
      const openvdb::BBoxd idx = latt->worldToIndex(world);
      openvdb::CoordBBox cover(openvdb::Coord::floor(idx.min()), openvdb::Coord::ceil(idx.max()));
      cover.intersect(lattBox);
      if (cover.empty()) continue;
      for (int k = cover.min().z(); k <= cover.max().z(); ++k)
        for (int j = cover.min().y(); j <= cover.max().y(); ++j)
          for (int i = cover.min().x(); i <= cover.max().x(); ++i) {
            // The voxel's centre, as GridIFS's lattice places it.
            const openvdb::Vec3d c(-1.0 + (2.0 * i + 1.0) / n, -1.0 + (2.0 * j + 1.0) / n, -1.0 + (2.0 * k + 1.0) / n);
            if (sampler.wsSample(c) >= threshold) out.add(i, j, k);
          }
    }
    out.flush();
    return int(GRIDIFS_VDB_OK);
  });
}

extern "C" __attribute__((visibility("default"))) int gridifs_vdb_io_grid_mesh(const char* path, const char* name,
                                                                               float threshold, GridifsVdbMesh emit,
                                                                               void* context, char* error,
                                                                               size_t errorSize) {
  return guarded(error, errorSize, [&] {
    openvdb::FloatGrid::Ptr grid;
    if (const int status = readFloatGrid(path, name, grid, error, errorSize); status != GRIDIFS_VDB_OK) return status;
    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
    std::vector<openvdb::Vec4I> quads;
    openvdb::tools::volumeToMesh(*grid, points, triangles, quads, double(threshold));
    std::vector<float> xyz;
    xyz.reserve(3 * points.size());
    for (const auto& p : points) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
    std::vector<std::uint32_t> tris, quadList;
    tris.reserve(3 * triangles.size());
    for (const auto& t : triangles) tris.insert(tris.end(), {t[0], t[1], t[2]});
    quadList.reserve(4 * quads.size());
    for (const auto& q : quads) quadList.insert(quadList.end(), {q[0], q[1], q[2], q[3]});
    emit(context, xyz.data(), points.size(), tris.data(), triangles.size(), quadList.data(), quads.size());
    return int(GRIDIFS_VDB_OK);
  });
}
