#include "io/flame_import.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <random>
#include <set>

#include "freeform/transition_matrix.h"
#include "io/flame_camera.h"
#include "io/project_io.h"
#include "model/stack_evaluator.h"

namespace gridifs {
namespace {

constexpr double kPi = 3.14159265358979323846;
/// Node targets beyond this are clamped: still far outside X (the chain restarts there, as
/// flam3 drops bad points) but finite, which grids require.
constexpr double kNodeClamp = 1e4;

double clampCoordinate(double v) { return std::isfinite(v) ? std::clamp(v, -kNodeClamp, kNodeClamp) : kNodeClamp; }

/// Whether some xform of the genome leaves the plane z = 0 (z variations, 3D affine parts).
bool leavesThePlane(const FlameGenome& genome) {
  for (const FlameXform& x : genome.xforms)
    if (x.isThreeD()) return true;
  return genome.finalXform && genome.finalXform->isThreeD();
}

/// A genome's point in X = (x, y, −z), the space of a natively imported genome (io/flame_camera.h),
/// and back: the same flip.
FlamePoint flipZ(FlamePoint p) { return {p.x, p.y, -p.z}; }

/// An xform as a function with native variations: a 2×2×2 grid whose corners are the pre-affine
/// map's images (it extrapolates, so it is that map everywhere), the xform's variations and
/// parameters by name, and its post map. A planar genome's grid sends z to the plane z = 0. A
/// genome that leaves the plane keeps its 3D affine parts, in X = (x, y, −z): each map becomes
/// S∘f∘S (S the flip of z), which leaves the grid and post maps affine and turns the sign of the
/// two variations whose z does not scale with the point's (ztranslate, zcone). Its planar
/// variations see only x and y, as in the genome, and GridIFS's carry w·z: where the genome drops
/// z (no preserve_z) a zscale of −Σ w over them takes it away again.
Function nativeXform(const FlameXform& x, const std::string& name, bool leavesPlane) {
  Function fn;
  fn.name = name;
  fn.resolution = {2, 2, 2};
  fn.weight = x.weight;
  fn.palette_index = x.color;
  fn.color_speed = x.color_speed;
  NodesOp nodes;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        const Vec3 u(-1.0 + 2.0 * i, -1.0 + 2.0 * j, -1.0 + 2.0 * k);
        const FlamePoint q = leavesPlane ? flipZ(x.preAffine(flipZ({u.x, u.y, u.z}))) : x.coefs.apply({u.x, u.y, 0.0});
        nodes.moves.push_back({{i, j, k}, Vec3(q.x, q.y, leavesPlane ? q.z : 0.0) - u});
      }
  fn.ops.push_back(Operation{nodes, Center{}, Selection{}, false});
  double planarWeight = 0.0;
  for (const auto& [variation, weight] : x.variations) {
    fn.variations[variation] += leavesPlane && flipsSignWithZ(variation) ? -weight : weight;
    // A pre-variation (pre_blur) moves the point and adds nothing to the sum, z included.
    const FlameVariation* known = findFlameVariation(variation);
    if (!isGenomeZVariation(variation) && !(known && known->pre)) planarWeight += weight;
  }
  if (leavesPlane && !x.preserveZ && planarWeight != 0.0) fn.variations["zscale"] -= planarWeight;
  for (const auto& [attribute, value] : x.params) fn.variation_params[attribute] = value;
  if (leavesPlane) {
    // The post map's matrix in X: S·M·S and S·t.
    const FlamePoint origin = x.postAffine({}), t = flipZ(origin);
    const double sign[3] = {1.0, 1.0, -1.0};
    std::array<std::array<double, 4>, 3> m{};
    bool identity = true;
    for (int c = 0; c < 3; ++c) {
      FlamePoint e{};
      (c == 0 ? e.x : c == 1 ? e.y : e.z) = 1.0;
      const FlamePoint image = x.postAffine(e);
      const double column[3] = {image.x - origin.x, image.y - origin.y, image.z - origin.z};
      for (int r = 0; r < 3; ++r) {
        m[std::size_t(r)][std::size_t(c)] = sign[r] * sign[c] * column[r];
        identity &= m[std::size_t(r)][std::size_t(c)] == (r == c ? 1.0 : 0.0);
      }
    }
    m[0][3] = t.x;
    m[1][3] = t.y;
    m[2][3] = t.z;
    identity &= t.x == 0.0 && t.y == 0.0 && t.z == 0.0;
    if (!identity) fn.post = PostTransform{{}, m};
  } else if (!x.post.isIdentity()) {
    const FlameAffine& m = x.post;
    fn.post = PostTransform{
        {}, std::array<std::array<double, 4>, 3>{{{m.a, m.b, 0.0, m.c}, {m.d, m.e, 0.0, m.f}, {0.0, 0.0, 1.0, 0.0}}}};
  }
  return fn;
}

/// The xform without its random variations: a grid samples a map, and random ones have none.
FlameXform withoutRandomVariations(const FlameXform& x, std::set<std::string>& dropped) {
  FlameXform out = x;
  out.variations.clear();
  for (const auto& v : x.variations)
    if (isRandomFlameVariation(v.first))
      dropped.insert(v.first);
    else
      out.variations.push_back(v);
  return out;
}

/// A robust extent of the attractor: a short chaos game in double precision with the genome's
/// weights and chaos rows; returns the 0.5 % and 99.5 % quantiles of x, y and z in the flame
/// camera's space (`frame`'s camera; 2D genomes: the flame plane, z = 0).
std::array<double, 6> attractorExtent(const FlameGenome& g, const FlameFrame& frame) {
  const std::size_t n = g.xforms.size();
  std::vector<std::vector<double>> rows(n, std::vector<double>(n, 0.0));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      rows[i][j] = g.xforms[j].weight * (j < g.xforms[i].chaos.size() ? g.xforms[i].chaos[j] : 1.0);
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<double> xs, ys, zs;
  constexpr int kIterations = 120000, kSkip = 20;
  auto start = [&] {
    const double x = unit(rng), y = unit(rng);
    return FlamePoint{x, y, g.threeD ? unit(rng) : 0.0};
  };
  FlamePoint p = start();
  std::size_t last = n;  // none
  int skip = kSkip;
  for (int it = 0; it < kIterations; ++it) {
    const std::vector<double>* weights = nullptr;
    std::vector<double> base;
    if (last < n)
      weights = &rows[last];
    else {
      for (const auto& x : g.xforms) base.push_back(x.weight);
      weights = &base;
    }
    double total = 0.0;
    for (double w : *weights) total += w;
    if (!(total > 0.0)) {
      last = n;
      continue;
    }
    double r = (unit(rng) + 1.0) * 0.5 * total;
    std::size_t k = 0;
    while (k + 1 < n && r >= (*weights)[k]) r -= (*weights)[k++];
    const FlamePoint q = g.xforms[k].apply(p);
    if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z) || std::fabs(q.x) > 1e10 ||
        std::fabs(q.y) > 1e10 || std::fabs(q.z) > 1e10) {
      p = start();
      last = n;
      skip = kSkip;
      continue;
    }
    p = q;
    last = k;
    if (skip > 0) {
      --skip;
      continue;
    }
    const FlamePoint c = frame.toCamera(p);
    xs.push_back(c.x);
    ys.push_back(c.y);
    zs.push_back(c.z);
  }
  if (xs.size() < 100) return {g.centerX, g.centerX, g.centerY, g.centerY, 0.0, 0.0};
  auto quantile = [](std::vector<double>& v, double q) {
    const std::size_t k = std::size_t(q * double(v.size() - 1));
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
    return v[k];
  };
  return {quantile(xs, 0.005), quantile(xs, 0.995), quantile(ys, 0.005),
          quantile(ys, 0.995), quantile(zs, 0.005), quantile(zs, 0.995)};
}

