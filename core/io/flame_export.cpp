#include "io/flame_export.h"

#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

#include "io/flame_camera.h"
#include "io/flame_import.h"
#include "model/stack_evaluator.h"
#include "tone/palette.h"
#include "tone/palette_gradient.h"

namespace gridifs {
namespace {

std::string num(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", v == 0.0 ? 0.0 : v);  // no "-0"
  return buffer;
}

std::string xmlEscape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

/// The flame xform attributes of a function: its fit conjugated into flame coordinates by the
/// frame (X = scale · flip(p − centre), no rotation).
FlameAffine toFlame(const FlameAffine& g, const FlameFrame& frame) {
  // p = fromX(X); F(p) = fromX(G(toX(p))). With toX(p) = s·S·(p − c), S = diag(1, −1):
  // F(p) = S·A·S·(p − c) + c + S·t / s.
  FlameAffine f;
  f.a = g.a;
  f.b = -g.b;
  f.d = -g.d;
  f.e = g.e;
  const double tx = g.c / frame.scale, ty = -g.f / frame.scale;
  f.c = -(f.a * frame.centerX + f.b * frame.centerY) + frame.centerX + tx;
  f.f = -(f.d * frame.centerX + f.e * frame.centerY) + frame.centerY + ty;
  return f;
}

std::string coefsText(const FlameAffine& f) {
  // The file's order is a d b e c f.
  return num(f.a) + " " + num(f.d) + " " + num(f.b) + " " + num(f.e) + " " + num(f.c) + " " + num(f.f);
}

/// A function's variations and their parameters as xform attributes (linear 1 without any).
std::string variationAttributes(const Function& fn, const std::string& label, std::vector<std::string>& warnings,
                                bool leavesPlane = false) {
  std::string text;
  for (const auto& [name, weight] : fn.variations)
    text +=
        (text.empty() ? "" : " ") + name + "=\"" + num(leavesPlane && flipsSignWithZ(name) ? -weight : weight) + "\"";
  if (text.empty()) text = "linear=\"1\"";
  for (const auto& [attribute, value] : fn.variation_params) text += " " + attribute + "=\"" + num(value) + "\"";
  if (fn.post && !leavesPlane) {
    const auto m = fn.post->affine();
    if (m[0][2] != 0.0 || m[1][2] != 0.0 || m[2][0] != 0.0 || m[2][1] != 0.0 || m[2][3] != 0.0)
      warnings.push_back(label + "'s post map moves points out of the plane z = 0; its plane part is exported");
  }
  return text;
}

/// A 3D affine map y = m·x + t.
struct Affine3 {
  double m[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  double t[3] = {0, 0, 0};
};

/// From X = (x, y, −z) to the flame's space: S·A·S and S·t (S the flip of z).
Affine3 flippedZ(const Affine3& a) {
  const double sign[3] = {1.0, 1.0, -1.0};
  Affine3 f;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) f.m[r][c] = sign[r] * sign[c] * a.m[r][c];
    f.t[r] = sign[r] * a.t[r];
  }
  return f;
}

/// A function's grid as a 3D affine map, when it is one (nodes within 1e-9 of it).
std::optional<Affine3> gridAffine3(const Function& fn, const std::string& path, double time) {
  const auto grid = evaluateFunctionAt(fn, path, time);
  Affine3 a;
  const Vec3 origin = grid->evaluate(Vec3(0.0));
  for (int c = 0; c < 3; ++c) {
    Vec3 e(0.0);
    e[c] = 1.0;
    const Vec3 image = grid->evaluate(e) - origin;
    for (int r = 0; r < 3; ++r) a.m[r][c] = image[r];
  }
  for (int r = 0; r < 3; ++r) a.t[r] = origin[r];
  for (int k = 0; k < 8; ++k) {
    const Vec3 corner((k & 1) ? 1.0 : -1.0, (k & 2) ? 1.0 : -1.0, (k & 4) ? 1.0 : -1.0);
    const Vec3 got = grid->evaluate(corner);
    for (int r = 0; r < 3; ++r) {
      const double want = a.m[r][0] * corner.x + a.m[r][1] * corner.y + a.m[r][2] * corner.z + a.t[r];
      if (std::fabs(got[r] - want) > 1e-9 * (1.0 + std::fabs(want))) return std::nullopt;
    }
  }
  return a;
}

/// A 3D affine map in JWildfire's form: the xy part, then yz (y and z mixed), then zx (x and z),
/// the translations added last (io/flame_genome.h). With yz's and zx's first diagonal entries 1
/// and yz's last 1, the other entries follow from the matrix; none when its xy block (the rows
/// of x and y over x and y) is singular or the remaining pivot vanishes.
struct JWildfireAffine {
  FlameAffine xy, yz, zx;
};
std::optional<JWildfireAffine> jwildfireForm(const Affine3& a) {
  const auto& L = a.m;
  const double d = L[1][0], e = L[1][1], q = L[1][2], v = L[0][2], t = L[2][2];
  const double det = L[0][1] * d - L[0][0] * e;
  if (std::fabs(det) < 1e-12 || (d == 0.0 && e == 0.0)) return std::nullopt;
  const double w = (L[2][1] * d - L[2][0] * e) / det;
  const double k = std::fabs(d) >= std::fabs(e) ? (L[2][0] - w * L[0][0]) / d : (L[2][1] - w * L[0][1]) / e;
  double r = 0.0;
  if (k != 0.0) {
    if (std::fabs(t - w * v) < 1e-12) return std::nullopt;
    r = k / (t - w * v);
  }
  JWildfireAffine out;
  out.xy = FlameAffine{L[0][0] - v * r * d, L[0][1] - v * r * e, a.t[0], d, e, a.t[1]};
  out.yz = FlameAffine{1.0, q, 0.0, r, 1.0, a.t[2]};
  out.zx = FlameAffine{1.0, v, 0.0, w, t, 0.0};
  return out;
}

/// The attributes of a 3D map in JWildfire's form: `coefs` (or `post`) and the 3D parts that are
/// not the identity. `prefix` is "" for the pre-affine map, "post" for the post map.
std::string affine3Attributes(const JWildfireAffine& j, bool post) {
  const FlameAffine identity;
  std::string text = std::string(post ? "post" : "coefs") + "=\"" + coefsText(j.xy) + "\"";
  if (!(j.yz == identity)) text += std::string(post ? " yzPost" : " yzCoefs") + "=\"" + coefsText(j.yz) + "\"";
  if (!(j.zx == identity)) text += std::string(post ? " zxPost" : " zxCoefs") + "=\"" + coefsText(j.zx) + "\"";
  return text;
}

/// The post map's plane part as the xform's `post` attribute (none when it has no post map).
std::string postAttribute(const Function& fn) {
  if (!fn.post) return "";
  const auto m = fn.post->affine();
  const FlameAffine f{m[0][0], m[0][1], m[0][3], m[1][0], m[1][1], m[1][3]};
  return " post=\"" + coefsText(f) + "\"";
}

}  // namespace

