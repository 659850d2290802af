#pragma once
// A headless OpenGL 4.3 core context with compute shaders, through EGL (libepoxy): the device
// platform (EGL_EXT_platform_device: a GPU without a window system or X server), else Mesa's
// surfaceless platform (EGL_MESA_platform_surfaceless; llvmpipe on machines without a GPU). No
// window, no hidden window, no display connection.
//
// Thread-safety: a context is current on at most one thread; create, use and destroy it on the
// thread that renders with it (GpuChaosRenderer's own thread).
#include <memory>
#include <stdexcept>
#include <string>

namespace gridifs::gpu {

/// The GPU path cannot run here: no EGL, no device, no GL 4.3 compute, or not enough memory for the
/// job. what() is one sentence for the user.
struct GpuUnavailable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// What the context offers.
struct GpuInfo {
  std::string renderer;  // GL_RENDERER, e.g. "NVIDIA H100 80GB HBM3/PCIe/SSE2" or "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string version;   // GL_VERSION
  std::string platform;  // "device" or "surfaceless"
  /// A software rasterizer (Mesa's llvmpipe, softpipe): correct, but slower than the CPU renderer.
  bool software = false;
  /// GL_ARB_gpu_shader_int64 with GL_NV_shader_atomic_int64: exact 64-bit z-buffer keys.
  bool atomic64 = false;
  long long maxStorageBlockBytes = 0;  // GL_MAX_SHADER_STORAGE_BLOCK_SIZE
  long long maxWorkGroups = 0;         // GL_MAX_COMPUTE_WORK_GROUP_COUNT in x
};

class HeadlessGlContext {
 public:
  /// Creates the context and makes it current on the calling thread. Throws GpuUnavailable.
  static std::unique_ptr<HeadlessGlContext> create();
  ~HeadlessGlContext();
  HeadlessGlContext(const HeadlessGlContext&) = delete;
  HeadlessGlContext& operator=(const HeadlessGlContext&) = delete;

  const GpuInfo& info() const { return info_; }

 private:
  HeadlessGlContext() = default;
  void* display_ = nullptr;
  void* context_ = nullptr;
  GpuInfo info_;
};

/// Creates a context on the calling thread, reads its GpuInfo and destroys it (`gridifs info`).
/// Throws GpuUnavailable.
GpuInfo probeGpu();

}  // namespace gridifs::gpu
