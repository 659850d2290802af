#include "gpu/chaos_compute.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include "gl_common/shader_build.h"
#include "gpu/embedded_compute_shaders.h"
#include "gpu/variation_stage.h"
#include "render/sample_chunks.h"

namespace gridifs::gpu {
namespace {

enum Binding {
  kFunctions,
  kNodes,
  kAlias,
  kChains,
  kTallies,
  kKeys,
  kDensity,
  kColorSums,
  kPalette,
  kStages,
  kTransitionWalk
};
constexpr int kBuffers = kTransitionWalk + 1;

constexpr std::uint32_t kGroupSize = 64;  // local_size_x in the shader
constexpr std::uint32_t kMaxChains = 1u << 18;
/// Points may go far beyond X under variations (spherical, julia near 0): the CPU kernel's bound then.
constexpr float kVariationEscapeBound = 1e10f;

/// One function as the shader's `Fn` (std430: 64 bytes).
struct GpuFunction {
  float toLattice[4];
  float maxCell[4];
  float color[4];
  float speed;
  std::uint32_t strideJ, strideK, pairOffset;
};
static_assert(sizeof(GpuFunction) == 64);

const char* shaderSource(const char* name) {
  for (const EmbeddedShader& s : kEmbeddedShaders)
    if (std::strcmp(s.name, name) == 0) return s.source;
  throw GpuUnavailable(std::string("the GPU renderer's shader ") + name + " is missing from this build");
}

std::string megabytes(std::size_t bytes) { return std::to_string((bytes + (1u << 20) - 1) >> 20) + " MB"; }

}  // namespace

std::uint32_t chainCount(const RenderJob& job, bool software) {
  // A preview runs until stopped: fewer chains on a software rasterizer, so the first points
  // (after every chain's skip) show within a frame.
  if (job.samples <= 0) return software ? (1u << 14) : kMaxChains;
  const std::int64_t perChain = 64 * std::int64_t(job.skip + 1);
  const std::int64_t n = job.samples / perChain / kGroupSize * kGroupSize;
  return std::uint32_t(std::clamp<std::int64_t>(n, kGroupSize, kMaxChains));
}

ChainRange chainsOf(const RenderJob& job, bool software) {
  const std::uint32_t total = chainCount(job, software);
  // A preview without a budget has nothing to split: it plays every chain, as the CPU plays
  // every chunk of an unlimited job.
  if (!job.part || job.samples <= 0) return ChainRange::all(total);
  const ChunkRange r = partChunks(total, job.part->index, job.part->count);
  return ChainRange{total, std::uint32_t(r.begin), std::uint32_t(r.end)};
}

std::int64_t chainBudget(const RenderJob& job, ChainRange chains) {
  if (job.samples <= 0 || chains.total == 0) return 0;
  const std::uint64_t base = std::uint64_t(job.samples) / chains.total;
  const std::uint64_t extra = std::uint64_t(job.samples) % chains.total;
  // The chains [0, extra) iterate once more; extraHere of them lie in [begin, end).
  const std::uint64_t extraHere = std::clamp<std::uint64_t>(extra, chains.begin, chains.end) - chains.begin;
  return std::int64_t(base * chains.size() + extraHere);
}

ChaosCompute::ChaosCompute(const GpuInfo& info, ChaosOutput output, bool accumulateColor, bool allowAtomic64)
    : info_(info),
      output_(output),
      color_(accumulateColor && (output == ChaosOutput::Image || output == ChaosOutput::Voxels)),
      points_(output == ChaosOutput::Points),
      atomic64_(allowAtomic64 && info.atomic64 && output == ChaosOutput::Image) {
  // An IFS with variations gets a program specialised to the variations it uses (programFor),
  // built on first use: plain grid IFSs pay nothing for them.
  if (output != ChaosOutput::Maps) plainProgram_ = buildProgram("");
  program_ = plainProgram_;
  static_assert(kBuffers == kBufferCount, "a buffer per binding");
  glGenBuffers(kBuffers, buffers_);
}

unsigned ChaosCompute::buildProgram(const std::string& usedVariations) const {
  const bool variations = !usedVariations.empty();
  std::string source = "#version 430 core\n";
  if (atomic64_)
    source += "#extension GL_ARB_gpu_shader_int64 : require\n#extension GL_NV_shader_atomic_int64 : require\n";
  source += std::string("#define ATOMIC64 ") + (atomic64_ ? "1" : "0") + "\n#define ACCUMULATE_COLOR " +
            (color_ ? "1" : "0") + "\n#define EMIT_POINTS " + (points_ ? "1" : "0") + "\n#define BIN_VOXELS " +
            (output_ == ChaosOutput::Voxels ? "1" : "0") + "\n#define VARIATIONS " + (variations ? "1" : "0") +
            "\n#define EVALUATE_MAPS " + (output_ == ChaosOutput::Maps ? "1" : "0") + "\n";
  if (variations)
    source += variationDefines(usedVariations) + "#line 1 1\n" + shaderSource("flame_variations.comp.glsl") + "\n";
  source += "#line 1 0\n";
  source += shaderSource("chaos_game.comp.glsl");
  const gl::ShaderBuild shader = gl::compileShader(GL_COMPUTE_SHADER, source.c_str());
  if (!shader.id) throw GpuUnavailable("the GPU driver rejected the chaos-game shader: " + shader.log);
  const gl::ShaderBuild program = gl::linkProgram({shader.id});
  if (!program.id) throw GpuUnavailable("the GPU driver could not link the chaos-game shader: " + program.log);
  return program.id;
}

ChaosCompute::~ChaosCompute() {
  glDeleteBuffers(kBuffers, buffers_);
  if (plainProgram_) glDeleteProgram(plainProgram_);
  for (const auto& [used, program] : variationPrograms_) glDeleteProgram(program);
}

unsigned ChaosCompute::programFor(const CompiledIfs& ifs) {
  if (!ifs.hasVariations && output_ != ChaosOutput::Maps) return plainProgram_;
  const std::string used = usedVariations(ifs);
  if (const auto it = variationPrograms_.find(used); it != variationPrograms_.end()) return it->second;
  // A modeller session tries many sets of variations; keep the last few programs, not all.
  constexpr std::size_t kKeptPrograms = 8;
  if (variationPrograms_.size() >= kKeptPrograms) {
    for (const auto& [key, program] : variationPrograms_) glDeleteProgram(program);
    variationPrograms_.clear();
  }
  return variationPrograms_[used] = buildProgram(used);
}

void ChaosCompute::allocate(unsigned buffer, std::size_t bytes, const std::string& what) {
  bytes = std::max<std::size_t>(bytes, 16);
  if (std::int64_t(bytes) > info_.maxStorageBlockBytes)
    throw GpuUnavailable("the GPU cannot hold " + what + ": it needs " + megabytes(bytes) +
                         " and the GPU's storage buffers hold at most " +
                         megabytes(std::size_t(info_.maxStorageBlockBytes)));
  while (glGetError() != GL_NO_ERROR) {
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
  glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(bytes), nullptr, GL_DYNAMIC_COPY);
  if (glGetError() == GL_OUT_OF_MEMORY)
    throw GpuUnavailable("the GPU is out of memory for " + what + " (" + megabytes(bytes) + ")");
}

void ChaosCompute::uploadIfs(const CompiledIfs& ifs) {
  // The compiled IFS: functions (then the final function) and their node pairs.
  std::vector<GpuFunction> functions;
  std::vector<float> nodes;
  auto add = [&](const CompiledFunction& f) {
    GpuFunction g{};
    for (int d = 0; d < 4; ++d) {
      g.toLattice[d] = f.toLattice[d];
      g.maxCell[d] = f.maxCell[d];
      g.color[d] = f.color[d];
    }
    g.speed = f.colorSpeed;
    g.strideJ = f.pairStrideJ;
    g.strideK = f.pairStrideK;
    g.pairOffset = std::uint32_t(nodes.size() / 8);
    for (const NodePair& p : f.pairs) {
      nodes.insert(nodes.end(), p.a, p.a + 4);
      nodes.insert(nodes.end(), p.b, p.b + 4);
    }
    functions.push_back(g);
  };
  for (const CompiledFunction& f : ifs.functions) add(f);
  if (ifs.finalFunction) add(*ifs.finalFunction);
  std::vector<std::uint32_t> alias;
  for (const AliasEntry& e : ifs.alias) alias.insert(alias.end(), {e.threshold, e.alias});

  auto upload = [&](Binding b, const void* data, std::size_t bytes, const std::string& what) {
    allocate(buffers_[b], bytes, what);
    glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(bytes), data);
  };
  upload(kFunctions, functions.data(), functions.size() * sizeof(GpuFunction), "the IFS");
  upload(kNodes, nodes.data(), nodes.size() * sizeof(float), "the IFS's grids");
  upload(kAlias, alias.data(), alias.size() * 4, "the IFS");
  // The transition walk as the CPU kernel reads it (one uvec4 per entry); a placeholder entry when
  // the chain game is unrestricted, so the binding always has storage.
  std::vector<std::uint32_t> walk;
  for (const TransitionStep& e : ifs.transitionWalk)
    walk.insert(walk.end(), {e.threshold, e.alias, e.keepRow, e.aliasRow});
  if (walk.empty()) walk.assign(4, 0u);
  upload(kTransitionWalk, walk.data(), walk.size() * 4, "the IFS's transitions");
  if (ifs.hasVariations || output_ == ChaosOutput::Maps) {
    const std::vector<std::uint32_t> stages = packVariationStages(ifs);
    upload(kStages, stages.data(), stages.size() * 4, "the IFS's variations");
  }
}

