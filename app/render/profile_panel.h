// One profile panel: its runs' dots (a field against a coordinate) on axes fitted to them, the exact curve
// over them and a legend kept off both. profile_view.cpp lays out the panels of a frame.
#pragma once
#include <string>
#include <vector>

#include "frame_build.h"
#include "sph/snapshot.h"
#include "view_settings.h"

namespace sph::render {

/// One run's dots in a panel.
struct ProfileRun {
  const sph::Snapshot* snap = nullptr;
  int run = 0;
  std::vector<float> y;                  ///< plotted values, one per snapshot particle
  const sph::SnapshotField* colour = nullptr;  ///< colour-mapped field; nullptr: drawn in `solid`
  Rgba solid;
  std::string legend;                    ///< its legend row ("" for none)
  float dot_scale = 1.f;                 ///< < 1: smaller dots, drawn over the runs before it
};

/// A panel: its area, titles, runs, exact curve and vertical limits.
struct ProfilePanel {
  PixelRect area;
  std::string y_title, x_title;
  std::vector<ProfileRun> runs;
  sph::ExactCurve curve;  ///< empty: none
  Rgba curve_color;
  std::string curve_label;
  bool fixed = false;     ///< y limits [y0, y1] as given
  double y0 = 0.0, y1 = 1.0;
  int legend_scale = 0;   ///< > 0: the legend's text scale (small panels)
  float y_label_min = 0.f;  ///< the y labels' column at least this wide [px]: stacked panels share their x axis
  bool x_labels = true;     ///< false: no x tick labels or title (the panel under it has them)
  /// Non-empty: its residual strip shows each later run minus the first (1D runs), under this title
  /// ("B - A"); empty: each run minus the exact curve.
  std::string versus_first;
};

/// The exact curve of `field` along `axis` (log10 of its positive values when `log`), or an empty one.
sph::ExactCurve curve_of(const sph::Snapshot& snap, const std::string& field, int axis, bool log);

/// The width [px] of the panel's y labels at its area (compose_panel's own measure).
float panel_label_width(const FrameBuild& f, const ProfilePanel& p, int axis);

/// Draws one panel. primary: its first run becomes the frame's primary particles (f.instances in
/// layout.plot); otherwise every run is a batch of its own.
void compose_panel(FrameBuild& f, const ProfilePanel& p, const ViewSettings& view, const ShownField& shown, int axis,
                   bool primary);

}  // namespace sph::render
