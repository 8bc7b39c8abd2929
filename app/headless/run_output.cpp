#include "run_output.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "sph/ic_export.h"
#include "sph/splash_ascii.h"

namespace sph::cli {
namespace {

std::ofstream open_file(const std::string& path) {
  std::ofstream f(path);
  if (!f) throw IoError("cannot write " + path);
  return f;
}

std::string diagnostics_note(const World& world) {
  return world.scene().name + ": conserved quantities per step (seed 000 eqs. 3.4.1-3.4.5)";
}

}  // namespace

void write_file(const std::string& path, const std::string& bytes) {
  if (!write_text_atomic(path, bytes)) throw IoError("cannot write " + path);
}

RunOutput::RunOutput(const std::string& dir, const World& world, const OutputOptions& options)
    : dir_(dir), options_(options) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw IoError("cannot create output directory " + dir + ": " + ec.message());
  open_file(dir + "/scene.json") << world.config().to_json();
  diag_ = open_file(dir + "/diagnostics.csv");
  if (options_.csv_comments) diag_ << "# " << diagnostics_note(world) << "\n";
  diag_ << diagnostics_csv_header() << "\n";
  if (world.has_reference()) {
    errors_ = open_file(dir + "/errors.csv");
    if (options_.csv_comments) errors_ << "# " << world.reference()->description() << "\n";
    errors_ << errors_csv_header(world.reference_columns()) << "\n";
    valid_until_ = world.reference()->valid_until();
  }
  columns_ = particle_columns(world);
}

std::vector<Field> RunOutput::particle_columns(const World& world) {
  // particle columns: id, position, velocity, then the scene's state fields, then the kind if it has walls
  std::vector<Field> columns_;
  for (Field f : {Field::Mass, Field::Density, Field::Pressure, Field::Energy, Field::H})
    if (world.particles().has(f)) columns_.push_back(f);
  for (std::size_t k = 0; k < kFieldCount; ++k) {
    const Field f = static_cast<Field>(k);
    if (world.particles().has(f) && info(f).csv && std::find(columns_.begin(), columns_.end(), f) == columns_.end())
      columns_.push_back(f);
  }
  return columns_;
}

void RunOutput::write_diagnostics(const World& world) {
  diag_ << diagnostics_csv_row(world.diagnostics()) << "\n";
  if (!diag_) throw IoError("cannot write " + dir_ + "/diagnostics.csv");
}

void RunOutput::write_particles(const World& world) {
  char stem[32];
  std::snprintf(stem, sizeof stem, "particles_%05d", files_);
  const std::string base = dir_ + "/" + stem;
  const std::string path = base + ".csv";
  std::ofstream f = open_file(path);
  const Particles& p = world.particles();
  if (options_.csv_comments) f << "# t = " << world.time() << ", step " << world.steps() << "\n";
  const bool walls = p.fluid() < p.size();
  f << "id,x,y,z,vx,vy,vz";
  for (Field c : columns_) f << "," << info(c).key;
  f << (walls ? ",kind\n" : "\n");
  std::string line;
  char num[32];
  for (const std::uint32_t i : world.by_id()) {  // rows in id order, whatever the storage order
    line = std::to_string(p.id[i]);
    auto put = [&](double v) {
      std::snprintf(num, sizeof num, ",%.15g", v);
      line += num;
    };
    for (int k = 0; k < 3; ++k) put(p.x[k][i]);
    for (int k = 0; k < 3; ++k) put(p.v[k][i]);
    for (Field c : columns_) put(p[c][i]);
    if (walls) line += p.is_wall(i) ? ",1" : ",0";
    line += '\n';
    f << line;
  }
  if (!f) throw IoError("cannot write " + path);
  ++files_;
  series_.push_back({world.time(), stem});
  steps_.push_back(world.steps());
  if (world.has_reference()) {
    errors_ << errors_csv_row(world.time(), world.reference_values(), world.time() <= valid_until_ * (1.0 + 1e-12))
            << "\n";
    if (!errors_) throw IoError("cannot write " + dir_ + "/errors.csv");
  }
  if (options_.vtu) {
    write_file(base + ".vtu", vtu_file(world));
    std::vector<PvdEntry> entries = series_;
    for (PvdEntry& e : entries) e.file += ".vtu";
    write_file(dir_ + "/particles.pvd", pvd_file(entries));
  }
  if (options_.splash) write_file(base + ".dat", splash_ascii_file(world));
  if (options_.hdf5) write_file(base + ".hdf5", hdf5_snapshot(world, IcFormat::Swift));
  if (!options_.csv_comments) write_meta(world);
}

void RunOutput::write_meta(const World& world) const {
  nlohmann::ordered_json j;
  j["scene"] = world.scene().name;
  j["about"] = "what the comment lines of the CSV files said (sph run --csv-comments puts them back in the files)";
  j["diagnostics.csv"] = diagnostics_note(world);
  if (world.has_reference()) j["errors.csv"] = world.reference()->description();
  nlohmann::ordered_json files = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < series_.size(); ++k)
    files.push_back({{"file", series_[k].file + ".csv"}, {"t", series_[k].t}, {"step", steps_[k]}});
  j["particles"] = files;
  write_file(dir_ + "/csv_meta.json", j.dump(2) + "\n");
}

void RunOutput::write_warnings(const World& world) {
  const std::string path = dir_ + "/warnings.csv";
  std::ofstream f = open_file(path);
  f << "kind,step,t,particle,checks,message\n";
  for (const RunWarning& w : world.warnings()) {
    std::string msg = w.message;  // one CSV field: quoted, inner quotes doubled
    for (std::size_t k = msg.find('"'); k != std::string::npos; k = msg.find('"', k + 2)) msg.insert(k, 1, '"');
    f << w.kind << "," << w.step << "," << w.t << "," << w.particle << "," << w.times << ",\"" << msg << "\"\n";
  }
  if (!f) throw IoError("cannot write " + path);
}

}  // namespace sph::cli
