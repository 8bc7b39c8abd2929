#include "view_target.h"

#include <cstring>

#include "gui_gl.h"

namespace sph::gui {
namespace {

/// GL rows are bottom-up; images are top-down.
void flip_rows(std::vector<std::uint8_t>* rgba, int width, int height) {
  const std::size_t row = static_cast<std::size_t>(width) * 4;
  std::vector<std::uint8_t> tmp(row);
  for (int y = 0; y < height / 2; ++y) {
    std::uint8_t* a = rgba->data() + static_cast<std::size_t>(y) * row;
    std::uint8_t* b = rgba->data() + static_cast<std::size_t>(height - 1 - y) * row;
    std::memcpy(tmp.data(), a, row);
    std::memcpy(a, b, row);
    std::memcpy(b, tmp.data(), row);
  }
}

void read_bound(int width, int height, std::vector<std::uint8_t>* rgba) {
  rgba->resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba->data());
  flip_rows(rgba, width, height);
}

}  // namespace

ViewTarget::~ViewTarget() { release(); }

void ViewTarget::release() {
  if (fbo_) glDeleteFramebuffers(1, &fbo_);
  if (color_) glDeleteTextures(1, &color_);
  if (depth_) glDeleteRenderbuffers(1, &depth_);
  fbo_ = color_ = depth_ = 0;
  width_ = height_ = 0;
}

bool ViewTarget::resize(int width, int height, std::string* err) {
  if (width == width_ && height == height_ && fbo_) return true;
  release();
  glGenTextures(1, &color_);
  glBindTexture(GL_TEXTURE_2D, color_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, 0);
  glGenRenderbuffers(1, &depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    release();
    *err = "off-screen view target incomplete (status " + std::to_string(status) + ")";
    return false;
  }
  width_ = width;
  height_ = height;
  return true;
}

void ViewTarget::bind() const { glBindFramebuffer(GL_FRAMEBUFFER, fbo_); }

void ViewTarget::unbind() { glBindFramebuffer(GL_FRAMEBUFFER, 0); }

void ViewTarget::finish() { glFinish(); }

void ViewTarget::blit_to_window(int x, int y, int window_height) const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  const int y0 = window_height - y - height_;  // GL's origin is bottom-left
  glBlitFramebuffer(0, 0, width_, height_, x, y0, x + width_, y0 + height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void ViewTarget::read_rgba(std::vector<std::uint8_t>* rgba) const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  read_bound(width_, height_, rgba);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void read_window_rgba(int width, int height, std::vector<std::uint8_t>* rgba) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  read_bound(width, height, rgba);
}

}  // namespace sph::gui