void ChaosCompute::depthRange(const CompiledIfs& ifs, const RenderJob& job, const OrbitCamera& camera) {
  // 32-bit keys quantise depth linearly over the depth range the plotted points can have: a
  // trilinear lookup is a convex combination of a cell's nodes, so every plotted point lies within
  // the depth range of the nodes of the functions that produce it (the final function's, if any).
  // Variations move points beyond the nodes: their range comes from a short pilot chaos game on
  // the CPU (points outside it take the nearest end step). Either way it depends on the IFS and
  // the camera only, never on the chain range: the keys of a render's parts mean the same depths,
  // so their minimum is the whole render's.
  float lo = std::numeric_limits<float>::infinity(), hi = -lo;
  if (ifs.hasVariations && output_ == ChaosOutput::Image && !atomic64_ &&
      variationDepthRange(ifs, camera, job.skip, lo, hi)) {
    depthMin_ = lo;
    depthScale_ = 65534.0f / (hi - lo);
    return;
  }
  const OrbitCamera::PixelRows rows = camera.pixelRows();
  const glm::dvec3 eye = camera.eye();
  auto range = [&](const CompiledFunction& f) {
    for (const NodePair& p : f.pairs)
      for (const float* q : {p.a, p.b}) {
        // A panoramic depth is the distance from the eye, convex: at most its largest at the
        // nodes (plus the stereo circle), at least the near plane.
        const float d = camera.panoramic()
                            ? float(glm::length(glm::dvec3(q[0], q[1], q[2]) - eye) + camera.stereoRadius())
                            : rows.rowD[0] * q[0] + rows.rowD[1] * q[1] + rows.rowD[2] * q[2] + rows.rowD[3];
        lo = std::min(lo, camera.panoramic() ? float(camera.nearPlane()) : d);
        hi = std::max(hi, d);
      }
  };
  if (ifs.finalFunction)
    range(*ifs.finalFunction);
  else
    for (const CompiledFunction& f : ifs.functions) range(f);
  lo = std::max(lo, float(camera.nearPlane()));
  depthMin_ = lo;
  depthScale_ = hi > lo ? 65534.0f / (hi - lo) : 0.0f;  // 0xFFFF.... stays the empty key
}

