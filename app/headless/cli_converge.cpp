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
#include "convergence_plot.h"
#include "frame_recorder.h"
#endif

namespace sph::cli {

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
  view.point_px = 7.f;  // the runs' dots
  const std::string png = (dir / "converge.png").string();
  if (!render_snapshot_rgba(convergence_plot(r), view, width, height, &rgba, &err) || !write_png(png, width, height, rgba, &err, &manifest)) {
    std::fprintf(stderr, "sph: %s: %s\n", png.c_str(), err.c_str());
    return kIoError;
  }
#endif
  if (!opt.quiet) std::printf("%s\nwritten to %s\n", md.c_str(), dir.string().c_str());
  return kOk;
}

}  // namespace sph::cli
