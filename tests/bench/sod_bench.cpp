// Speed against error on the Sod shock tube (tests/bench/README.md): for each resolution, kernel and
// integrator, the wall time, particle-steps per second and L1 errors of rho, v and p against the exact
// Riemann solution. A benchmark, not a test: it prints CSV (and a markdown table with --md).
//   sod_bench [--t 0.2] [--n 100,200,...] [--kernels M4,M6] [--integrators leapfrog,rk4] [--threads N]
//             [--csv FILE] [--md FILE]
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "sph/world.h"

namespace {

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  for (std::string item; std::getline(ss, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  double t_end = 0.2;
  std::vector<std::string> ns = {"100", "200", "400", "800", "1600"};
  std::vector<std::string> kernels = {"M4", "M5", "M6", "gaussian", "wendland_c2", "wendland_c4"};
  std::vector<std::string> integrators = {"leapfrog", "predictor_corrector", "rk4", "euler"};
  std::string csv_path, md_path;
  for (int a = 1; a + 1 < argc; a += 2) {
    const std::string k = argv[a], v = argv[a + 1];
    if (k == "--t") t_end = std::stod(v);
    else if (k == "--n") ns = split(v);
    else if (k == "--kernels") kernels = split(v);
    else if (k == "--integrators") integrators = split(v);
    else if (k == "--threads") omp_set_num_threads(std::stoi(v));
    else if (k == "--csv") csv_path = v;
    else if (k == "--md") md_path = v;
    else { std::fprintf(stderr, "sod_bench: unknown flag %s\n", k.c_str()); return 2; }
  }
  std::ostringstream csv, md;
  csv << "code,n_left,N_total,kernel,integrator,t_end,steps,wall_s,particle_steps_per_s,L1_rho,L1_v,L1_p\n";
  md << "| N left | N total | kernel | integrator | steps | wall [s] | particle-steps/s | L1(rho) | L1(v) | L1(p) |\n"
     << "|---:|---:|---|---|---:|---:|---:|---:|---:|---:|\n";
  for (const auto& n : ns)
    for (const auto& kern : kernels)
      for (const auto& integ : integrators) {
        sph::RunConfig cfg = sph::RunConfig::from_scene("sod");
        cfg.set("scene.n_left", n, "sod_bench");
        cfg.set("kernel", kern, "sod_bench");
        cfg.set("integrator", integ, "sod_bench");
        const auto t0 = std::chrono::steady_clock::now();
        std::string status = "ok";
        struct { double L1_rho = 0, L1_v = 0, L1_p = 0; } e;
        std::int64_t steps = 0;
        std::size_t N = 0;
        try {
          sph::World w(cfg);
          w.advance_to(t_end);
          e.L1_rho = w.report().reference_value("L1_rho");
          e.L1_v = w.report().reference_value("L1_v");
          e.L1_p = w.report().reference_value("L1_p");
          steps = w.steps();
          N = w.particles().size();
        } catch (const sph::DivergedError& err) {
          status = "diverged";
        }
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const double rate = static_cast<double>(steps) * static_cast<double>(N) / wall;
        char line[512];
        std::snprintf(line, sizeof line, "sph-sandbox,%s,%zu,%s,%s,%g,%lld,%.4f,%.4g,%.4e,%.4e,%.4e\n", n.c_str(), N,
                      kern.c_str(), integ.c_str(), t_end, static_cast<long long>(steps), wall, rate, e.L1_rho, e.L1_v,
                      e.L1_p);
        if (status != "ok") std::snprintf(line, sizeof line, "sph-sandbox,%s,,%s,%s,%g,,,,diverged,,\n", n.c_str(),
                                          kern.c_str(), integ.c_str(), t_end);
        csv << line;
        std::fputs(line, stdout);
        std::fflush(stdout);
        std::snprintf(line, sizeof line, "| %s | %zu | %s | %s | %lld | %.3f | %.3g | %.3e | %.3e | %.3e |\n", n.c_str(), N,
                      kern.c_str(), integ.c_str(), static_cast<long long>(steps), wall, rate, e.L1_rho, e.L1_v, e.L1_p);
        md << (status == "ok" ? std::string(line) : "| " + n + " | | " + kern + " | " + integ + " | diverged | | | | | |\n");
      }
  if (!csv_path.empty()) std::ofstream(csv_path) << csv.str();
  if (!md_path.empty()) std::ofstream(md_path) << md.str();
  return 0;
}