FlameFrame chooseFrame(const FlameGenome& g, std::vector<std::string>& warnings) {
  FlameFrame frame;
  frame.rotate = g.rotate;
  frame.threeD = g.threeD;
  if (g.threeD) {
    frame.pitch = g.camPitch;
    frame.yaw = g.camYaw;
    frame.zpos = g.camZpos;
  }
  if (g.frameHint) {
    frame.centerX = (*g.frameHint)[0];
    frame.centerY = (*g.frameHint)[1];
    frame.scale = (*g.frameHint)[2];
    return frame;
  }
  frame.centerX = g.centerX;
  frame.centerY = g.centerY;
  const double ppu = g.pixelsPerUnit();
  const double viewHalf = 0.5 * double(std::max(g.width, g.height)) / ppu;
  // The attractor's extent around the centre, in the view's (rotated) axes.
  const auto e = attractorExtent(g, frame);
  double half = viewHalf;
  const double t = g.rotate * kPi / 180.0;
  for (double x : {e[0], e[1]})
    for (double y : {e[2], e[3]}) {
      // Rotated offsets from the centre in the camera's image plane.
      const double dx = x - g.centerX, dy = y - g.centerY;
      const double rx = std::cos(t) * dx - std::sin(t) * dy, ry = std::sin(t) * dx + std::cos(t) * dy;
      half = std::max({half, std::fabs(rx), std::fabs(ry)});
    }
  if (g.threeD) {
    frame.zCenter = 0.5 * (e[4] + e[5]);
    half = std::max(half, 0.5 * (e[5] - e[4]));
  }
  half *= 1.05;  // a margin: the quantiles leave the outermost points out
  const double cap = 4.0 * viewHalf;
  if (half > cap) {
    warnings.push_back("the attractor reaches far beyond the view; points more than four view sizes away are clamped");
    half = cap;
  }
  frame.scale = 1.0 / half;
  return frame;
}