void ChaosCompute::setProjectionUniforms(const OrbitCamera& camera) {
  auto loc = [&](const char* name) { return glGetUniformLocation(program_, name); };
  const CameraProjection projection = camera.settings().projection;
  glUniform1i(loc("uProjection"), !camera.panoramic() ? 0 : projection == CameraProjection::Fisheye ? 1 : 2);
  glUniform1i(loc("uStereo"), camera.eyes() == 2 ? 1 : 0);
  const int rightEye = camera.eyes() == 2 ? 1 : 0;
  const OrbitCamera::PixelRows rows = camera.pixelRows(rightEye);
  const float right[4][4] = {{rows.rowX[0], rows.rowY[0], rows.rowW[0], rows.rowD[0]},
                             {rows.rowX[1], rows.rowY[1], rows.rowW[1], rows.rowD[1]},
                             {rows.rowX[2], rows.rowY[2], rows.rowW[2], rows.rowD[2]},
                             {rows.rowX[3], rows.rowY[3], rows.rowW[3], rows.rowD[3]}};
  glUniform4fv(loc("uCamRight"), 4, &right[0][0]);
  float bounds[2][4], centre[2][2], turn[2][9];
  for (int eye = 0; eye < 2; ++eye) {
    const EyeRegion r = camera.eyeRegion(camera.eyes() == 2 ? eye : 0);
    const float b[4] = {float(r.x), float(r.x + r.width), float(r.y), float(r.y + r.height)};
    std::copy(b, b + 4, bounds[eye]);
    centre[eye][0] = float(r.x + 0.5 * r.width);
    centre[eye][1] = float(r.y + 0.5 * r.height);
    const glm::dmat3& t = camera.eyeTurn(camera.eyes() == 2 ? eye : 0);
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) turn[eye][3 * c + k] = float(t[c][k]);  // column major, as GLSL's
  }
  glUniform4fv(loc("uEyeBounds"), 2, &bounds[0][0]);
  glUniform2fv(loc("uEyeCentre"), 2, &centre[0][0]);
  glUniform1f(loc("uPixelsPerRadian"), float(camera.pixelsPerRadian()));
  glUniform1f(loc("uHalfFov"), float(camera.settings().fov * (M_PI / 360.0)));
  glUniform1f(loc("uEyeRadius"), float(camera.stereoRadius()));
  const glm::dvec3 up = camera.viewUp();
  glUniform3f(loc("uViewUp"), float(up.x), float(up.y), float(up.z));
  glUniformMatrix3fv(loc("uEyeTurn"), 2, GL_FALSE, &turn[0][0]);
  const float sign[2] = {float(camera.eyeSign(0)), float(camera.eyeSign(1))};
  glUniform1fv(loc("uEyeSign"), 2, sign);
  // The lens blur (Camera::lens_blur, flam3's cam_dof): the view's right and up axes in world
  // space, and the view depth's row, as the CPU's lens (render/shaded_plot.h) takes them.
  const double blur = camera.settings().lens_blur;
  glUniform1f(loc("uLensAperture"), float(0.1 * blur));
  if (blur > 0.0) {
    const glm::dmat4& view = camera.view();
    glUniform3f(loc("uLensRight"), float(view[0][0]), float(view[1][0]), float(view[2][0]));
    glUniform3f(loc("uLensUp"), float(view[0][1]), float(view[1][1]), float(view[2][1]));
    const OrbitCamera::PixelRows centre = camera.pixelRows(0);
    glUniform4f(loc("uLensDepthRow"), centre.rowD[0], centre.rowD[1], centre.rowD[2], centre.rowD[3]);
    glUniform1f(loc("uLensFocus"), float(camera.settings().distance));
  }
}

