#include "cli_export.h"

#include <omp.h>

#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli_common.h"
#include "exit_codes.h"
#include "sph/memory_budget.h"
#include "run_output.h"
#include "sph/ic_export.h"
#include "sph/suggest.h"
#include "sph/world.h"

namespace sph::cli {

std::string parameter_path(const std::string& ic_path, const std::string& format) {
  std::filesystem::path p(ic_path);
  const std::string stem = p.extension() == ".hdf5" || p.extension() == ".h5" ? p.stem().string() : p.filename().string();
  return (p.parent_path() / (stem + (format == "gadget4" ? "-param.txt" : ".yml"))).string();
}

int export_command(const ExportOptions& opt) {
  IcFormat format{};
  if (!parse(opt.format, format)) {
    std::fprintf(stderr, "sph: export-ics --format %s: expected swift or gadget4%s\n", opt.format.c_str(),
                 did_you_mean(opt.format, {"swift", "gadget4"}).c_str());
    return kUsage;
  }
  if (opt.out.empty() || !(opt.out.ends_with(".hdf5") || opt.out.ends_with(".h5"))) {
    std::fprintf(stderr, "sph: export-ics --out: name the .hdf5 file to write (got '%s')\n", opt.out.c_str());
    return kUsage;
  }
  RunConfig cfg;
  try {
    cfg = RunConfig::load(opt.scene);
    apply_sets(cfg, opt.sets);
    if (opt.until >= 0.0) cfg.params.time.t_end = opt.until;
    cfg.validate();
    check_run_memory(cfg);
    const std::string why = hdf5_unsupported(cfg.params);
    if (!why.empty()) throw ConfigError("scene " + cfg.scene->name + ": " + why);
  } catch (const ConfigError& e) {
    std::fprintf(stderr, "sph: export-ics: %s\n", e.what());
    return kInvalidScene;
  }
  if (opt.threads > 0) omp_set_num_threads(opt.threads);
  std::unique_ptr<World> world;  // the state at t = 0 as a run starts (density and h solved, masses anchored)
  try {
    world = std::make_unique<World>(cfg);
  } catch (const DivergedError& e) {
    std::fprintf(stderr, "sph: export-ics: %s; nothing written\n", e.what());
    return kDiverged;
  }
  std::vector<std::string> warnings;
  const std::string ic_name = std::filesystem::path(opt.out).filename().string();
  const std::string params = parameter_file(*world, format, ic_name, &warnings);
  const std::string param_path = parameter_path(opt.out, opt.format);
  std::error_code ec;
  const std::filesystem::path dir = std::filesystem::path(opt.out).parent_path();
  if (!dir.empty()) std::filesystem::create_directories(dir, ec);
  try {
    write_file(opt.out, hdf5_snapshot(*world, format));
    write_file(param_path, params);
  } catch (const IoError& e) {
    std::filesystem::remove(opt.out, ec);  // both files or neither
    std::fprintf(stderr, "sph: export-ics: I/O error: %s\n", e.what());
    return kIoError;
  }
  std::printf("%s: %zu particles of %s (%s layout), parameter file %s\n", opt.out.c_str(), world->particles().size(),
              cfg.scene->name.c_str(), opt.format.c_str(), param_path.c_str());
  if (format == IcFormat::Swift)  // the YAML names its file relative to the folder it is in
    std::printf("run: cd %s && %s\n", dir.empty() ? "." : dir.string().c_str(),
                swift_run_line(cfg.params, std::filesystem::path(param_path).filename().string()).c_str());
  if (!warnings.empty()) {
    std::fprintf(stderr, "what %s cannot reproduce (%zu):\n", format == IcFormat::Swift ? "SWIFT" : "GADGET-4",
                 warnings.size());
    for (const std::string& w : warnings) std::fprintf(stderr, "  %s\n", w.c_str());
  }
  return kOk;
}

}  // namespace sph::cli
