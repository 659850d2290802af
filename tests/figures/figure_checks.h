#pragma once
// What the figures tier and scripts/figures read back from a figure's outputs: the manifest
// (docs/figures/figures.json), image coverage and pixels, VDB density, node lists. Shared by the
// test binary and the X-ray thumbnail tool so both read outputs the same way.
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <openvdb/openvdb.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace gridifs::figures {

/// One command of a figure: gridifs ARGS with {project} and {out} replaced, plus the small
/// (tests) or full (docs) size arguments.
struct Step {
  std::vector<std::string> args, small, full;
  std::string out;         // output file name (a printf pattern for frame sequences)
  std::string project;     // relative to the source root
  bool stdoutOut = false;  // the verb prints its result; `out` is where it is kept
  bool quiet = true;       // the verb takes --quiet
};

struct Figure {
  std::string id, paper, figure, shows, status, reason, thumbnail;
  std::string project;
  std::vector<Step> steps;
  std::string checkKind;  // coverage | density | nodes | mesh
  double checkMin = 0;
  bool makeable() const { return status == "made"; }
};

/// GoogleTest prints a figure by its id (not as bytes) in test lists and failures.
inline void PrintTo(const Figure& f, std::ostream* os) { *os << f.id; }

inline std::vector<std::string> strings(const nlohmann::json& j, const char* key) {
  std::vector<std::string> v;
  if (j.contains(key))
    for (const auto& s : j.at(key)) v.push_back(s.get<std::string>());
  return v;
}

inline std::vector<Figure> loadManifest(const std::filesystem::path& path) {
  std::ifstream in(path);
  const nlohmann::json doc = nlohmann::json::parse(in);
  std::vector<Figure> out;
  for (const auto& e : doc.at("figures")) {
    Figure f;
    f.id = e.at("id").get<std::string>();
    f.paper = e.at("paper").get<std::string>();
    f.figure = e.at("figure").get<std::string>();
    f.shows = e.at("shows").get<std::string>();
    f.status = e.value("status", std::string("made"));
    f.reason = e.value("reason", std::string());
    f.thumbnail = e.value("thumbnail", std::string());
    f.project = e.value("project", std::string());
    if (e.contains("steps"))
      for (const auto& s : e.at("steps")) {
        Step step;
        step.args = strings(s, "args");
        step.small = strings(s, "small");
        step.full = strings(s, "full");
        step.out = s.at("out").get<std::string>();
        step.project = s.value("project", f.project);
        step.stdoutOut = s.value("stdout", false);
        step.quiet = s.value("quiet", true) && !step.stdoutOut;
        f.steps.push_back(step);
      }
    if (e.contains("check")) {
      f.checkKind = e.at("check").at("kind").get<std::string>();
      f.checkMin = e.at("check").value("min", 0.0);
    }
    out.push_back(f);
  }
  return out;
}

/// The files a step wrote: its output, or for a printf pattern (frames) every file it names.
inline std::vector<std::filesystem::path> stepOutputs(const std::filesystem::path& dir, const std::string& out) {
  std::vector<std::filesystem::path> files;
  if (out.find('%') == std::string::npos) {
    if (std::filesystem::exists(dir / out)) files.push_back(dir / out);
    return files;
  }
  for (int f = 0; f < 10000; ++f) {
    char name[512];
    std::snprintf(name, sizeof name, out.c_str(), f);
    if (std::filesystem::exists(dir / name))
      files.push_back(dir / name);
    else if (!files.empty())
      break;
  }
  return files;
}

/// Fraction of pixels that differ from the background (the top-left pixel's colour, which every
/// figure here leaves empty) by more than 3% in any channel.
inline std::optional<double> imageCoverage(const std::filesystem::path& file) {
  OIIO::ImageBuf buf(file.string());
  if (!buf.read(0, 0, true, OIIO::TypeDesc::FLOAT)) return std::nullopt;
  const OIIO::ROI roi = buf.roi();
  const int nc = std::min(roi.nchannels(), 3);
  std::vector<float> bg(roi.nchannels());
  buf.getpixel(roi.xbegin, roi.ybegin, bg.data());
  std::vector<float> px(roi.nchannels());
  long covered = 0, total = 0;
  for (int y = roi.ybegin; y < roi.yend; ++y)
    for (int x = roi.xbegin; x < roi.xend; ++x, ++total) {
      buf.getpixel(x, y, px.data());
      for (int c = 0; c < nc; ++c)
        if (std::fabs(px[c] - bg[c]) > 0.03f) {
          ++covered;
          break;
        }
    }
  return total ? double(covered) / double(total) : 0.0;
}

/// Whether two images have the same size and the same pixels (PNG metadata may differ).
inline bool samePixels(const std::filesystem::path& a, const std::filesystem::path& b) {
  OIIO::ImageBuf ia(a.string()), ib(b.string());
  if (!ia.read(0, 0, true, OIIO::TypeDesc::FLOAT) || !ib.read(0, 0, true, OIIO::TypeDesc::FLOAT)) return false;
  if (ia.roi() != ib.roi()) return false;
  const auto cmp = OIIO::ImageBufAlgo::compare(ia, ib, 0.0f, 0.0f);
  return cmp.nfail == 0 && !cmp.error;
}

inline openvdb::FloatGrid::Ptr readDensity(const std::filesystem::path& file) {
  openvdb::initialize();
  openvdb::io::File vdb(file.string());
  vdb.open();
  openvdb::GridBase::Ptr base = vdb.readGrid("density");
  vdb.close();
  return openvdb::gridPtrCast<openvdb::FloatGrid>(base);
}

/// The density lattice's size N (voxel size 2/N over the cube [-1, 1]^3).
inline int latticeSize(const openvdb::FloatGrid& grid) { return int(std::lround(2.0 / grid.voxelSize()[0])); }

/// Fraction of the N^3 lattice with density above zero.
inline double densityCoverage(const openvdb::FloatGrid& grid) {
  long on = 0;
  for (auto it = grid.cbeginValueOn(); it; ++it)
    if (*it > 0.f) on += long(it.getVoxelCount());
  const double n = latticeSize(grid);
  return double(on) / (n * n * n);
}

/// Whether two density grids hold the same values at the same voxels (VDB files carry a UUID,
/// so their bytes differ from run to run).
inline bool sameDensity(const openvdb::FloatGrid& a, const openvdb::FloatGrid& b) {
  if (a.activeVoxelCount() != b.activeVoxelCount()) return false;
  auto acc = b.getConstAccessor();
  for (auto it = a.cbeginValueOn(); it; ++it) {
    if (!it.isVoxelValue()) {  // a tile: every voxel in it has the tile's value
      openvdb::CoordBBox box;
      it.getBoundingBox(box);
      for (auto c = box.begin(); c; ++c)
        if (acc.getValue(*c) != *it) return false;
    } else if (acc.getValue(it.getCoord()) != *it) {
      return false;
    }
  }
  return true;
}

/// Sum of density along one axis, normalised by its maximum: the paper's grey "X-ray" picture
/// of a measure attractor, `size` pixels square, rows from the top (+y or +z up).
inline std::vector<float> xray(const openvdb::FloatGrid& grid, char axis, int& size) {
  size = latticeSize(grid);
  std::vector<float> img(size_t(size) * size, 0.f);
  for (auto it = grid.cbeginValueOn(); it; ++it) {
    openvdb::CoordBBox box;
    it.getBoundingBox(box);
    for (auto c = box.begin(); c; ++c) {
      const int i = (*c)[0], j = (*c)[1], k = (*c)[2];  // lattice voxel (i, j, k)
      int u = i, v = j;
      if (axis == 'x') {
        u = j;
        v = k;
      }
      if (axis == 'y') {
        u = i;
        v = k;
      }
      if (u < 0 || v < 0 || u >= size || v >= size) continue;
      img[size_t(size - 1 - v) * size + u] += *it;
    }
  }
  const float peak = *std::max_element(img.begin(), img.end());
  if (peak > 0)
    for (float& p : img) p /= peak;
  return img;
}

/// Faces of an OBJ file (`export-mesh … -o OUT.obj`).
inline long objFaces(const std::filesystem::path& file) {
  std::ifstream in(file);
  long faces = 0;
  for (std::string line; std::getline(in, line);)
    if (line.rfind("f ", 0) == 0) ++faces;
  return faces;
}

/// `gridifs nodes` output: one "i j k x y z" line per node.
inline std::vector<std::array<double, 6>> readNodes(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::vector<std::array<double, 6>> nodes;
  std::array<double, 6> n{};
  while (in >> n[0] >> n[1] >> n[2] >> n[3] >> n[4] >> n[5]) nodes.push_back(n);
  return nodes;
}

}  // namespace gridifs::figures