/// Grid nodes per axis. 2D genomes: R×R×2 (z collapsed). 3D genomes put the flame camera's depth
/// on X's y: when the camera is not turned (pitch and yaw 0) that is the flame's z, and an xform
/// whose variations see an x and y that do not depend on z is affine in z for fixed x and y, so
/// two layers along y sample it exactly; otherwise (a turned camera, or z mixed into x or y)
/// depth needs clamp(R/2, 2, 32) layers. Affine xforms are exact with 2×2×2.
Index3 gridResolution(const FlameXform& x, const FlameFrame& frame, int resolution) {
  if (x.isAffine()) return {2, 2, 2};
  if (!frame.threeD) return {resolution, resolution, 2};
  const bool turned = frame.pitch != 0.0 || frame.yaw != 0.0;
  const int depth = !turned && !x.xyDependsOnZ() ? 2 : std::clamp(resolution / 2, 2, 32);
  return {resolution, depth, resolution};
}

/// The map in X; 2D genomes keep z at 0.
FlamePoint mapInX(const FlameXform& x, const FlameFrame& frame, const Vec3& u) {
  const FlamePoint p = frame.fromX({u.x, u.y, frame.threeD ? u.z : 0.0});
  FlamePoint q = frame.toX(x.apply(frame.threeD ? p : FlamePoint{p.x, p.y, 0.0}));
  if (!frame.threeD) q.z = 0.0;
  return q;
}

Function sampleXform(const FlameXform& x, const FlameFrame& frame, int resolution, const std::string& name) {
  Function fn;
  fn.name = name;
  const Index3 n = gridResolution(x, frame, resolution);
  fn.resolution = n;
  fn.weight = x.weight;
  fn.palette_index = x.color;
  fn.color_speed = x.color_speed;
  NodesOp nodes;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        const Vec3 u(-1.0 + 2.0 * i / (n[0] - 1), -1.0 + 2.0 * j / (n[1] - 1), -1.0 + 2.0 * k / (n[2] - 1));
        const FlamePoint q = mapInX(x, frame, u);
        const Vec3 target(clampCoordinate(q.x), clampCoordinate(q.y), frame.threeD ? clampCoordinate(q.z) : 0.0);
        nodes.moves.push_back({{i, j, k}, target - u});
      }
  fn.ops.push_back(Operation{nodes, Center{}, Selection{}, false});
  return fn;
}

}  // namespace

FlamePoint FlameFrame::toCamera(FlamePoint p) const {
  if (!threeD) return p;
  const auto m = flameCameraRows(pitch, yaw);
  const double v[3] = {p.x, p.y, p.z - zpos};
  FlamePoint c;
  c.x = m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2];
  c.y = m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2];
  c.z = m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2];
  return c;
}

FlamePoint FlameFrame::fromCamera(FlamePoint c) const {
  if (!threeD) return c;
  const auto m = flameCameraRows(pitch, yaw);  // orthonormal: the inverse is the transpose
  return {m[0][0] * c.x + m[1][0] * c.y + m[2][0] * c.z, m[0][1] * c.x + m[1][1] * c.y + m[2][1] * c.z,
          m[0][2] * c.x + m[1][2] * c.y + m[2][2] * c.z + zpos};
}

