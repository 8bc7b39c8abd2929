#include "particle_pass.h"

#include <cstdint>
#include <string_view>

namespace sph::render {

namespace {
bool is_software_renderer(const GlApi& gl) {
  const GLubyte* s = gl.GetString(GL_RENDERER);
  if (s == nullptr) return false;
  const std::string_view name(reinterpret_cast<const char*>(s));
  return name.find("llvmpipe") != std::string_view::npos || name.find("softpipe") != std::string_view::npos ||
         name.find("swrast") != std::string_view::npos;
}
}  // namespace

bool ParticlePass::init(const GlApi& gl, std::string* err) {
  if (!flat_.build(gl, "particles.vert", "particles.frag", "", err)) return false;
  if (!shaded_.build(gl, "particles.vert", "particles.frag", "#define SPH_SHADED 1\n", err)) return false;
  if (!image_.build(gl, "image.vert", "image.frag", "", err)) return false;
  software_gl_ = is_software_renderer(gl);

  gl.GenVertexArrays(1, &vao_);
  gl.GenBuffers(1, &vbo_);
  gl.BindVertexArray(vao_);
  gl.BindBuffer(GL_ARRAY_BUFFER, vbo_);
  const GLsizei stride = kInstanceFloats * sizeof(float);
  // location 0: centre (3 floats), 1: radius, 2: value, 3: wall flag; one step per instance.
  const GLint sizes[4] = {3, 1, 1, 1};
  const std::uintptr_t offsets[4] = {0, 3 * sizeof(float), 4 * sizeof(float), 5 * sizeof(float)};
  for (GLuint loc = 0; loc < 4; ++loc) {
    gl.EnableVertexAttribArray(loc);
    gl.VertexAttribPointer(loc, sizes[loc], GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offsets[loc]));
    gl.VertexAttribDivisor(loc, 1);
  }
  gl.BindVertexArray(0);

  gl.GenTextures(1, &cmap_tex_);
  gl.BindTexture(GL_TEXTURE_1D, cmap_tex_);
  gl.TexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  gl.TexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  gl.TexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl.BindTexture(GL_TEXTURE_1D, 0);

  gl.GenVertexArrays(1, &image_vao_);
  gl.GenTextures(1, &image_tex_);
  gl.BindTexture(GL_TEXTURE_2D, image_tex_);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  gl.BindTexture(GL_TEXTURE_2D, 0);
  return true;
}

void ParticlePass::destroy(const GlApi& gl) {
  flat_.destroy(gl);
  shaded_.destroy(gl);
  image_.destroy(gl);
  if (vbo_) gl.DeleteBuffers(1, &vbo_);
  if (vao_) gl.DeleteVertexArrays(1, &vao_);
  if (image_vao_) gl.DeleteVertexArrays(1, &image_vao_);
  if (cmap_tex_) gl.DeleteTextures(1, &cmap_tex_);
  if (image_tex_) gl.DeleteTextures(1, &image_tex_);
  vbo_ = vao_ = image_vao_ = cmap_tex_ = image_tex_ = 0;
  cmap_loaded_ = -1;
}

void ParticlePass::upload_colormap(const GlApi& gl, Colormap cmap) {
  if (cmap_loaded_ == static_cast<int>(cmap)) return;
  const ColormapLut& lut = colormap_lut(cmap);
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl.TexImage1D(GL_TEXTURE_1D, 0, GL_RGBA8, kColormapLutSize, 0, GL_RGBA, GL_UNSIGNED_BYTE, lut.data());
  cmap_loaded_ = static_cast<int>(cmap);
}

void ParticlePass::draw(const GlApi& gl, const ParticleDraw& d, Colormap cmap, const ValueRange& range,
                        const FixedColors& colors) {
  if (d.instances->empty()) return;
  if (uses_cpu())
    draw_cpu(gl, d, cmap, range, colors);
  else
    draw_gpu(gl, d, cmap, range, colors);
}

void ParticlePass::draw_gpu(const GlApi& gl, const ParticleDraw& d, Colormap cmap, const ValueRange& range,
                            const FixedColors& colors) {
  const GlProgram& prog = d.shaded ? shaded_ : flat_;
  gl.UseProgram(prog.id());
  gl.ActiveTexture(GL_TEXTURE0);
  gl.BindTexture(GL_TEXTURE_1D, cmap_tex_);
  upload_colormap(gl, cmap);
  gl.Uniform1i(prog.uniform(gl, "u_cmap"), 0);
  gl.UniformMatrix4fv(prog.uniform(gl, "u_view"), 1, GL_FALSE, d.camera->view.m.data());
  gl.UniformMatrix4fv(prog.uniform(gl, "u_proj"), 1, GL_FALSE, d.camera->proj.m.data());
  gl.Uniform2f(prog.uniform(gl, "u_viewport"), d.width, d.height);
  gl.Uniform1f(prog.uniform(gl, "u_pixel_radius"), d.pixel_radius);
  gl.Uniform1f(prog.uniform(gl, "u_min_radius"), d.min_radius);
  gl.Uniform2f(prog.uniform(gl, "u_range"), range.min, range.max);
  const Rgba& bad = colors.invalid;
  const Rgba& wall = colors.wall;
  gl.Uniform4f(prog.uniform(gl, "u_invalid_color"), bad.r, bad.g, bad.b, bad.a);
  gl.Uniform4f(prog.uniform(gl, "u_wall_color"), wall.r, wall.g, wall.b, wall.a);

  gl.BindVertexArray(vao_);
  gl.BindBuffer(GL_ARRAY_BUFFER, vbo_);
  const std::vector<float>& instances = *d.instances;
  gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(instances.size() * sizeof(float)), instances.data(),
                GL_STREAM_DRAW);
  if (d.shaded) {
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LESS);
    gl.DepthMask(GL_TRUE);
    gl.Disable(GL_BLEND);
  }
  const GLsizei count = static_cast<GLsizei>(instances.size() / kInstanceFloats);
  gl.DrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, count);
  gl.Disable(GL_DEPTH_TEST);
  gl.Enable(GL_BLEND);
  gl.BindVertexArray(0);
  gl.BindTexture(GL_TEXTURE_1D, 0);
  gl.UseProgram(0);
}

void ParticlePass::draw_cpu(const GlApi& gl, const ParticleDraw& d, Colormap cmap, const ValueRange& range,
                            const FixedColors& colors) {
  SplatParams p;
  p.view = d.camera->view;
  p.proj = d.camera->proj;
  p.width = static_cast<int>(d.width);
  p.height = static_cast<int>(d.height);
  p.pixel_radius = d.pixel_radius;
  p.min_radius = d.min_radius;
  p.range = range;
  p.cmap = cmap;
  p.colors = colors;
  p.shaded = d.shaded;
  splat_particles(*d.instances, p, &splat_);

  gl.UseProgram(image_.id());
  gl.ActiveTexture(GL_TEXTURE0);
  gl.BindTexture(GL_TEXTURE_2D, image_tex_);
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, splat_.width, splat_.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                splat_.rgba.data());
  gl.Uniform1i(image_.uniform(gl, "u_image"), 0);
  // The image is premultiplied: composite with "over" for premultiplied colour.
  gl.BlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  gl.BindVertexArray(image_vao_);
  gl.DrawArrays(GL_TRIANGLES, 0, 3);  // one triangle covering the viewport
  gl.BindVertexArray(0);
  gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  gl.BindTexture(GL_TEXTURE_2D, 0);
  gl.UseProgram(0);
}

}  // namespace sph::render
