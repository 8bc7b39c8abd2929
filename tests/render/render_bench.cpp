// Frame-time benchmark at 1280x720 for 10k and 100k particles in 2D and 3D (pseudo-random positions:
// the hardest case for caches and for PNG compression). Per case: render + readback with the chosen
// particle path and with GPU quads for comparison, PNG write, their sum, and the frame period of
// FrameRecorder, which compresses each PNG on a background thread while the next frame renders.
// Prints a markdown table. Run by hand: sph_render_bench [frames per case] [output dir].
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "frame_recorder.h"
#include "synthetic_snapshots.h"

namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

int fail(const std::string& err) {
  std::fprintf(stderr, "sph_render_bench: %s\n", err.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  namespace cli = sph::cli;
  using sph::render::ParticlePath;
  const int frames = argc > 1 ? std::max(1, std::atoi(argv[1])) : 10;
  const std::filesystem::path dir = argc > 2 ? argv[2] : (std::filesystem::temp_directory_path() / "sph_render_bench");
  std::filesystem::create_directories(dir);
  constexpr int kW = 1280, kH = 720;

  std::string err;
  auto renderer = cli::OffscreenRenderer::create(&err);
  if (!renderer) return fail(err);
  std::printf("%s, %dx%d, median of %d frames\n", renderer->description().c_str(), kW, kH, frames);
  if (std::FILE* f = std::fopen("/proc/loadavg", "r")) {  // timings on a busy machine read high
    char load[64] = {};
    if (std::fgets(load, sizeof load, f)) std::printf("load average at start: %s", load);
    std::fclose(f);
  }
  const char* path_name = renderer->renderer().particles_on_cpu() ? "CPU splat" : "GPU quads";
  std::printf("\n| dim | particles | render + readback, %s [ms] | same, GPU quads [ms] | PNG write [ms] | sum [ms] "
              "| FrameRecorder period [ms] |\n", path_name);
  std::printf("|----:|----------:|----:|----:|----:|----:|----:|\n");

  std::vector<std::uint8_t> rgba;
  const sph::render::ViewSettings view;
  auto time_render = [&](const sph::Snapshot& snap, std::vector<double>* ms) {
    renderer->render(snap, view, kW, kH, &rgba, &err);  // warm-up (shader variants, buffer sizes)
    for (int f = 0; f < frames; ++f) {
      const auto t0 = Clock::now();
      if (!renderer->render(snap, view, kW, kH, &rgba, &err)) return false;
      ms->push_back(ms_since(t0));
    }
    return true;
  };
  for (int dim : {2, 3})
    for (int n : {10000, 100000}) {
      const sph::Snapshot snap = sph::render::test::random_cloud(dim, n);
      const std::string tag = std::to_string(dim) + "d_" + std::to_string(n);
      std::vector<double> gpu_ms, render_ms, png_ms;
      renderer->renderer().set_particle_path(ParticlePath::Gpu);
      if (!time_render(snap, &gpu_ms)) return fail(err);
      renderer->renderer().set_particle_path(ParticlePath::Auto);
      if (!time_render(snap, &render_ms)) return fail(err);
      for (int f = 0; f < frames; ++f) {
        const auto t0 = Clock::now();
        if (!cli::write_png((dir / ("bench_" + tag + ".png")).string(), kW, kH, rgba, &err)) return fail(err);
        png_ms.push_back(ms_since(t0));
      }
      // FrameRecorder: frames back to back, PNGs compressed in the background.
      cli::FrameOptions o;
      o.dir = (dir / ("recorder_" + tag)).string();
      auto rec = cli::FrameRecorder::create(o, &err);
      if (!rec || !rec->write_frame(snap, &err) || !rec->flush(&err)) return fail(err);  // warm-up
      const auto t0 = Clock::now();
      for (int f = 0; f < frames; ++f)
        if (!rec->write_frame(snap, &err)) return fail(err);
      if (!rec->flush(&err)) return fail(err);
      const double period = ms_since(t0) / frames;
      std::printf("| %dD | %d | %.1f | %.1f | %.1f | %.1f | %.1f |\n", dim, n, median(render_ms), median(gpu_ms),
                  median(png_ms), median(render_ms) + median(png_ms), period);
    }
  std::printf("\nframes written to %s\n", dir.c_str());
  return 0;
}
