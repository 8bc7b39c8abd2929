#include "run_output.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_common.h"
#include "sph/ic_export.h"
#include "sph/splash_ascii.h"

namespace sph::cli {
namespace {

std::string diagnostics_note(const World& world) {
  return world.config().scene->name + ": conserved quantities per step (seed 000 eqs. 3.4.1-3.4.5)";
}

}  // namespace

void write_file(const std::string& path, const std::string& bytes) {
  const std::string err = write_file_atomic(path, bytes);
  if (!err.empty()) throw IoError(err);
}

void RunOutput::check(const std::string& err) {
  if (err.empty()) return;
  failed_ = true;
  throw IoError(err);
}

void RunOutput::put(const std::string& name, const std::string& bytes) { check(manifest_.write(name, bytes)); }

RunOutput::RunOutput(const std::string& dir, const World& world, const OutputOptions& options)
    : dir_(dir), options_(options), manifest_(dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw IoError("cannot create output directory " + dir + ": " + ec.message());
  if (!std::filesystem::is_directory(dir, ec)) throw IoError("cannot create output directory " + dir + ": not a directory");
  remove_stale_temporaries(dir);
  put("scene.json", world.config().to_json());
  check(diag_.open(dir + "/diagnostics.csv"));
  if (options_.csv_comments) check(diag_.append("# " + diagnostics_note(world) + "\n"));
  check(diag_.append(diagnostics_csv_header() + "\n"));
  if (world.report().has_reference()) {
    check(errors_.open(dir + "/errors.csv"));
    if (options_.csv_comments) check(errors_.append("# " + world.report().reference()->description() + "\n"));
    check(errors_.append(errors_csv_header(world.report().reference_columns()) + "\n"));
    valid_until_ = world.report().reference()->valid_until();
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

RunOutput::~RunOutput() {
  if (finished_) return;
  if (failed_) {
    diag_.abandon();
    errors_.abandon();
    return;
  }
  try {
    finish();
  } catch (const IoError& e) {
    std::fprintf(stderr, "sph: I/O error: %s\n", e.what());
  }
}

void RunOutput::finish() {
  if (finished_) return;
  finished_ = true;
  for (GrowingFile* g : {&diag_, &errors_}) {
    if (!g->is_open()) continue;
    const FileStamp stamp = g->stamp();
    const std::string name = g->path().filename().string();
    check(g->finish());
    check(manifest_.add(name, stamp));
  }
}

void RunOutput::write_diagnostics(const World& world) {
  check(diag_.append(diagnostics_csv_row(world.report().diagnostics()) + "\n"));
}

void RunOutput::write_particles(const World& world) {
  char stem[32];
  std::snprintf(stem, sizeof stem, "particles_%05d", files_);
  const std::string base = stem;
  const Particles& p = world.particles();
  std::string f;
  if (options_.csv_comments) {
    std::ostringstream note;  // the default float format of earlier versions
    note << "# t = " << world.time() << ", step " << world.steps() << "\n";
    f += note.str();
  }
  const bool walls = p.fluid() < p.size();
  f += "id,x,y,z,vx,vy,vz";
  for (Field c : columns_) (f += ",") += info(c).key;
  f += walls ? ",kind\n" : "\n";
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
    f += line;
  }
  check(diag_.flush());  // the rows up to this output reach the system with the particle file
  put(base + ".csv", f);
  ++files_;
  series_.push_back({world.time(), stem});
  steps_.push_back(world.steps());
  if (!options_.probe_rows) write_errors(world);
  if (options_.vtu) {
    put(base + ".vtu", vtu_file(world));
    std::vector<PvdEntry> entries = series_;
    for (PvdEntry& e : entries) e.file += ".vtu";
    put("particles.pvd", pvd_file(entries));
  }
  if (options_.splash) put(base + ".dat", splash_ascii_file(world));
  if (options_.hdf5) put(base + ".hdf5", hdf5_snapshot(world, IcFormat::Swift));
  if (!options_.csv_comments) write_meta(world);
}

void RunOutput::write_meta(const World& world) {
  nlohmann::ordered_json j;
  j["scene"] = world.config().scene->name;
  j["about"] = "what the comment lines of the CSV files said (sph run --csv-comments puts them back in the files)";
  j["diagnostics.csv"] = diagnostics_note(world);
  if (world.report().has_reference()) j["errors.csv"] = world.report().reference()->description();
  nlohmann::ordered_json files = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < series_.size(); ++k)
    files.push_back({{"file", series_[k].file + ".csv"}, {"t", series_[k].t}, {"step", steps_[k]}});
  j["particles"] = files;
  put("csv_meta.json", j.dump(2) + "\n");
}

namespace {

/// One CSV field: quoted, inner quotes doubled.
std::string csv_quoted(std::string msg) {
  for (std::size_t k = msg.find('"'); k != std::string::npos; k = msg.find('"', k + 2)) msg.insert(k, 1, '"');
  return "\"" + msg + "\"";
}

}  // namespace

void RunOutput::write_warnings(const World& world, const DivergedError* stop) {
  std::ostringstream f;  // written whole at the end of the run (atomically)
  f << "kind,step,t,particle,checks,message\n";
  for (const RunWarning& w : world.checks().warnings())
    f << w.kind << "," << w.step << "," << w.t << "," << w.particle << "," << w.times << "," << csv_quoted(w.message)
      << "\n";
  if (stop) f << "diverged," << stop->step << "," << stop->t << "," << stop->particle << ",1," << csv_quoted(stop->what()) << "\n";
  put("warnings.csv", f.str());
}

void RunOutput::write_errors(const World& world) {
  if (!world.report().has_reference()) return;
  check(errors_.append(
      errors_csv_row(world.time(), world.report().reference_values(), world.time() <= valid_until_ * (1.0 + 1e-12)) + "\n"));
  check(errors_.flush());
}

}  // namespace sph::cli
