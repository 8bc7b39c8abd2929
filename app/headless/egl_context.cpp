// EGL backend of OffscreenContext: a display without a window system, an OpenGL 3.3 core context made
// current with no surface, and a framebuffer object (RGBA8 colour, 24-bit depth) the renderer draws
// into. GL entry points come from eglGetProcAddress (EGL_KHR_get_all_proc_addresses), like the renderer's.
#include "egl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>

namespace sph::cli {
namespace {

void* egl_get_proc(const char* name) { return object_pointer(eglGetProcAddress(name)); }

template <class Fn>
Fn load(const char* name) {
  Fn f = nullptr;
  void* p = egl_get_proc(name);
  std::memcpy(&f, &p, sizeof(f));
  return f;
}

bool has_extension(const char* list, const char* name) {
  if (list == nullptr) return false;
  const std::size_t n = std::strlen(name);
  for (const char* s = std::strstr(list, name); s != nullptr; s = std::strstr(s + 1, name))
    if ((s == list || s[-1] == ' ') && (s[n] == ' ' || s[n] == '\0')) return true;
  return false;
}

std::string egl_error(const char* call) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%s failed (EGL error 0x%04x)", call, static_cast<unsigned>(eglGetError()));
  return buf;
}

/// The framebuffer-object calls the renderer's table does not carry.
struct FboApi {
  PFNGLGENFRAMEBUFFERSPROC GenFramebuffers = nullptr;
  PFNGLBINDFRAMEBUFFERPROC BindFramebuffer = nullptr;
  PFNGLDELETEFRAMEBUFFERSPROC DeleteFramebuffers = nullptr;
  PFNGLFRAMEBUFFERRENDERBUFFERPROC FramebufferRenderbuffer = nullptr;
  PFNGLCHECKFRAMEBUFFERSTATUSPROC CheckFramebufferStatus = nullptr;
  PFNGLGENRENDERBUFFERSPROC GenRenderbuffers = nullptr;
  PFNGLBINDRENDERBUFFERPROC BindRenderbuffer = nullptr;
  PFNGLRENDERBUFFERSTORAGEPROC RenderbufferStorage = nullptr;
  PFNGLDELETERENDERBUFFERSPROC DeleteRenderbuffers = nullptr;
  bool load_all() {
    GenFramebuffers = load<PFNGLGENFRAMEBUFFERSPROC>("glGenFramebuffers");
    BindFramebuffer = load<PFNGLBINDFRAMEBUFFERPROC>("glBindFramebuffer");
    DeleteFramebuffers = load<PFNGLDELETEFRAMEBUFFERSPROC>("glDeleteFramebuffers");
    FramebufferRenderbuffer = load<PFNGLFRAMEBUFFERRENDERBUFFERPROC>("glFramebufferRenderbuffer");
    CheckFramebufferStatus = load<PFNGLCHECKFRAMEBUFFERSTATUSPROC>("glCheckFramebufferStatus");
    GenRenderbuffers = load<PFNGLGENRENDERBUFFERSPROC>("glGenRenderbuffers");
    BindRenderbuffer = load<PFNGLBINDRENDERBUFFERPROC>("glBindRenderbuffer");
    RenderbufferStorage = load<PFNGLRENDERBUFFERSTORAGEPROC>("glRenderbufferStorage");
    DeleteRenderbuffers = load<PFNGLDELETERENDERBUFFERSPROC>("glDeleteRenderbuffers");
    return GenFramebuffers && BindFramebuffer && DeleteFramebuffers && FramebufferRenderbuffer &&
           CheckFramebufferStatus && GenRenderbuffers && BindRenderbuffer && RenderbufferStorage && DeleteRenderbuffers;
  }
};

class EglContext final : public OffscreenContext {
 public:
  EglContext(EGLDisplay display, EGLContext context, std::string platform)
      : display_(display), context_(context), platform_(std::move(platform)) {}
  // The display stays initialised: EGL hands every context of a platform the same display, and
  // eglTerminate would take the other contexts of this process with it.
  ~EglContext() override {
    if (gl_loaded_ && eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      fbo_.BindFramebuffer(GL_FRAMEBUFFER, 0);
      release_target();
    }
    if (eglGetCurrentContext() == context_) eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
  }

