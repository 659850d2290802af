#include "volume/volume_points.h"

#include "volume/set_iterates.h"

namespace gridifs {

std::shared_ptr<const CompiledIfs> compileVolumePoints(const Project& project, const DensityVolume& volume,
                                                       std::size_t points) {
  std::vector<Vec3> samples = sampleDensityVolume(volume, points, project.render.seed);
  if (samples.empty())
    throw ModelError("functions", "the volume of the median functions is empty, so there is nothing to draw");
  Function f;
  f.name = "volume";
  f.kind = FunctionKind::Condensation;
  f.set.shape = SetShape::Vdb;  // read through the sampler, as a set from a file
  f.set.path = "volume";
  Vec3 color{0.0};
  double total = 0.0;
  for (const Function& g : project.functions) {
    if (g.muted || !(g.weight > 0.0)) continue;
    color += g.weight * g.color;
    total += g.weight;
  }
  f.color = total > 0.0 ? color / total : Vec3{1.0};
  Project single;
  single.camera = project.camera;
  single.render = project.render;
  single.functions = {f};
  return compileIfs(single, [&](std::size_t) { return std::move(samples); });
}

}  // namespace gridifs