FlamePoint FlameFrame::toX(FlamePoint p) const {
  const FlamePoint q = toCamera(p);
  const double t = rotate * kPi / 180.0, c = std::cos(t), s = std::sin(t);
  const double dx = q.x - centerX, dy = q.y - centerY;
  // flam3 turns the picture by `rotate` degrees about the centre; in its plane (rows going
  // down with y) the view axes are the plane's axes turned by +rotate (checked against flam3-render).
  const double rx = c * dx - s * dy, ry = s * dx + c * dy;
  if (threeD) return {scale * rx, -scale * (q.z - zCenter), -scale * ry};
  return {scale * rx, -scale * ry, scale * q.z};
}

FlamePoint FlameFrame::fromX(FlamePoint x) const {
  const double t = rotate * kPi / 180.0, c = std::cos(t), s = std::sin(t);
  const double rx = x.x / scale, ry = (threeD ? -x.z : -x.y) / scale;
  const double depth = threeD ? zCenter - x.y / scale : x.z / scale;
  return fromCamera({centerX + c * rx + s * ry, centerY - s * rx + c * ry, depth});
}

FlameFileImport importFlameFile(const std::filesystem::path& file, const std::string& genome,
                                const std::filesystem::path& paletteFolder) {
  namespace fs = std::filesystem;
  const std::vector<FlameGenome> genomes = loadFlameFile(file);
  const FlameGenome& chosen = selectGenome(genomes, genome);
  const std::size_t index = std::size_t(&chosen - genomes.data());
  std::string stem;
  for (char c : chosen.name.empty() ? file.stem().string() + "-" + std::to_string(index) : chosen.name)
    stem += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
  const fs::path paletteFile = fs::absolute(paletteFolder / (stem + ".palette.json"));
  FlameImportOptions options;
  options.inlinePaletteReference = "file:" + paletteFile.string();
  FlameImport imported = importFlameGenome(chosen, options);
  if (imported.palette) {
    std::error_code ec;
    fs::create_directories(paletteFolder, ec);
    const fs::path temporary = fs::path(paletteFile).concat(".tmp");
    {
      std::ofstream out(temporary, std::ios::binary);
      out << serializePaletteJson(*imported.palette);
      if (!out.flush()) throw IoError("cannot write the palette " + paletteFile.string());
    }
    fs::rename(temporary, paletteFile, ec);
    if (ec) throw IoError("cannot write the palette " + paletteFile.string() + ": " + ec.message());
  }
  FlameFileImport out{std::move(imported.project), std::move(imported.warnings), {}};
  out.description = (chosen.name.empty() ? file.filename().string() : chosen.name) + " (genome " +
                    std::to_string(index + 1) + " of " + std::to_string(genomes.size()) + ")";
  return out;
}

double flameSamplingError(const Function& function, const FlameXform& map, const FlameFrame& frame) {
  const auto grid = evaluateFunctionAt(function, "");
  const Index3 n = function.resolution;
  // 2D genomes: the z = 0 plane. 3D: every cell's centre.
  const int layers = frame.threeD ? n[2] - 1 : 1;
  double worst = 0.0;
  for (int k = 0; k < layers; ++k)
    for (int j = 0; j + 1 < n[1]; ++j)
      for (int i = 0; i + 1 < n[0]; ++i) {
        const Vec3 u(-1.0 + (2.0 * i + 1.0) / (n[0] - 1), -1.0 + (2.0 * j + 1.0) / (n[1] - 1),
                     frame.threeD ? -1.0 + (2.0 * k + 1.0) / (n[2] - 1) : 0.0);
        const FlamePoint q = mapInX(map, frame, u);
        if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z) || std::fabs(q.x) > kNodeClamp ||
            std::fabs(q.y) > kNodeClamp || std::fabs(q.z) > kNodeClamp)
          continue;
        const Vec3 g = grid->evaluate(u);
        worst = std::max(worst, std::hypot(g.x - q.x, g.y - q.y, g.z - q.z));
      }
  return worst;
}

