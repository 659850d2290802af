#include "gpu/headless_gl_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstring>
#include <vector>

namespace gridifs::gpu {
namespace {

bool hasClientExtension(const char* name) {
  const char* all = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!all) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = std::strstr(all, name); p; p = std::strstr(p + n, name))
    if ((p == all || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

bool hasGlExtension(const char* name) {
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i)
    if (std::strcmp(reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i))), name) == 0) return true;
  return false;
}

struct Candidate {
  EGLDisplay display;
  const char* platform;
  bool softwareDevice;
};

/// Hardware devices first, then software devices, then the surfaceless platform.
std::vector<Candidate> candidates() {
  std::vector<Candidate> out, software;
  if (hasClientExtension("EGL_EXT_platform_device") && hasClientExtension("EGL_EXT_device_enumeration")) {
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (eglQueryDevicesEXT(16, devices, &count))
      for (EGLint i = 0; i < count; ++i) {
        const char* ext = eglQueryDeviceStringEXT(devices[i], EGL_EXTENSIONS);
        const bool soft = ext && std::strstr(ext, "EGL_MESA_device_software");
        EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        if (d != EGL_NO_DISPLAY) (soft ? software : out).push_back({d, "device", soft});
      }
  }
  out.insert(out.end(), software.begin(), software.end());
  if (hasClientExtension("EGL_MESA_platform_surfaceless")) {
    EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (d != EGL_NO_DISPLAY) out.push_back({d, "surfaceless", false});
  }
  return out;
}

}  // namespace

std::unique_ptr<HeadlessGlContext> HeadlessGlContext::create() {
  if (!hasClientExtension("EGL_EXT_platform_base"))
    throw GpuUnavailable(
        "no usable EGL was found (the GPU renderer needs EGL with the device or surfaceless "
        "platform)");
  const std::vector<Candidate> list = candidates();
  if (list.empty()) throw GpuUnavailable("EGL offers no GPU device and no surfaceless platform");
  std::string why = "no EGL device could be initialised";
  for (const Candidate& c : list) {
    EGLint major = 0, minor = 0;
    if (!eglInitialize(c.display, &major, &minor)) continue;
    if (!eglBindAPI(EGL_OPENGL_API)) {
      eglTerminate(c.display);
      why = "the EGL device offers no desktop OpenGL";
      continue;
    }
    const EGLint attributes[] = {
        EGL_CONTEXT_MAJOR_VERSION,           4,       EGL_CONTEXT_MINOR_VERSION, 3, EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLContext context = eglCreateContext(c.display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context == EGL_NO_CONTEXT) {
      eglTerminate(c.display);
      why = "the GPU offers no OpenGL 4.3 context, so it has no compute shaders";
      continue;
    }
    if (!eglMakeCurrent(c.display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
      eglDestroyContext(c.display, context);
      eglTerminate(c.display);
      why = "the OpenGL 4.3 context could not be made current without a window";
      continue;
    }
    std::unique_ptr<HeadlessGlContext> out(new HeadlessGlContext());
    out->display_ = c.display;
    out->context_ = context;
    GpuInfo& info = out->info_;
    info.renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    info.version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    info.platform = c.platform;
    info.software = c.softwareDevice || info.renderer.find("llvmpipe") != std::string::npos ||
                    info.renderer.find("softpipe") != std::string::npos ||
                    info.renderer.find("SwiftShader") != std::string::npos;
    info.atomic64 = hasGlExtension("GL_ARB_gpu_shader_int64") && hasGlExtension("GL_NV_shader_atomic_int64");
    GLint64 block = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &block);
    info.maxStorageBlockBytes = block;
    GLint groups = 0;
    glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 0, &groups);
    info.maxWorkGroups = groups;
    if (epoxy_gl_version() < 43 || groups <= 0) throw GpuUnavailable("the GPU offers no OpenGL 4.3 compute shaders");
    return out;
  }
  throw GpuUnavailable(why);
}

HeadlessGlContext::~HeadlessGlContext() {
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display_, context_);
  // The display is not terminated: EGL displays are per process and another context (the
  // modeller's, a second renderer) may still use it; eglTerminate would pull it from under them.
}

GpuInfo probeGpu() { return HeadlessGlContext::create()->info(); }

}  // namespace gridifs::gpu
