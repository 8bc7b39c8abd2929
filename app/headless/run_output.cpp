#include "run_output.h"

#include <cstdio>
#include <filesystem>

namespace sph::cli {
namespace {

std::ofstream open_file(const std::string& path) {
  std::ofstream f(path);
  if (!f) throw IoError("cannot write " + path);
  return f;
}

}  // namespace

RunOutput::RunOutput(const std::string& dir, const World& world) : dir_(dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw IoError("cannot create output directory " + dir + ": " + ec.message());
  open_file(dir + "/scene.json") << world.config().to_json();
  diag_ = open_file(dir + "/diagnostics.csv");
  diag_ << "# " << world.scene().name << ": conserved quantities per step (seed 000 eqs. 3.4.1-3.4.5)\n"
        << diagnostics_csv_header() << "\n";
  if (world.has_reference()) {
    errors_ = open_file(dir + "/errors.csv");
    errors_ << "# L1 = mean over particles with x in [" << world.reference()->window_lo() << ", "
            << world.reference()->window_hi() << "] of |f - f_exact|; exact Riemann solution\n"
            << errors_csv_header() << "\n";
  }
}

void RunOutput::write_diagnostics(const World& world) {
  diag_ << diagnostics_csv_row(world.diagnostics()) << "\n";
  if (!diag_) throw IoError("cannot write " + dir_ + "/diagnostics.csv");
}

void RunOutput::write_particles(const World& world) {
  char name[64];
  std::snprintf(name, sizeof name, "/particles_%05d.csv", files_);
  const std::string path = dir_ + name;
  std::ofstream f = open_file(path);
  const Particles& p = world.particles();
  f << "# t = " << world.time() << ", step " << world.steps() << "\n";
  f << "id,x,y,z,vx,vy,vz,m,rho,p,u,h\n";
  const bool has_p = p.has(Field::Pressure), has_u = p.has(Field::Energy);
  char line[512];
  for (std::size_t i = 0; i < p.size(); ++i) {
    std::snprintf(line, sizeof line, "%lld,%.15g,%.15g,%.15g,%.15g,%.15g,%.15g,%.15g,%.15g,%.15g,%.15g,%.15g\n",
                  static_cast<long long>(p.id[i]), p.x[0][i], p.x[1][i], p.x[2][i], p.v[0][i], p.v[1][i], p.v[2][i],
                  p[Field::Mass][i], p[Field::Density][i], has_p ? p[Field::Pressure][i] : 0.0,
                  has_u ? p[Field::Energy][i] : 0.0, p[Field::H][i]);
    f << line;
  }
  if (!f) throw IoError("cannot write " + path);
  ++files_;
  if (world.has_reference()) {
    errors_ << errors_csv_row(world.errors()) << "\n";
    if (!errors_) throw IoError("cannot write " + dir_ + "/errors.csv");
  }
}

}  // namespace sph::cli
