#include "cli_converge.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "cli_common.h"
#include "sph/output_manifest.h"
#include "exit_codes.h"
#include "sph/convergence.h"
#include "sph/world.h"
#ifdef SPH_HAVE_FRAMES
#include "frame_recorder.h"
#endif

namespace sph::cli {
namespace {

#ifdef SPH_HAVE_FRAMES
/// log10 e against log10 h as a 1D profile: the runs as points, the fitted line as the exact curve.
Snapshot plot_of(const ConvergenceResult& r) {
  Snapshot s;
  s.scene = "converge";
  s.dim = 1;
  s.count = r.runs.size();
  SnapshotField f{"log10_e", "log10 " + r.column, {}, 0.f, 0.f};
  float x_lo = 1e30f, x_hi = -1e30f;
  for (const ConvergenceRun& run : r.runs) {
    const float x = static_cast<float>(std::log10(run.h)), y = static_cast<float>(std::log10(run.error));
    s.x.push_back(x);
    s.y.push_back(0.f);
    s.z.push_back(0.f);
    s.h.push_back(0.f);
    f.values.push_back(y);
    x_lo = std::min(x_lo, x);
    x_hi = std::max(x_hi, x);
  }
  f.min = *std::min_element(f.values.begin(), f.values.end());
  f.max = *std::max_element(f.values.begin(), f.values.end());
  // the least-squares line through the points: log e = c + slope log h
  double mx = 0, my = 0;
  for (std::size_t k = 0; k < s.count; ++k) { mx += s.x[k]; my += f.values[k]; }
  mx /= static_cast<double>(s.count);
  my /= static_cast<double>(s.count);
  ExactCurve line{"log10_e", {}, {}, 0};
  const float pad = 0.05f * (x_hi - x_lo);
  for (float x : {x_lo - pad, x_hi + pad}) {
    line.x.push_back(x);
    line.value.push_back(static_cast<float>(my + r.slope * (x - mx)));
  }
  s.fields.push_back(std::move(f));
  s.exact.push_back(std::move(line));
  s.bounds = {x_lo - pad, x_hi + pad, 0, 1, 0, 1};
  char title[256];
  std::snprintf(title, sizeof title, "convergence of %s: %s at t = %g against %s, fitted slope %.3f", r.scene.c_str(),
                r.column.c_str(), r.t, r.key.c_str(), r.slope);
  s.title = title;
  s.x_label = "log10 " + r.step_name() + " (" + r.step_meaning() + ")";  // not "h": the smoothing length
  s.points_label = "runs";
  s.curve_label = "least-squares fit";
  return s;
}
#endif

}  // namespace

int converge_command(const ConvergeOptions& opt) {
  RunConfig base;
  ConvergenceStudy study;
  try {
    base = RunConfig::load(opt.scene);
    apply_sets(base, opt.sets);
    base.validate();
    study.key = opt.key;
    study.values = parse_number_list(opt.values, "--values");
    study.t = opt.until;
    study.column = opt.column;
    study = resolve_study(base, study);
  } catch (const ConfigError& e) {
    std::fprintf(stderr, "sph: converge: %s\n", e.what());
    return kInvalidScene;
  }
  int width = 0, height = 0;
  if (!parse_plot_size(opt.size, &width, &height)) return kUsage;
  const std::filesystem::path dir = opt.out.empty() ? "converge_" + base.scene->name : opt.out;
  bool existed = false;
  if (!make_output_dir(dir, &existed)) {
    std::fprintf(stderr, "sph: --out %s: cannot create the directory\n", dir.string().c_str());
    return kIoError;
  }
  if (opt.threads > 0) omp_set_num_threads(opt.threads);
  ConvergenceResult r;
  const int rc = guarded_runs("converge", dir, existed, [&] {
    r = run_convergence(base, study, [&](const ConvergenceRun& run) {
      if (!opt.quiet)
        std::fprintf(stderr, "  %s = %g: %s = %.6g (%lld steps, %.2f s)\n", study.key.c_str(), run.value,
                     study.column.c_str(), run.error, static_cast<long long>(run.steps), run.wall_s);
    });
  });
  if (rc != kOk) return rc;
  const std::string md = convergence_markdown(r);
  OutputManifest manifest(dir);
  std::string io_err = manifest.write("converge.csv", convergence_csv(r, opt.csv_comments));
  if (io_err.empty()) io_err = manifest.write("converge.md", md);
  if (!io_err.empty()) {
    std::fprintf(stderr, "sph: I/O error: %s\n", io_err.c_str());
    return kIoError;
  }
#ifdef SPH_HAVE_FRAMES
  std::vector<std::uint8_t> rgba;
  std::string err;
  render::ViewSettings view;
  view.color_by = "log10_e";
  view.point_px = 6.f;
  const std::string png = (dir / "converge.png").string();
  if (!render_snapshot_rgba(plot_of(r), view, width, height, &rgba, &err) || !write_png(png, width, height, rgba, &err, &manifest)) {
    std::fprintf(stderr, "sph: %s: %s\n", png.c_str(), err.c_str());
    return kIoError;
  }
#endif
  if (!opt.quiet) std::printf("%s\nwritten to %s\n", md.c_str(), dir.string().c_str());
  return kOk;
}

}  // namespace sph::cli
