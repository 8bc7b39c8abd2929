// `sph bench`: speed against error for every scene with a reference (see cli_bench.h).
#include "cli_bench.h"

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

/// One curve of the plot: a scene's study with one kernel and one integrator.
struct Series {
  std::string kernel, integrator;
  RunConfig base;
  ConvergenceStudy study;
  ConvergenceResult result;
  std::string label() const { return kernel + " / " + integrator; }
};

struct SceneBench {
  std::string scene;
  std::vector<Series> series;
};

std::string short_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

/// Kernels are compared where the scene runs SPH sums; N-body and FPM scenes keep their own.
bool uses_kernels(const RunConfig& cfg) { return cfg.params.physics.density != DensityMode::None; }
/// DFSPH steps by its own symplectic Euler: --integrators does not apply.
bool uses_integrators(const RunConfig& cfg) { return cfg.params.physics.eos != EosType::Dfsph; }

std::string csv_text(const std::vector<SceneBench>& all, int threads, bool comment) {
  std::string s = comment ? "# sph bench: error at the study's time against wall time, " + std::to_string(threads) +
                                " threads; valid = 0 where the reference no longer applied\n"
                          : std::string();
  s += "scene,kernel,integrator,key,value,h,particles,column,error,valid,warnings,wall_s,steps\n";
  for (const SceneBench& b : all)
    for (const Series& se : b.series)
      for (const ConvergenceRun& r : se.result.runs)
        s += b.scene + "," + se.kernel + "," + se.integrator + "," + se.study.key + "," + short_text(r.value) + "," +
             short_text(r.h) + "," + std::to_string(r.particles) + "," + se.study.column + "," + short_text(r.error) +
             "," + (r.valid ? "1" : "0") + "," + std::to_string(r.warnings) + "," + short_text(r.wall_s) + "," +
             std::to_string(r.steps) + "\n";
  return s;
}

std::string markdown_text(const std::vector<SceneBench>& all, int threads) {
  std::string s;
  char buf[320];
  for (const SceneBench& b : all) {
    const Series& first = b.series.front();
    std::snprintf(buf, sizeof buf, "### `%s`: %s at t = %g against wall time (%d thread%s)\n\n", b.scene.c_str(),
                  first.study.column.c_str(), first.result.t, threads, threads == 1 ? "" : "s");
    s += buf;
    s += "| kernel / integrator | " + first.study.key + " | particles | " + first.study.column +
         " | order | wall [s] | steps |\n|---|---:|---:|---:|---:|---:|---:|\n";
    for (const Series& se : b.series)
      for (const ConvergenceRun& r : se.result.runs) {
        char order[32] = "-";
        if (!std::isnan(r.order)) std::snprintf(order, sizeof order, "%.2f", r.order);
        std::snprintf(buf, sizeof buf, "| %s | %g | %zu | %.4g%s | %s | %.3f | %lld |\n", se.label().c_str(), r.value,
                      r.particles, r.error, r.valid ? "" : " (reference no longer applies)", order, r.wall_s,
                      static_cast<long long>(r.steps));
        s += buf;
      }
    s += "\n";
  }
  return s;
}

#ifdef SPH_HAVE_FRAMES
/// log10 error against log10 wall time: each curve an outline through its runs, each run a dot of the
/// curve's colour (a one-vertex outline of the same label), one legend row per curve.
Snapshot plot_of(const SceneBench& b, int threads) {
  Snapshot s;
  s.scene = "bench";
  s.dim = 2;
  float x0 = 1e30f, x1 = -1e30f, y0 = 1e30f, y1 = -1e30f;
  for (const Series& se : b.series) {
    Outline line;
    line.label = se.label();
    for (const ConvergenceRun& r : se.result.runs) {
      if (!(r.error > 0.0) || !(r.wall_s > 0.0)) continue;
      const float x = static_cast<float>(std::log10(r.wall_s)), y = static_cast<float>(std::log10(r.error));
      line.x.push_back(x);
      line.y.push_back(y);
      s.outlines.push_back({line.label, {x}, {y}});
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
    s.outlines.push_back(std::move(line));
  }
  if (!(x1 >= x0)) x0 = y0 = 0.f, x1 = y1 = 1.f;
  const float px = 0.08f * std::max(0.5f, x1 - x0), py = 0.08f * std::max(0.5f, y1 - y0);
  s.bounds = {x0 - px, x1 + px, y0 - py, y1 + py, 0.f, 1.f};
  const Series& first = b.series.front();
  char title[256];
  std::snprintf(title, sizeof title, "work precision of %s: %s at t = %g against wall time (%s, %d thread%s)",
                b.scene.c_str(), first.study.column.c_str(), first.result.t, first.study.key.c_str(), threads,
                threads == 1 ? "" : "s");
  s.title = title;
  s.x_label = "log10 wall time [s]";
  s.y_label = "log10 " + first.study.column;
  return s;
}
#endif

}  // namespace