void ChaosCompute::setup(const CompiledIfs& ifs, const RenderJob& job, ChainRange share, int voxelResolution) {
  // The compute shader walks grid functions, chosen independently or by transition rows (a
  // transition matrix or an IFS matrix with states); the CPU renderer takes the rest (auto falls
  // back to it).
  if (ifs.barycentricSize > 0)
    throw GpuUnavailable("the GPU renderer does not run free-form (control point) IFSs; the CPU renderer does");
  for (const CompiledFunction& f : ifs.functions)
    if (!f.points.empty())
      throw GpuUnavailable("the GPU renderer does not run condensation functions; the CPU renderer does");
  program_ = programFor(ifs);
  job_ = job;
  // The buffers hold the share's chains only; the shader adds share.begin to a chain's local
  // index wherever the global index matters (its seed, its budget).
  const std::uint32_t chains = share.size();
  chains_ = chains;
  count_ = std::uint32_t(ifs.functions.size());
  issued_ = 0;
  budgetBase_ = budgetExtra_ = extraHere_ = 0;
  if (job.samples > 0 && share.total > 0) {
    budgetBase_ = std::uint64_t(job.samples) / share.total;
    budgetExtra_ = std::uint64_t(job.samples) % share.total;
    extraHere_ = std::uint64_t(chainBudget(job, share)) - budgetBase_ * chains;
  }
  const OrbitCamera camera(job.camera, job.width, job.height);
  const OrbitCamera::PixelRows rows = camera.pixelRows();
  depthRange(ifs, job, camera);

  voxels_ = output_ == ChaosOutput::Voxels ? voxelResolution : 0;
  const std::size_t n = std::size_t(voxels_);
  pixels_ = points_ ? 0 : voxels_ > 0 ? n * n * n : std::size_t(job.width) * std::size_t(job.height);
  const std::string image = voxels_ > 0 ? std::to_string(voxels_) + "³ volume"
                                        : std::to_string(job.width) + "×" + std::to_string(job.height) + " image";
  uploadIfs(ifs);
  allocate(buffers_[kChains], std::size_t(chains) * 64, "the chains");
  allocate(buffers_[kTallies], std::size_t(chains) * 8, "the chains");
  const std::uint32_t ones = 0xFFFFFFFFu, zero = 0;
  if (points_) {
    // 32 bytes a slot; as many iterations per dispatch as 64 MB of slots hold.
    pointSlots_ = std::size_t(chains) * std::max<std::size_t>(1, (std::size_t(64) << 20) / 32 / std::max(chains, 1u));
    allocate(buffers_[kKeys], pointSlots_ * 32, "the points");
  } else if (voxels_ > 0) {
    allocate(buffers_[kDensity], pixels_ * 4, "the density of a " + image);
    glClearBufferData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    if (color_) {
      allocate(buffers_[kColorSums], pixels_ * 24, "the colour sums of a " + image);
      glClearBufferData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    }
  } else {
    allocate(buffers_[kKeys], pixels_ * (atomic64_ ? 8 : 4), "the z-buffer of a " + image);
    glClearBufferData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &ones);
    allocate(buffers_[kDensity], pixels_ * 4, "the density of a " + image);
    glClearBufferData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    if (color_) {
      allocate(buffers_[kColorSums], pixels_ * 32, "the colour sums of a " + image);
      glClearBufferData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
      std::vector<float> palette(257 * 4, 0.0f);
      if (job.palette) {
        for (std::size_t i = 0; i < 256 && i < job.palette->colors.size(); ++i) {
          palette[i * 4 + 0] = job.palette->colors[i].r;
          palette[i * 4 + 1] = job.palette->colors[i].g;
          palette[i * 4 + 2] = job.palette->colors[i].b;
        }
        std::copy_n(&palette[255 * 4], 4, &palette[256 * 4]);
      }
      allocate(buffers_[kPalette], palette.size() * sizeof(float), "the palette");
      glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(palette.size() * sizeof(float)), palette.data());
    }
  }
  for (int b = 0; b < kBuffers; ++b) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(b), buffers_[b]);

  glUseProgram(program_);
  auto loc = [&](const char* name) { return glGetUniformLocation(program_, name); };
  glUniform1ui(loc("uChains"), chains);
  glUniform1ui(loc("uChainBase"), share.begin);
  glUniform1ui(loc("uCount"), count_);
  glUniform1i(loc("uHasFinal"), ifs.finalFunction ? 1 : 0);
  glUniform1ui(loc("uSkip"), std::uint32_t(job.skip));
  glUniform1f(loc("uEscape"),
              ifs.hasVariations ? std::max(limits::kEscapeBound, kVariationEscapeBound) : limits::kEscapeBound);
  glUniform2ui(loc("uSeed"), std::uint32_t(job.seed), std::uint32_t(job.seed >> 32));
  glUniform2ui(loc("uBudget"), std::uint32_t(budgetBase_), std::uint32_t(budgetExtra_));
  glUniform1i(loc("uUnlimited"), job.samples <= 0 ? 1 : 0);
  glUniform4f(loc("uCamX"), rows.rowX[0], rows.rowY[0], rows.rowW[0], rows.rowD[0]);
  glUniform4f(loc("uCamY"), rows.rowX[1], rows.rowY[1], rows.rowW[1], rows.rowD[1]);
  glUniform4f(loc("uCamZ"), rows.rowX[2], rows.rowY[2], rows.rowW[2], rows.rowD[2]);
  glUniform4f(loc("uCam1"), rows.rowX[3], rows.rowY[3], rows.rowW[3], rows.rowD[3]);
  glUniform2f(loc("uSize"), float(job.width), float(job.height));
  glUniform1f(loc("uNear"), float(camera.nearPlane()));
  setProjectionUniforms(camera);
  glUniform1ui(loc("uStride"), std::uint32_t(job.width));
  glUniform2f(loc("uDepthQuant"), depthMin_, depthScale_);
  glUniform1i(loc("uPalette"), job.palette && voxels_ == 0 ? 1 : 0);
  glUniform1ui(loc("uVoxels"), std::uint32_t(voxels_));
  glUniform1i(loc("uTransitions"), ifs.transitionWalk.empty() ? 0 : 1);
  glUniform1ui(loc("uRestartInterval"), ifs.transitionWalk.empty() ? 0u : ifs.restartInterval);
  glUniform1ui(loc("uStateRowsOffset"), ifs.stateRowsOffset);
  glUniform1ui(loc("uMode"), 0);
  if (chains > 0) glDispatchCompute((chains + kGroupSize - 1) / kGroupSize, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  glUniform1ui(loc("uMode"), 1);
  if (glGetError() == GL_OUT_OF_MEMORY) throw GpuUnavailable("the GPU ran out of memory for the " + image);
}