namespace {

/// The camera of a natively imported genome: X holds the flame's own plane. A flat genome's
/// orthographic camera looks at z = 0 from below (pitch -90°), where x runs right and y down as in
/// flam3's image; yaw -90° - rotate turns the view as flam3's `rotate` does (points plotted at
/// R(rotate)·(p - centre)). A 3D camera (pitch, yaw, perspective) becomes the project camera that
/// sees the same picture (io/flame_camera.h). flam3 counts density per unit of its plane, which
/// is X's unit here.
void frameNatively(const FlameGenome& genome, Camera& cam, FlameSettings& flame) {
  flame.density_unit = 1.0;
  FlameCamera f;
  f.centerX = genome.centerX;
  f.centerY = genome.centerY;
  f.pixelsPerUnit = genome.pixelsPerUnit();
  f.rotate = genome.rotate;
  f.pitch = genome.camPitch;
  f.yaw = genome.camYaw;
  f.perspective = genome.camPerspective;
  f.zpos = genome.camZpos;
  if (f.threeD() || leavesThePlane(genome)) {
    // How far the attractor reaches from the camera's pivot, for an orthographic eye to stand beyond
    // (a genome that leaves the plane, seen flat, has depth too).
    const auto e = attractorExtent(genome, FlameFrame{});
    double reach = 0.0;
    for (double x : {e[0], e[1]})
      for (double y : {e[2], e[3]})
        for (double z : {e[4], e[5]}) reach = std::max(reach, std::hypot(x, y, z - f.zpos));
    cam = cameraFromFlame(f, genome.height, reach);
    return;
  }
  cam.projection = CameraProjection::Orthographic;
  cam.pitch = -90.0;
  cam.yaw = -90.0 - genome.rotate;
  // A flat camera keeps the plane z = cam_zpos sharp under cam_dof (X's z is the flame's −z).
  cam.target =
      Vec3(genome.centerX, genome.centerY, genome.camDof != 0.0 && genome.camZpos != 0.0 ? -genome.camZpos : 0.0);
  const double halfH = 0.5 * genome.height / genome.pixelsPerUnit();
  cam.fov = 2.0 * std::atan(0.5) * 180.0 / kPi;  // 53.13°: halfH = distance / 2
  cam.distance = 2.0 * halfH;
  if (!(cam.distance >= 1e-3 && cam.distance <= 1e4))
    throw FlameError("the genome's view is too small or too large to frame");
}

/// The camera of a sampled import: the frame's view of X.
void frameSampled(const FlameGenome& genome, FlameImport& out, Camera& cam) {
  // The view: a camera looking down −z (image x = X's x, image up = X's +y).
  cam.projection = CameraProjection::Orthographic;
  cam.yaw = -90.0;
  cam.pitch = 90.0;
  cam.target = Vec3(0.0);
  const double halfH = 0.5 * genome.height / genome.pixelsPerUnit() * out.frame.scale;
  cam.fov = 2.0 * std::atan(0.5) * 180.0 / kPi;  // 53.13°: halfH = distance / 2
  cam.distance = 2.0 * halfH;
  if (genome.threeD) {
    // Level with the frame's horizon, looking along +y (image x = X's x, image up = X's +z):
    // exactly the flame camera's view, and the orbit camera turns about the picture's up axis.
    cam.pitch = 0.0;
    if (genome.camPerspective > 0.0) {
      // The flame's eye sits on the camera's axis at 1 / perspective in front of the plane
      // c_z = 0, which it shows at the view's scale (zr = 1 − perspective · c_z).
      cam.projection = CameraProjection::Perspective;
      cam.distance = out.frame.scale / genome.camPerspective;
      cam.target = Vec3(0.0, out.frame.scale * out.frame.zCenter, 0.0);
      // The eye looks at the flame's plane z = 0; an attractor thousands of view sizes away from
      // that plane in depth has no view a project camera can hold.
      if (!(std::fabs(cam.target.y) <= 1e4))
        throw FlameError("the attractor lies too far in front of or behind the flame's camera plane to frame");
      if (genome.centerX != 0.0 || genome.centerY != 0.0)
        out.warnings.push_back(
            "the flame's perspective eye is off the view's centre; GridIFS's camera looks straight at the centre, "
            "so parallax differs slightly");
      if (cam.distance - cam.target.y < 1.0)
        out.warnings.push_back("the flame's eye is inside the attractor's domain; points behind it are not drawn");
    } else {
      if (genome.camPerspective < 0.0)
        out.warnings.push_back("a negative cam_perspective is not supported; the view is orthographic");
      cam.distance = std::max(cam.distance, 4.0);  // the eye above all of X
    }
    cam.fov = 2.0 * std::atan(halfH / cam.distance) * 180.0 / kPi;
  }
  if (!(cam.distance >= 1e-3 && cam.distance <= 1e4) || !(cam.fov >= 1.0 && cam.fov <= 170.0))
    throw FlameError("the genome's view is too small or too large to frame");
}

std::string whyNotNative(const FlameGenome& genome) {
  if (genome.frameHint) return "it is GridIFS's own grid export";
  if (!leavesThePlane(genome)) return {};
  // GridIFS's spherical, bubble and eyefish are 3D (they see z); the genome's see the plane. A
  // dependent variation reads the xy pre-affine coefficients, which GridIFS takes from the whole
  // map, z parts included.
  std::vector<const FlameXform*> all;
  for (const FlameXform& x : genome.xforms) all.push_back(&x);
  if (genome.finalXform) all.push_back(&*genome.finalXform);
  for (const FlameXform* x : all)
    for (const auto& v : x->variations) {
      if (!isGenomeZVariation(v.first) && flameVariationWritesZ(v.first))
        return "its " + v.first + " sees the plane, GridIFS's sees z too";
      const FlameVariation* variation = findFlameVariation(v.first);
      if ((x->yz || x->zx) && variation && variation->dependent)
        return "its " + v.first + " reads coefficients that its 3D affine parts change";
    }
  return {};
}

}  // namespace