const std::vector<std::string>& default_bench_scenes() {
  static const std::vector<std::string> scenes = {"sod", "shocktube_castellanos", "toro3", "sedov"};
  return scenes;
}

int bench_command(const BenchOptions& opt) {
  const std::vector<std::string>& names = opt.scenes.empty() ? default_bench_scenes() : opt.scenes;
  std::vector<SceneBench> all;
  // everything is checked before the first run: a bad scene, key or value writes nothing
  try {
    const std::vector<double> values = parse_number_list(opt.values, "--values");
    const std::vector<std::string> integrators =
        opt.integrators.empty() ? std::vector<std::string>{"leapfrog", "rk4"} : split_names(opt.integrators);
    for (const std::string& name : names) {
      RunConfig cfg = RunConfig::load(name);
      apply_sets(cfg, opt.sets);
      cfg.validate();
      std::vector<std::string> kernels = split_names(opt.kernels);
      if (!uses_kernels(cfg)) kernels = {"-"};  // N-body and FPM scenes: --kernels does not apply
      else if (kernels.empty()) kernels = {"M4", "M6", "wendland_c2"};
      SceneBench b{cfg.scene->name, {}};
      const std::vector<std::string> steppers = uses_integrators(cfg) ? integrators : std::vector<std::string>{"dfsph"};
      for (const std::string& k : kernels)
        for (const std::string& integ : steppers) {
          Series se{k, integ, cfg, {}, {}};
          if (uses_kernels(cfg)) se.base.set("kernel.type", k, "--kernels");  // else the kernel is not a parameter
          if (uses_integrators(cfg)) se.base.set("time.integrator", integ, "--integrators");
          ConvergenceStudy asked;
          asked.values = values;
          se.study = resolve_study(se.base, asked);
          b.series.push_back(std::move(se));
        }
      all.push_back(std::move(b));
    }
  } catch (const ConfigError& e) {
    std::fprintf(stderr, "sph: bench: %s\n", e.what());
    return kInvalidScene;
  }
  int width = 0, height = 0;
  if (!parse_plot_size(opt.size, &width, &height)) return kUsage;
  const std::filesystem::path dir = opt.out;
  bool existed = false;
  if (!make_output_dir(dir, &existed)) {
    std::fprintf(stderr, "sph: --out %s: cannot create the directory\n", dir.string().c_str());
    return kIoError;
  }
  if (opt.threads > 0) omp_set_num_threads(opt.threads);
  const int threads = omp_get_max_threads();
  const int rc = guarded_runs("bench", dir, existed, [&] {
    for (SceneBench& b : all)
      for (Series& se : b.series)
        se.result = run_convergence(se.base, se.study, [&](const ConvergenceRun& r) {
          if (!opt.quiet)
            std::fprintf(stderr, "  %s %s: %s = %g: %s = %.4g in %.3f s (%lld steps)%s\n", b.scene.c_str(),
                         se.label().c_str(), se.study.key.c_str(), r.value, se.study.column.c_str(), r.error, r.wall_s,
                         static_cast<long long>(r.steps), r.valid ? "" : " [reference no longer applies]");
        });
  });
  if (rc != kOk) return rc;
  const std::string md = markdown_text(all, threads);
  OutputManifest manifest(dir);
  std::string io_err = manifest.write("bench.csv", csv_text(all, threads, opt.csv_comments));
  if (io_err.empty()) io_err = manifest.write("bench.md", md);
  if (!io_err.empty()) {
    std::fprintf(stderr, "sph: I/O error: %s\n", io_err.c_str());
    return kIoError;
  }
#ifdef SPH_HAVE_FRAMES
  for (const SceneBench& b : all) {
    std::vector<std::uint8_t> rgba;
    std::string err;
    render::ViewSettings view;
    view.point_px = 7.f;
    const std::string png = (dir / ("bench_" + b.scene + ".png")).string();
    if (!render_snapshot_rgba(plot_of(b, threads), view, width, height, &rgba, &err) ||
        !write_png(png, width, height, rgba, &err, &manifest)) {
      std::fprintf(stderr, "sph: %s: %s\n", png.c_str(), err.c_str());
      return kIoError;
    }
  }
#endif
  if (!opt.quiet) std::printf("%swritten to %s\n", md.c_str(), dir.string().c_str());
  return kOk;
}

}  // namespace sph::cli