void ChaosCompute::dispatch(std::uint32_t iterations) {
  if (chains_ == 0) return;  // an empty part (more parts than chains): nothing to play
  if (points_) iterations = std::min<std::uint32_t>(iterations, std::uint32_t(pointSlots_ / chains_));
  glUseProgram(program_);
  glUniform1ui(glGetUniformLocation(program_, "uIterations"), iterations);
  glDispatchCompute((chains_ + kGroupSize - 1) / kGroupSize, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  issued_ += iterations;
}

void ChaosCompute::finish() { glFinish(); }

std::int64_t ChaosCompute::samplesDone() const {
  if (job_.samples <= 0) return std::int64_t(issued_ * chains_);
  return std::int64_t(extraHere_ * std::min(budgetBase_ + 1, issued_) +
                      (chains_ - extraHere_) * std::min(budgetBase_, issued_));
}

bool ChaosCompute::finished() const {
  return job_.samples > 0 && (chains_ == 0 || issued_ >= budgetBase_ + (extraHere_ ? 1 : 0));
}

void ChaosCompute::readback(ChaosReadback& out) const {
  out.width = job_.width;
  out.height = job_.height;
  out.atomic64 = atomic64_;
  out.depthMin = depthMin_;
  out.depthScale = depthScale_;
  auto read = [](unsigned buffer, void* data, std::size_t bytes) {
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(bytes), data);
  };
  std::vector<std::uint32_t> tallies(std::size_t(chains_) * 2);
  read(buffers_[kTallies], tallies.data(), tallies.size() * 4);
  out.bad = out.plotted = 0;
  for (std::size_t i = 0; i < chains_; ++i) {
    out.bad += tallies[2 * i];
    out.plotted += tallies[2 * i + 1];
  }
  out.samples = samplesDone();
  if (points_) return;
  if (voxels_ > 0) {
    out.keys64.clear();
    out.keys32.clear();
    out.density.resize(pixels_);
    read(buffers_[kDensity], out.density.data(), pixels_ * 4);
    out.colorSums.resize(color_ ? pixels_ * 6 : 0);
    if (color_) read(buffers_[kColorSums], out.colorSums.data(), pixels_ * 24);
    return;
  }
  if (atomic64_) {
    out.keys64.resize(pixels_);
    out.keys32.clear();
    read(buffers_[kKeys], out.keys64.data(), pixels_ * 8);
  } else {
    out.keys32.resize(pixels_);
    out.keys64.clear();
    read(buffers_[kKeys], out.keys32.data(), pixels_ * 4);
  }
  out.density.resize(pixels_);
  read(buffers_[kDensity], out.density.data(), pixels_ * 4);
  if (color_) {
    out.colorSums.resize(pixels_ * 8);
    read(buffers_[kColorSums], out.colorSums.data(), pixels_ * 32);
  } else {
    out.colorSums.clear();
  }
}

