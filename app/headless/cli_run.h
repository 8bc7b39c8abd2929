// `sph run` and `sph check`.
#pragma once
#include <string>
#include <vector>

#include "cli_compare.h"

namespace sph::cli {

struct RunOptions {
  std::string scene;               ///< built-in name or JSON file
  std::vector<std::string> sets;   ///< key=value overrides, applied in order after the file
  double until = -1.0;             ///< end time override (< 0: the scene's t_end)
  std::string out;                 ///< output directory ("" = no files)
  int threads = 0;                 ///< OpenMP threads (0 = default)
  bool quiet = false;
  bool csv_comments = false;       ///< the '#' lines of earlier versions in the CSV files
  bool vtu = false, splash = false, hdf5 = false;  ///< the other particle formats (need --out)
  // frames (headless-render build only)
  std::string frames;              ///< frame directory ("" = no frames)
  double every = 0.1;              ///< simulated time between frames
  std::string size = "1280x720";
  std::string color_by;             ///< empty: rho where the scene has it, else its first field
  std::string cmap = "viridis";
  std::string range = "auto";
  bool log_scale = false;
  bool linear = false;              ///< --linear: no automatic log10 colour scale
  bool residuals = false;           ///< --residuals: profiles with a strip of the error against the exact curve
  bool high_contrast = false;       ///< --high-contrast: white-on-black axes, labels and legends (a projector)
  bool hide_walls = false;          ///< --hide-walls: 2D and 3D frames without the wall particles
  std::string cut;                  ///< --cut AXIS=VALUE: 3D cutaway (e.g. z=0), empty: none
  std::string profile_axis = "off";  ///< 2D scenes: "x" or "y" plots the field against that coordinate
  std::string video;
  int fps = 30;                    ///< frame rate of --video [frames/s]
  std::string gl;                  ///< --gl osmesa|egl|auto (empty: SPH_GL, else auto)
  long long tree_probe = -1;       ///< frames draw the Barnes-Hut walk of this particle (-1: none)
  std::string panels;              ///< profiles: comma-separated fields, one panel each ("rho,v,p,u")
  CompareOptions compare;          ///< run B of an A/B comparison (--compare, --compare-set)
  std::string sweep;               ///< --sweep KEY=V1,V2,...: run A beside one run per value (cli_sweep.h)
  double probe_every = 0.0;        ///< --probe-every: errors.csv rows at this interval of simulated time (0 = at each output)
  double checkpoint_every = 0.0;   ///< --checkpoint-every: simulated time between checkpoints (0 = none)
};

struct ResumePoint;  // run_checkpoint.h

/// `sph run`; with `resume`, continues the run a checkpoint holds (sph resume).
int run_command(const RunOptions& opt, const ResumePoint* resume = nullptr);
int check_command(const RunOptions& opt);
int list_command();

}  // namespace sph::cli
