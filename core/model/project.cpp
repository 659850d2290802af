#include "model/project.h"

#include <algorithm>
#include <cmath>
#include <variant>

namespace gridifs {

std::int64_t renderSampleCount(const RenderSettings& render) {
  if (!render.quality) return render.samples;
  // flam3's quality: samples per output pixel (supersampling adds buckets, not samples).
  const double n = *render.quality * double(render.width) * double(render.height);
  if (!(n >= 1.0)) return 1;
  return std::int64_t(std::llround(std::min(n, 1e11)));
}

Project defaultNewProject() {
  Project p;
  Function f;
  f.name = "f1";
  f.placement.scale = Vec3{0.5};
  f.color = {1.0, 0.6, 0.2};
  p.functions.push_back(f);
  return p;
}

namespace {

std::size_t approximateMemory(const Function& f) {
  std::size_t bytes = sizeof(Function) + f.name.capacity() + f.ops.capacity() * sizeof(Operation);
  for (const Operation& op : f.ops) {
    bytes += op.selection.capacity() * sizeof(SelectionBox);
    if (const auto* morph = std::get_if<MorphOp>(&op.params))
      bytes += morph->pairs.capacity() * sizeof(morph->pairs[0]);
    if (const auto* nodes = std::get_if<NodesOp>(&op.params)) bytes += nodes->moves.capacity() * sizeof(NodeMove);
    if (const auto* calc = std::get_if<CalculatorOp>(&op.params))
      bytes += calc->x.capacity() + calc->y.capacity() + calc->z.capacity();
  }
  for (const auto& row : f.matrix) bytes += sizeof(row) + row.capacity() * sizeof(double);
  return bytes;
}

}  // namespace

std::size_t approximateMemory(const Project& project) {
  std::size_t bytes = sizeof(Project) + project.render.flame.palette.capacity();
  for (const Function& f : project.functions) bytes += approximateMemory(f);
  if (project.final_function) bytes += approximateMemory(*project.final_function);
  for (const auto& row : project.transitions) bytes += sizeof(row) + row.capacity() * sizeof(double);
  for (const auto& [path, track] : project.tracks)
    bytes += 64 + path.capacity() + track.keys.capacity() * sizeof(Keyframe);  // 64: a map node
  if (project.space) bytes += project.space->control_points.capacity() * sizeof(Vec3);
  if (project.states)
    for (const auto& row : project.states->matrix)
      for (const auto& entry : row) bytes += sizeof(entry) + entry.capacity() * sizeof(std::uint32_t);
  return bytes;
}

}  // namespace gridifs
