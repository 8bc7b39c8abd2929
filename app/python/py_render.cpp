// A frame of the world through the shared renderer (the one `sph run --frames` and sph-gui draw with), in
// an off-screen OpenGL context, returned as a NumPy RGBA image (height, width, 4) of uint8, rows top-down.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <stdexcept>

#include "py_bindings.h"
#include "sph/report.h"
#ifdef SPH_HAVE_FRAMES
#include "colormap.h"
#include "field_range.h"
#include "offscreen_renderer.h"
#endif

namespace sph::py {
namespace {

namespace pyb = pybind11;

#ifdef SPH_HAVE_FRAMES
/// What the caller chose beside the field: colour map, range, log scale, walls, 3D cutaway and orbit.
struct Choices {
  std::string cmap;
  std::optional<std::pair<float, float>> range;
  std::optional<bool> log;
  bool walls = true;
  std::optional<std::string> cut;  ///< "z=0.1": only particles with z <= 0.1 (3D)
  float yaw = 35.f, pitch = 25.f;  ///< the orbit camera [degrees] (3D)
};

/// "z=0.1" -> axis 2 at 0.1 (sph run --cut's syntax); ValueError otherwise.
void set_cut(render::ViewSettings& v, const std::string& cut) {
  const auto eq = cut.find('=');
  const std::string axes = "xyz";
  if (eq != 1 || axes.find(cut[0]) == std::string::npos)
    throw pyb::value_error("render: cut '" + cut + "': expected x=VALUE, y=VALUE or z=VALUE");
  try {
    std::size_t used = 0;
    v.cut_at = std::stof(cut.substr(2), &used);
    if (used != cut.size() - 2) throw std::invalid_argument(cut);
  } catch (const std::exception&) {
    throw pyb::value_error("render: cut '" + cut + "': expected x=VALUE, y=VALUE or z=VALUE");
  }
  v.cut_axis = static_cast<int>(axes.find(cut[0]));
}

/// The view of `sph run --frames` (the same defaults) with the caller's choices; ValueError names a bad one.
render::ViewSettings view_of(const sph::Snapshot& snap, const std::string& color_by, const Choices& c) {
  const std::string& cmap = c.cmap;
  const auto& range = c.range;
  const auto& log = c.log;
  if (!snap.find(color_by)) throw pyb::value_error("render: color_by: " + render::missing_field_message(snap, color_by));
  const auto names = render::colormap_names();
  if (std::find(names.begin(), names.end(), cmap) == names.end())
    throw pyb::value_error("render: cmap '" + cmap + "': expected viridis, magma, cividis or coolwarm");
  render::ViewSettings v;
  v.color_by = color_by;
  v.cmap = cmap;
  if (range) {
    if (!(range->first < range->second)) throw pyb::value_error("render: range: expected (min, max) with min < max");
    v.auto_range = false;
    v.range_min = range->first;
    v.range_max = range->second;
  }
  if (log) {
    v.log_scale = *log;
    v.auto_log = false;
  }
  v.show_walls = c.walls;
  if (c.cut) set_cut(v, *c.cut);
  if (!(std::abs(c.pitch) < 90.f)) throw pyb::value_error("render: pitch: expected -90 < pitch < 90 degrees");
  v.orbit.yaw_deg = c.yaw;
  v.orbit.pitch_deg = c.pitch;
  return v;
}
#endif

pyb::array_t<std::uint8_t> render_frame(PyWorld& w, int width, int height, const std::string& color_by,
                                        const Choices& c) {
  if (width < 16 || height < 16 || width > 8192 || height > 8192)
    throw pyb::value_error("render: width and height: expected 16 ... 8192 pixels");
#ifdef SPH_HAVE_FRAMES
  const sph::Snapshot snap = w.world().report().snapshot();
  const render::ViewSettings view = view_of(snap, color_by, c);
  std::vector<std::uint8_t> rgba;
  std::string err;
  if (!w.renderer().render(snap, view, width, height, &rgba, &err)) throw std::runtime_error("render: " + err);
  pyb::array_t<std::uint8_t> img({height, width, 4});
  std::memcpy(img.mutable_data(), rgba.data(), rgba.size());
  return img;
#else
  (void)w, (void)color_by, (void)c;
  throw std::runtime_error("render: this build has no headless renderer (SPH_BUILD_HEADLESS_RENDER=OFF)");
#endif
}

}  // namespace

void bind_render(WorldClass& cls) {
  cls.def(
      "render",
      [](PyWorld& w, int width, int height, const std::string& color_by, const std::string& cmap,
         std::optional<std::pair<float, float>> range, std::optional<bool> log, bool walls,
         std::optional<std::string> cut, float yaw, float pitch) {
        return render_frame(w, width, height, color_by, Choices{cmap, range, log, walls, cut, yaw, pitch});
      },
      pyb::arg("width") = 1280, pyb::arg("height") = 720, pyb::arg("color_by") = "rho", pyb::arg("cmap") = "viridis",
      pyb::arg("range") = std::nullopt, pyb::arg("log") = std::nullopt, pyb::arg("walls") = true,
      pyb::arg("cut") = std::nullopt, pyb::arg("yaw") = 35.f, pyb::arg("pitch") = 25.f,
      "The world now as `sph run --frames` draws it (1D profiles, 2D discs, 3D shaded spheres, colour bar,\n"
      "time), as a (height, width, 4) uint8 RGBA array. range: (min, max), else automatic; log: True/False,\n"
      "else automatic (over two decades); cut: 'z=0.1' shows only z <= 0.1 (3D); yaw, pitch: the 3D orbit\n"
      "camera [degrees]. The off-screen context (SPH_GL: osmesa, egl, auto) is made once per world.");
}

}  // namespace sph::py
