// RunOutput continued from a checkpoint (sph resume): the streamed CSVs are cut back to where they
// stood at the checkpoint and appended to; the particle-file counters and series are taken back.
#include <filesystem>

#include "run_output.h"

namespace sph::cli {
namespace {

/// Cuts `path` back to `bytes` and opens it for appending; throws IoError naming it.
std::ofstream reopen(const std::string& path, std::uint64_t bytes) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec || size < bytes)
    throw IoError(path + " is shorter than at the checkpoint (" + std::to_string(ec ? 0 : size) + " of " +
                  std::to_string(bytes) + " bytes)");
  std::filesystem::resize_file(path, bytes, ec);
  if (ec) throw IoError("cannot cut back " + path + ": " + ec.message());
  std::ofstream f(path, std::ios::app | std::ios::binary);
  if (!f) throw IoError("cannot write " + path);
  return f;
}

}  // namespace

RunOutput::RunOutput(const std::string& dir, const World& world, const OutputOptions& options,
                     const OutputResume& resume)
    : dir_(dir), options_(options), files_(resume.files), series_(resume.series), steps_(resume.steps) {
  write_file(dir + "/scene.json", world.config().to_json());  // the end time may have changed (--until)
  diag_ = reopen(dir + "/diagnostics.csv", resume.diag_bytes);
  if (world.has_reference()) {
    errors_ = reopen(dir + "/errors.csv", resume.errors_bytes);
    valid_until_ = world.reference()->valid_until();
  }
  columns_ = particle_columns(world);
}

OutputResume RunOutput::resume_state() {
  diag_.flush();
  if (!diag_) throw IoError("cannot write " + dir_ + "/diagnostics.csv");
  OutputResume r;
  r.files = files_;
  r.series = series_;
  r.steps = steps_;
  r.diag_bytes = static_cast<std::uint64_t>(diag_.tellp());
  if (errors_.is_open()) {
    errors_.flush();
    if (!errors_) throw IoError("cannot write " + dir_ + "/errors.csv");
    r.errors_bytes = static_cast<std::uint64_t>(errors_.tellp());
  }
  return r;
}

}  // namespace sph::cli