bool isNativeGenome(const FlameGenome& genome) { return whyNotNative(genome).empty(); }

FlameImport importFlameGenome(const FlameGenome& genome, const FlameImportOptions& options) {
  if (options.resolution < 2 || options.resolution > limits::kMaxResolution)
    throw FlameError("the resolution must be between 2 and " + std::to_string(limits::kMaxResolution));
  FlameImport out;
  out.warnings = genome.warnings;
  const bool native = isNativeGenome(genome) && !options.sampleOntoGrids;
  const bool leavesPlane = leavesThePlane(genome);
  if (!native) out.frame = chooseFrame(genome, out.warnings);
  Project& p = out.project;

  // Palette: the genome's own colors, else flam3's collection by number, turned by `hue` as
  // flam3 does when it takes a palette from its collection (flam3 leaves inline colors as they are).
  // The hue stays a setting (render.flame.hue), so the artist can keep turning it.
  FlameSettings& fl = p.render.flame;
  std::optional<Palette> palette = genome.palette;
  const double hue = genome.hue - std::floor(genome.hue);
  if (genome.palette) {
    fl.palette = options.inlinePaletteReference;
  } else if (genome.paletteNumber >= 0) {
    fl.palette = "flam3:" + std::to_string(genome.paletteNumber);
    fl.hue = hue;
    try {
      palette = resolvePalette(fl.palette);
      if (hue != 0.0) palette = rotatePaletteHue(*palette, hue);
    } catch (const PaletteError&) {
      out.warnings.push_back("palette " + fl.palette + " is not installed here; function colors are white");
      palette.reset();
    }
  } else {
    out.warnings.push_back("the genome names no palette; using the default palette");
    try {
      palette = resolvePalette(fl.palette);
    } catch (const PaletteError&) {
      out.warnings.push_back("palette " + fl.palette + " is not installed here; function colors are white");
    }
  }
  if (fl.palette == options.inlinePaletteReference) {
    if (options.inlinePaletteReference.empty())
      throw FlameError("the genome has its own palette but there is no place to save it");
    out.palette = palette;
  }

  // Genomes keep their variations natively, in the flame's own coordinates (X = (x, y, −z) for
  // those that leave the plane), whatever their camera; GridIFS's own grid exports
  // (gridifs_frame), --grids, and the few 3D genomes GridIFS's variations cannot follow
  // (whyNotNative) are sampled onto grids.
  if (!native && !options.sampleOntoGrids && !genome.frameHint)
    out.warnings.push_back("the genome's maps are sampled onto grids: " + whyNotNative(genome));
  std::set<std::string> dropped;
  auto convert = [&](const FlameXform& x, const std::string& name) {
    if (native) return nativeXform(x, name, leavesPlane);
    const FlameXform sampled = withoutRandomVariations(x, dropped);
    Function fn = sampleXform(sampled, out.frame, options.resolution, name);
    fn.sampling_error = flameSamplingError(fn, sampled, out.frame);
    return fn;
  };
  for (std::size_t i = 0; i < genome.xforms.size(); ++i) {
    const FlameXform& x = genome.xforms[i];
    Function fn = convert(x, x.name.empty() ? "x" + std::to_string(i + 1) : x.name);
    if (palette) {
      const Rgb c = palette->lookup(x.color);
      fn.color = Vec3(c.r, c.g, c.b);
    }
    p.functions.push_back(std::move(fn));
  }
  if (genome.finalXform) {
    Function fn = convert(*genome.finalXform, "final");
    fn.weight = 1.0;
    if (palette) {
      const Rgb c = palette->lookup(genome.finalXform->color);
      fn.color = Vec3(c.r, c.g, c.b);
    }
    p.final_function = std::move(fn);
  }
  if (!dropped.empty()) {
    std::string list;
    for (const auto& n : dropped) list += (list.empty() ? "" : ", ") + n;
    out.warnings.push_back("the random variations " + list +
                           " of this genome were left out (its maps are sampled onto grids)");
  }
  // chaos → transitions (flam3's xaos: row i weights the xform that follows xform i).
  bool restricted = false;
  for (const FlameXform& x : genome.xforms)
    for (double c : x.chaos) restricted |= c != 1.0;
  if (restricted) {
    const std::size_t n = genome.xforms.size();
    p.transitions.assign(n, std::vector<double>(n, 1.0));
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n && j < genome.xforms[i].chaos.size(); ++j)
        p.transitions[i][j] = genome.xforms[i].chaos[j];
    for (std::size_t i = 0; i < n; ++i) {
      bool any = false;
      for (std::size_t j = 0; j < n; ++j) any |= p.transitions[i][j] > 0.0 && genome.xforms[j].weight > 0.0;
      if (!any) throw FlameError("xform " + std::to_string(i) + "'s chaos row allows no xform with a positive weight");
    }
  }

  if (!native) frameSampled(genome, out, p.camera);

  RenderSettings& r = p.render;
  r.width = genome.width;
  r.height = genome.height;
  r.samples = std::int64_t(std::min(1e11, std::max(1.0, genome.quality * genome.width * genome.height)));
  r.seed = 1;
  r.skip = 20;
  r.background = Vec3(genome.background[0], genome.background[1], genome.background[2]);
  r.depth_cue = 0.0;
  r.mode = DisplayMode::Flame;
  auto clamped = [&](double v, double lo, double hi, const char* what) {
    if (v < lo || v > hi) {
      out.warnings.push_back(std::string("the genome's ") + what + " was clamped into the supported range");
      return std::clamp(v, lo, hi);
    }
    return v;
  };
  fl.brightness = clamped(genome.brightness, 0.0, 1e4, "brightness");
  fl.gamma = clamped(genome.gamma, 0.05, 100.0, "gamma");
  fl.gamma_threshold = clamped(genome.gamma_threshold, 0.0, 1.0, "gamma_threshold");
  fl.vibrancy = clamped(genome.vibrancy, 0.0, 1.0, "vibrancy");
  fl.highlight_power = clamped(genome.highlight_power, -1.0, 100.0, "highlight_power");
  fl.supersample = int(clamped(genome.supersample, 1, 8, "supersample"));
  fl.estimator_radius = clamped(genome.estimator_radius, 0.0, 64.0, "estimator_radius");
  fl.estimator_minimum = clamped(genome.estimator_minimum, 0.0, fl.estimator_radius, "estimator_minimum");
  fl.estimator_curve = clamped(genome.estimator_curve, 0.05, 10.0, "estimator_curve");
  fl.filter_radius = clamped(genome.filter, 0.0, 10.0, "filter");
  fl.density_unit = out.frame.scale;  // keeps flam3's exposure (hits per pixel of its plane)
  if (native) {
    frameNatively(genome, p.camera, fl);
    // The camera pivots on the flame's plane c_z = 0 (io/flame_camera.h), the plane cam_dof keeps
    // sharp; the blur's reach is a ratio of distances, the same at any scale.
    p.camera.lens_blur = std::fabs(genome.camDof);
  } else if (genome.camDof != 0.0) {
    out.warnings.push_back("the camera's cam_dof blur was left out: it needs a natively imported genome");
  }
  try {
    validateProject(p);
  } catch (const ModelError& e) {
    throw FlameError(std::string("the converted project is not valid (") + e.what() + ")");
  }
  return out;
}

}  // namespace gridifs