FlameExport exportFlame(const Project& project, const std::filesystem::path& projectFolder, const std::string& name) {
  if (project.space)
    throw ModelError("space",
                     "a free-form (control point) IFS has no flame form: its maps act on barycentric "
                     "coordinates, not on the plane");
  if (project.states)
    throw ModelError("states",
                     "a flame genome has no states: its chaos matrix says which xform may follow which, and "
                     "cannot hold an IFS matrix with initial and final states");
  FlameExport out;
  // A project with flame variations lives in the flame's own coordinates (X's plane z = 0 is the
  // flame plane, seen from below: see isNativeGenome); its maps are written as they are.
  bool native = project.final_function && project.final_function->hasVariationStage();
  for (const Function& fn : project.functions) native |= fn.hasVariationStage();
  // Otherwise the flame plane is X's z = 0 plane with y flipped (image rows go down with y); the
  // frame is recorded so that importing the file again restores the same grids.
  FlameFrame frame;
  frame.scale = project.render.flame.density_unit;  // flam3's exposure counts density per flame unit
  const Camera& cam = project.camera;
  const RenderSettings& r = project.render;
  if (native) frame.scale = 1.0;
  if (!native && !(cam.orthographic() && cam.pitch == 90.0))
    out.warnings.push_back(
        "the camera is not an orthographic view from above; the flame frames its target and extent seen from above");
  const double halfH = cam.distance * std::tan(cam.fov * 3.14159265358979323846 / 360.0);
  const double ppu = r.height / (2.0 * halfH) * frame.scale;
  FlamePoint center = native ? FlamePoint{cam.target.x, cam.target.y} : frame.fromX({cam.target.x, cam.target.y});
  double rotate = native ? std::remainder(-90.0 - cam.yaw, 360.0) : 0.0;
  // A native project's camera other than the flat view from below is written as the flame's 3D
  // camera (io/flame_camera.h); a perspective eye off the flame's z axis moves the genome.
  std::optional<FlameCameraExport> camera3D;
  const bool flatView =
      cam.orthographic() && cam.pitch == -90.0 && cam.roll == 0.0 && cam.shift_x == 0.0 && cam.shift_y == 0.0;
  if (native && !flatView) {
    try {
      camera3D = flameCameraFromProject(cam, r.height);
      center = {camera3D->camera.centerX, camera3D->camera.centerY};
      rotate = camera3D->camera.rotate;
    } catch (const FlameError& e) {
      out.warnings.push_back(std::string(e.what()) + "; the flame frames the camera's target from below");
    }
  }
  if (rotate == 0.0) rotate = 0.0;  // no "-0"
  // A native project whose maps leave the plane z = 0 (imported from a 3D genome, or made so) is
  // written in JWildfire's 3D form: each map's 3D parts, ztranslate's and zcone's signs turned
  // back (X's z is the flame's −z), and preserve_z, under which the planar variations carry w·z
  // as GridIFS's do.
  bool leavesPlane = false;
  if (native) {
    auto leaves = [&](const Function& fn, const std::string& path) {
      if (fn.muted) return false;
      for (const auto& [name, weight] : fn.variations)
        if (flipsSignWithZ(name) && weight != 0.0) return true;
      if (fn.post) {
        const auto m = fn.post->affine();
        if (m[2][0] != 0.0 || m[2][1] != 0.0 || m[2][3] != 0.0 || m[0][2] != 0.0 || m[1][2] != 0.0) return true;
      }
      const auto a = gridAffine3(fn, path, project.time);
      return a && (a->m[2][0] != 0.0 || a->m[2][1] != 0.0 || a->m[2][2] != 0.0 || a->t[2] != 0.0);
    };
    for (std::size_t i = 0; i < project.functions.size(); ++i)
      leavesPlane |= leaves(project.functions[i], "functions[" + std::to_string(i) + "]");
    if (project.final_function) leavesPlane |= leaves(*project.final_function, "final");
  }
  const FlameSettings& fl = r.flame;
  std::ostringstream x;
  x << "<flame name=\"" << xmlEscape(name) << "\" version=\"GridIFS\" size=\"" << r.width << " " << r.height
    << "\" center=\"" << num(center.x) << " " << num(center.y) << "\" scale=\"" << num(ppu) << "\" zoom=\"0\" rotate=\""
    << num(rotate) << "\" oversample=\"" << fl.supersample << "\" supersample=\"" << fl.supersample << "\" filter=\""
    << num(fl.filter_radius) << "\" filter_shape=\"gaussian\" quality=\""
    << num(double(renderSampleCount(r)) / (double(r.width) * r.height)) << "\" background=\"" << num(r.background.x)
    << " " << num(r.background.y) << " " << num(r.background.z) << "\" brightness=\"" << num(fl.brightness)
    << "\" gamma=\"" << num(fl.gamma) << "\" gamma_threshold=\"" << num(fl.gamma_threshold) << "\" vibrancy=\""
    << num(fl.vibrancy) << "\" highlight_power=\"" << num(fl.highlight_power) << "\" estimator_radius=\""
    << num(fl.estimator_radius) << "\" estimator_minimum=\"" << num(fl.estimator_minimum) << "\" estimator_curve=\""
    << num(fl.estimator_curve) << "\" palette_mode=\"linear\" interpolation_type=\"linear\"";
  if (camera3D) {
    const FlameCamera& f = camera3D->camera;
    // Apophysis 7X's and Fractorium's name for the perspective; JWildfire reads both.
    x << " cam_pitch=\"" << num(f.pitch) << "\" cam_yaw=\"" << num(f.yaw) << "\" cam_perspective=\""
      << num(f.perspective) << "\" cam_zpos=\"" << num(f.zpos) << "\"";
  }
  if (leavesPlane) x << " preserve_z=\"1\"";
  // The lens blur keeps the plane through the target sharp: the flame camera's c_z = 0 plane when
  // it is written as a 3D camera, and the flat view's own plane (where a native genome lies).
  if (native && cam.lens_blur != 0.0) {
    x << " cam_dof=\"" << num(cam.lens_blur) << "\"";
    // A flat view keeps the plane through its target sharp: flam3's plane z = cam_zpos (X's z is
    // the flame's −z).
    if (!camera3D && cam.target.z != 0.0) x << " cam_zpos=\"" << num(-cam.target.z) << "\"";
  } else if (cam.lens_blur != 0.0) {
    out.warnings.push_back("the camera's lens blur was left out: a sampled flame has no plane for it to keep sharp");
  }
  if (fl.palette_keys.empty() && fl.palette.rfind("flam3:", 0) == 0 &&
      fl.palette.find_first_not_of("0123456789", 6) == std::string::npos)
    x << " palette=\"" << fl.palette.substr(6) << "\"";
  // flam3 writes its hue beside the colours it has already turned (flam3_print), as we do below.
  if (fl.hue != 0.0) x << " hue=\"" << num(fl.hue) << "\"";
  if (!native)
    x << " " << kFlameFrameAttribute << "=\"" << num(frame.centerX) << " " << num(frame.centerY) << " "
      << num(frame.scale) << "\"";
  x << ">\n";

  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < project.functions.size(); ++i)
    if (!project.functions[i].muted) kept.push_back(i);
  // The genome moved by (mx, my): every map becomes T∘f∘T⁻¹, its pre-affine's translation taking
  // −A·t and its post map +t. Variations that read the pre-affine's translation see another one.
  auto moved = [&](const Function& fn, FlameAffine pre, const std::string& label) {
    const double mx = camera3D->moveX, my = camera3D->moveY;
    pre.c -= pre.a * mx + pre.b * my;
    pre.f -= pre.d * mx + pre.e * my;
    FlameAffine post;
    if (fn.post) {
      const auto m = fn.post->affine();
      post = FlameAffine{m[0][0], m[0][1], m[0][3], m[1][0], m[1][1], m[1][3]};
    }
    post.c += mx;
    post.f += my;
    for (const auto& [name, weight] : fn.variations)
      if (const FlameVariation* v = findFlameVariation(name); v && v->dependent)
        out.warnings.push_back(label + "'s " + name +
                               " reads the pre-affine's translation, which moving the genome under the flame's "
                               "camera changes");
    return "color=\"" + num(fn.palette_index) + "\" color_speed=\"" + num(fn.color_speed) + "\" " +
           variationAttributes(fn, label, out.warnings) + " coefs=\"" + coefsText(pre) + "\" post=\"" +
           coefsText(post) + "\" name=\"" + xmlEscape(fn.name) + "\"";
  };
  auto xformAttributes = [&](const Function& fn, const std::string& path, const std::string& label) {
    if (leavesPlane) {
      const auto grid3 = gridAffine3(fn, path, project.time);
      if (grid3) {
        Affine3 pre = flippedZ(*grid3), post;
        if (fn.post) {
          const auto m = fn.post->affine();
          Affine3 inX;
          for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 3; ++c) inX.m[r][c] = m[std::size_t(r)][std::size_t(c)];
            inX.t[r] = m[std::size_t(r)][3];
          }
          post = flippedZ(inX);
        }
        if (camera3D) {
          const double mx = camera3D->moveX, my = camera3D->moveY;
          for (int r = 0; r < 3; ++r) pre.t[r] -= pre.m[r][0] * mx + pre.m[r][1] * my;
          post.t[0] += mx;
          post.t[1] += my;
        }
        const auto jPre = jwildfireForm(pre), jPost = jwildfireForm(post);
        if (jPre && jPost) {
          const JWildfireAffine identity{FlameAffine{}, FlameAffine{}, FlameAffine{}};
          const bool hasPost = !(jPost->xy == identity.xy && jPost->yz == identity.yz && jPost->zx == identity.zx);
          return "color=\"" + num(fn.palette_index) + "\" color_speed=\"" + num(fn.color_speed) + "\" " +
                 variationAttributes(fn, label, out.warnings, true) + " " + affine3Attributes(*jPre, false) +
                 (hasPost ? " " + affine3Attributes(*jPost, true) : std::string()) + " name=\"" + xmlEscape(fn.name) +
                 "\"";
        }
        out.warnings.push_back(label +
                               "'s 3D map has no JWildfire form (its x and y rows are dependent); its plane "
                               "part is exported");
      } else {
        out.warnings.push_back(label + "'s grid is not an affine map in 3D; its plane part is exported");
      }
    }
    const auto grid = evaluateFunctionAt(fn, path, project.time);
    double error = 0.0;
    const FlameAffine fit = fitAffine(*grid, error);
    if (error > 1e-9) {
      char buffer[64];
      std::snprintf(buffer, sizeof buffer, "%.3g", error);
      out.warnings.push_back(label +
                             " is not affine in the z = 0 plane: exported as its least-squares affine fit "
                             "(largest node error " +
                             buffer + ")");
    }
    if (native && camera3D && (camera3D->moveX != 0.0 || camera3D->moveY != 0.0)) return moved(fn, fit, label);
    if (native)
      return "color=\"" + num(fn.palette_index) + "\" color_speed=\"" + num(fn.color_speed) + "\" " +
             variationAttributes(fn, label, out.warnings) + " coefs=\"" + coefsText(fit) + "\"" + postAttribute(fn) +
             " name=\"" + xmlEscape(fn.name) + "\"";
    return "color=\"" + num(fn.palette_index) + "\" color_speed=\"" + num(fn.color_speed) + "\" linear=\"1\" coefs=\"" +
           coefsText(toFlame(fit, frame)) + "\" name=\"" + xmlEscape(fn.name) + "\"";
  };
  for (std::size_t i : kept) {
    const Function& fn = project.functions[i];
    x << "  <xform weight=\"" << num(fn.weight) << "\" "
      << xformAttributes(fn, "functions[" + std::to_string(i) + "]",
                         "function " + std::to_string(i) + " \"" + fn.name + "\"");
    if (!project.transitions.empty()) {
      x << " chaos=\"";
      for (std::size_t k = 0; k < kept.size(); ++k) x << (k ? " " : "") << num(project.transitions[i][kept[k]]);
      x << "\"";
    }
    x << "/>\n";
  }
  if (project.final_function && !project.final_function->muted)
    x << "  <finalxform " << xformAttributes(*project.final_function, "final", "the final function") << "/>\n";
  try {
    const Palette palette = resolveFlamePalette(fl, projectFolder);
    for (int i = 0; i < Palette::kSize; ++i) {
      const Rgb& c = palette.colors[std::size_t(i)];
      x << "  <color index=\"" << i << "\" rgb=\"" << int(std::lround(c.r * 255.0f)) << " "
        << int(std::lround(c.g * 255.0f)) << " " << int(std::lround(c.b * 255.0f)) << "\"/>\n";
    }
  } catch (const PaletteError& e) {
    out.warnings.push_back(std::string("the palette was not exported: ") + e.what());
  }
  x << "</flame>\n";
  out.xml = x.str();
  return out;
}

}  // namespace gridifs