  bool make_current(int width, int height, std::string* err) override {
    if (width <= 0 || height <= 0) {
      if (err) *err = "invalid frame size " + std::to_string(width) + "x" + std::to_string(height);
      return false;
    }
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      if (err) *err = egl_error("eglMakeCurrent");
      return false;
    }
    if (!gl_loaded_) {
      if (!gl_.load(egl_get_proc, err)) return false;
      if (!fbo_.load_all()) {
        if (err) *err = "EGL: no framebuffer-object entry points";
        return false;
      }
      gl_loaded_ = true;
    }
    if (width != width_ || height != height_) {
      release_target();
      fbo_.GenRenderbuffers(2, renderbuffers_);
      fbo_.BindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[0]);
      fbo_.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
      fbo_.BindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[1]);
      fbo_.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
      fbo_.GenFramebuffers(1, &framebuffer_);
      fbo_.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
      fbo_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffers_[0]);
      fbo_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, renderbuffers_[1]);
      if (fbo_.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        if (err) *err = "EGL: the " + std::to_string(width) + "x" + std::to_string(height) + " framebuffer is incomplete";
        release_target();
        return false;
      }
      width_ = width;
      height_ = height;
    }
    fbo_.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);  // the renderer draws into whatever is bound
    return true;
  }

  render::GetProcFn proc_loader() const override { return egl_get_proc; }

  bool read_pixels(std::vector<std::uint8_t>* rgba, std::string* err) override {
    if (!gl_loaded_ || framebuffer_ == 0) {
      if (err) *err = "no current EGL context";
      return false;
    }
    fbo_.BindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
    read_top_down(gl_, width_, height_, &scratch_, rgba);
    return true;
  }

  int width() const override { return width_; }
  int height() const override { return height_; }

  std::string description() const override {
    if (!gl_loaded_) return "EGL (" + platform_ + ", not current)";
    auto str = [&](GLenum e) {
      const GLubyte* s = gl_.GetString(e);
      return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
    };
    return "EGL (" + platform_ + "), OpenGL " + str(GL_VERSION) + ", " + str(GL_RENDERER);
  }

 private:
  void release_target() {
    if (framebuffer_ != 0) fbo_.DeleteFramebuffers(1, &framebuffer_);
    if (renderbuffers_[0] != 0) fbo_.DeleteRenderbuffers(2, renderbuffers_);
    framebuffer_ = 0;
    renderbuffers_[0] = renderbuffers_[1] = 0;
    width_ = height_ = 0;
  }

  EGLDisplay display_;
  EGLContext context_;
  std::string platform_;
  render::GlApi gl_;  // what readback needs; the renderer loads its own table
  FboApi fbo_;
  bool gl_loaded_ = false;
  GLuint framebuffer_ = 0, renderbuffers_[2] = {0, 0};
  int width_ = 0, height_ = 0;
  std::vector<std::uint8_t> scratch_;
};

/// A display of Mesa's surfaceless platform, else of the first EGL device; *platform names it.
EGLDisplay open_display(std::string* platform, std::string* err) {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  auto get_display = load<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  if (get_display == nullptr || !has_extension(client, "EGL_EXT_platform_base")) {
    *err = "EGL has no eglGetPlatformDisplayEXT (EGL_EXT_platform_base)";
    return EGL_NO_DISPLAY;
  }
  if (has_extension(client, "EGL_MESA_platform_surfaceless")) {
    EGLDisplay d = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) {
      *platform = "surfaceless";
      return d;
    }
  }
  if (has_extension(client, "EGL_EXT_platform_device")) {
    auto query_devices = load<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
    EGLDeviceEXT devices[8];
    EGLint count = 0;
    if (query_devices && query_devices(8, devices, &count) && count > 0) {
      for (EGLint k = 0; k < count; ++k) {
        EGLDisplay d = get_display(EGL_PLATFORM_DEVICE_EXT, devices[k], nullptr);
        if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) {
          *platform = "device " + std::to_string(k);
          return d;
        }
      }
    }
  }
  *err = "neither EGL_MESA_platform_surfaceless nor an EGL_EXT_platform_device display could be initialised (" +
         egl_error("eglInitialize") + ")";
  return EGL_NO_DISPLAY;
}

}  // namespace

std::unique_ptr<OffscreenContext> create_egl_context(std::string* err) {
  std::string platform, why;
  EGLDisplay display = open_display(&platform, &why);
  if (display == EGL_NO_DISPLAY) {
    if (err) *err = why;
    return nullptr;
  }
  auto fail = [&](const std::string& msg) -> std::unique_ptr<OffscreenContext> {
    if (err) *err = msg;
    return nullptr;
  };
  if (!eglBindAPI(EGL_OPENGL_API)) return fail(egl_error("eglBindAPI(EGL_OPENGL_API)"));
  EGLConfig config = nullptr;
  if (!has_extension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_no_config_context")) {
    const EGLint want[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLint n = 0;
    if (!eglChooseConfig(display, want, &config, 1, &n) || n < 1) return fail(egl_error("eglChooseConfig"));
  }
  const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                            EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, attribs);
  if (context == EGL_NO_CONTEXT) return fail(egl_error("eglCreateContext (OpenGL 3.3 core)"));
  return std::make_unique<EglContext>(display, context, platform);
}

}  // namespace sph::cli
