// What the viewer chose: field and colour map, value range, cameras, particle size, text size, which
// overlays (walls, outlines, exact curves) and, in 2D, the plane or a profile against x or y.
// Plain values with defaults; the GUI edits its own copy, the headless program fills one from flags.
#pragma once
#include <string>
#include <vector>

namespace sph::render {

/// 2D view: orthographic, equal aspect.
struct Camera2D {
  bool fit = true;                  ///< centre on the snapshot's bounds (ignore center_x/y)
  float center_x = 0.f, center_y = 0.f;  ///< view centre when !fit [world units]
  float zoom = 1.f;                 ///< 1 = the bounds fill the plot; 2 = twice as close
};

/// 3D view: perspective orbit around the centre of the bounds.
struct OrbitCamera {
  float yaw_deg = 35.f;    ///< rotation about the up axis [degrees]
  float pitch_deg = 25.f;  ///< elevation above the horizontal plane [degrees], |pitch| < 90
  float distance = 0.f;    ///< eye to centre [world units]; 0 = fit the bounds into the view
  float zoom = 1.f;        ///< divides the (fitted or given) distance
  float fov_deg = 35.f;    ///< vertical field of view [degrees]
  int up_axis = 2;         ///< 0 = x, 1 = y, 2 = z points up on screen
};

enum class SizeMode {
  Smoothing,  ///< radius = h_scale * h [world units] (never under min_radius_px)
  Pixels,     ///< radius = point_px [px]
};

struct ViewSettings {
  std::string color_by = "rho";  ///< SnapshotField::name shown by colour (and on the y axis in 1D)
  std::string cmap = "viridis";  ///< viridis, magma, cividis, coolwarm
  bool auto_range = true;        ///< per frame: the field's percentiles below; else [range_min, range_max]
  /// Auto range between these percentiles of the fluid's finite values: 0, 100 = min/max; the GUI's
  /// default 1, 99 keeps one outlier from squeezing every other particle into one colour.
  float percentile_lo = 0.f, percentile_hi = 100.f;
  float range_min = 0.f, range_max = 1.f;  ///< fixed range [field units] (log10 of them with log_scale)
  bool show_trails = true;       ///< few-body 2D scenes: draw each particle's path so far (sph::TrailLog)
  bool log_scale = false;        ///< colour (and profile axis) by log10 of the field; values <= 0 are not drawn
  /// Plane and 3D views with an auto range: colour by log10 when the field is positive and spans more than
  /// two decades between its 1st and 99th percentiles (render::spans_decades); profiles keep their axis.
  bool auto_log = true;

  Camera2D camera2d;
  OrbitCamera orbit;

  SizeMode size_mode = SizeMode::Smoothing;
  float h_scale = 0.5f;        ///< disc radius / h in Smoothing mode (0.5 h ~ spacing/2 for h ~ 1.2 dx)
  float point_px = 3.f;        ///< radius in Pixels mode, and of the 1D profile dots [px]
  float min_radius_px = 1.f;   ///< smallest disc drawn [px]

  bool show_exact = true;      ///< profiles: draw the exact/reference curve when the snapshot has one
  /// Profiles with an exact curve: under each panel a strip of each run's values minus the exact ones
  /// (profile_residual.h); a comparison (A/B) always has it.
  bool residuals = false;
  bool high_contrast = false;  ///< white-on-black chrome (palette::kHighContrast): axes, labels, legends
  bool show_walls = true;      ///< 2D/3D: draw wall particles (in palette::kWall); profiles never show them
  bool show_tree = true;       ///< 2D/3D: draw the snapshot's Barnes-Hut cells (render::add_tree_overlay) when it has them
  bool show_outlines = true;   ///< 2D: draw the snapshot's reference outlines over the particles
  int profile_axis = -1;       ///< 2D: -1 = the plane view; 0 / 1 = profile of the field against x / y
  /// 3D cutaway: -1 none; 0, 1, 2: only the particles with x, y or z <= cut_at are drawn (the inside shows)
  int cut_axis = -1;
  float cut_at = 0.f;          ///< [length]
  int text_scale = 0;          ///< integer pixel scale of the 13 px font; 0 = from the frame height
  /// Profiles: one panel per field, e.g. {"rho", "v", "p", "u"} as the seed documents show shock tubes
  /// ("v" is v_x in 1D, |v| otherwise); empty: the colour-by field alone.
  std::vector<std::string> panels;
};

}  // namespace sph::render
