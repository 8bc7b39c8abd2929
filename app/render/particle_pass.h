// GL side of the particles: the colour-map texture, and either
//  - the GPU path: instance buffer + the flat (discs) and shaded (spheres) variants of
//    particles.vert/.frag, or
//  - the CPU path for software GL (llvmpipe): cpu_splat.h draws the particles into an image that is
//    drawn as one textured quad (image.vert/.frag). llvmpipe pays ~1 us per primitive: 100k particles
//    cost 300+ ms as quads, ~25 ms as a CPU splat (1280x720, 2 cores).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "colormap.h"
#include "cpu_splat.h"
#include "field_range.h"
#include "frame_build.h"
#include "gl_api.h"
#include "gl_program.h"
#include "particle_path.h"

namespace sph::render {

/// One set of particles to draw: the instances, their camera and the size of the viewport they go to.
struct ParticleDraw {
  const std::vector<float>* instances = nullptr;
  const CameraMatrices* camera = nullptr;
  float width = 0.f, height = 0.f;  ///< viewport [px]
  float pixel_radius = 0.f, min_radius = 1.f;
  bool shaded = false;
  /// The frame's primary set (FrameBuild::instances in layout.plot).
  static ParticleDraw primary(const FrameBuild& f) {
    return {&f.instances, &f.camera, f.layout.plot.w, f.layout.plot.h, f.pixel_radius, f.min_radius, f.shaded};
  }
  static ParticleDraw of(const ParticleBatch& b) {
    return {&b.instances, &b.camera, b.rect.w, b.rect.h, b.pixel_radius, b.min_radius, b.shaded};
  }
};

class ParticlePass {
 public:
  bool init(const GlApi& gl, std::string* err);
  void destroy(const GlApi& gl);
  void set_path(ParticlePath path) { path_ = path; }
  bool uses_cpu() const { return path_ == ParticlePath::Cpu || (path_ == ParticlePath::Auto && software_gl_); }

  /// Draws d's instances into the current viewport (which must be d.width x d.height). `colors.invalid`
  /// colours non-finite values (and every particle when no field is shown), `colors.wall` walls.
  void draw(const GlApi& gl, const ParticleDraw& d, Colormap cmap, const ValueRange& range, const FixedColors& colors);

 private:
  void draw_gpu(const GlApi& gl, const ParticleDraw& d, Colormap cmap, const ValueRange& range,
                const FixedColors& colors);
  void draw_cpu(const GlApi& gl, const ParticleDraw& d, Colormap cmap, const ValueRange& range,
                const FixedColors& colors);
  void upload_colormap(const GlApi& gl, Colormap cmap);

  GlProgram flat_, shaded_, image_;
  GLuint vao_ = 0, vbo_ = 0, cmap_tex_ = 0, image_tex_ = 0;
  GLuint image_vao_ = 0;  // no attributes: image.vert makes its vertices from gl_VertexID
  int cmap_loaded_ = -1;  // Colormap in the texture, -1 = none yet
  bool software_gl_ = false;
  ParticlePath path_ = ParticlePath::Auto;
  SplatImage splat_;  // CPU path target, reused between frames
};

}  // namespace sph::render