void ChaosCompute::readPoints(std::vector<float>& slots, std::uint32_t iterations) const {
  iterations = std::min<std::uint32_t>(iterations, std::uint32_t(pointSlots_ / chains_));
  slots.resize(std::size_t(iterations) * chains_ * 8);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffers_[kKeys]);
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(slots.size() * 4), slots.data());
}

std::vector<std::array<float, 3>> ChaosCompute::evaluateMaps(const CompiledIfs& ifs,
                                                             const std::vector<std::uint32_t>& functions,
                                                             const std::vector<std::array<float, 3>>& points,
                                                             std::uint64_t seed) {
  if (output_ != ChaosOutput::Maps) throw std::logic_error("evaluateMaps needs a ChaosCompute for ChaosOutput::Maps");
  const std::size_t n = std::min(functions.size(), points.size());
  program_ = programFor(ifs);
  uploadIfs(ifs);
  // Chain slots as the shader's Chain (64 bytes): p = (x, y, z, 0), misc.x = the function.
  std::vector<std::uint32_t> slots(n * 16, 0u);
  for (std::size_t i = 0; i < n; ++i) {
    std::memcpy(&slots[16 * i], points[i].data(), 12);
    slots[16 * i + 12] = functions[i];
  }
  allocate(buffers_[kChains], slots.size() * 4, "the points");
  glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(slots.size() * 4), slots.data());
  for (int b = 0; b < kBuffers; ++b) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(b), buffers_[b]);
  glUseProgram(program_);
  auto loc = [&](const char* name) { return glGetUniformLocation(program_, name); };
  glUniform1ui(loc("uChains"), std::uint32_t(n));
  glUniform1ui(loc("uChainBase"), 0);
  glUniform2ui(loc("uSeed"), std::uint32_t(seed), std::uint32_t(seed >> 32));
  if (n > 0) glDispatchCompute(std::uint32_t((n + kGroupSize - 1) / kGroupSize), 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffers_[kChains]);
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(slots.size() * 4), slots.data());
  std::vector<std::array<float, 3>> out(n);
  for (std::size_t i = 0; i < n; ++i) std::memcpy(out[i].data(), &slots[16 * i], 12);
  return out;
}

}  // namespace gridifs::gpu
