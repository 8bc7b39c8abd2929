// The renderer shared by the GUI and the headless program: draws one sph::Snapshot into the
// currently bound framebuffer with OpenGL 3.3 core, loaded through a get_proc_address seam.
//
//   dim 1: profile plot (x against the field) with the exact curve drawn over the particles;
//   dim 2: discs in an equal-aspect axes box with the reference outlines over them, or (ViewSettings::
//          profile_axis) a profile of the field against x or y;  dim 3: lit spheres under an orbit camera.
//   Wall particles are grey (palette::kWall) in 2D and 3D, whatever the field, and left out of profiles.
//   Always: a title row (scene, time, step) and a colour bar with the field label and range.
//
// Use from the thread that owns the GL context; destroy (or shutdown()) while it is current.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "frame_layout.h"
#include "frame_scene.h"
#include "gl_api.h"
#include "particle_path.h"
#include "text_batch.h"
#include "view_settings.h"

namespace sph {
struct Snapshot;
}

namespace sph::render {

struct FrameBuild;
struct ShownField;

class Renderer {
 public:
  Renderer();
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  /// Loads GL, compiles the shaders, builds the font. False with *err if anything is missing.
  bool init(GetProcFn get_proc, std::string* err);
  /// Frees the GL objects (needs the context current). Called by the destructor if not done yet.
  void shutdown();
  bool initialized() const;

  /// Draws the snapshot into a width x height frame of the bound framebuffer (viewport origin 0,0).
  /// A colour-by field missing from the snapshot falls back to the first field, with a warning in the
  /// title row (see missing_field_message in field_range.h to report it elsewhere).
  void render(const sph::Snapshot& snap, const ViewSettings& view, int width, int height);
  /// The same for a FrameScene: one run, or the two of a comparison (profiles: both runs' dots in two
  /// colours with their L1 errors in the legend; 2D: A, B and the difference map B - A; 3D: A and B),
  /// with ViewSettings::panels (profiles: one panel per field) and the inspector's highlight.
  void render(const FrameScene& scene, const ViewSettings& view, int width, int height);
  /// The particle the last frame drew nearest to pixel (px, py) of the frame (top-left origin), if one
  /// is within max_px: picking with the mouse.
  std::optional<Picked> pick(float px, float py, float max_px) const;
  /// Where the last frame drew particle `index` of run 0 (A) or 1 (B) [frame px]; nullopt if nowhere.
  std::optional<std::array<float, 2>> pixel_of(int run, std::uint32_t index) const;

  /// Chooses how particles are drawn (default Auto: on the CPU for software GL). Both give the same
  /// picture to within a few 1/255 at antialiased edges.
  void set_particle_path(ParticlePath path);
  /// True if particles are currently splatted on the CPU (after init).
  bool particles_on_cpu() const;

  /// Where the last frame put its plot and colour bar, and its plot -> pixel mapping.
  const FrameLayout& last_layout() const;
  /// Every line of text the last frame drew, with its box (layout checks: text_layout.h).
  const std::vector<TextSpan>& last_texts() const;
  /// The loaded GL table (for readback and error checks by the caller).
  const GlApi& gl() const;

 private:
  struct Impl;
  /// CPU: layout, overlay geometry, particle instances.
  static void compose(FrameBuild& f, const FrameScene& scene, const ViewSettings& view, const ShownField& shown,
                      int width, int height);
  /// GL: clears, overlay under the particles, particles, overlay over them, text.
  static void draw(Impl& d, const ShownField& shown, int width, int height);

  std::unique_ptr<Impl> impl_;
};

}  // namespace sph::render
