// RunOutput continued from a checkpoint (sph resume): the growing CSVs are cut back to where they stood
// at the checkpoint and appended to, manifest.json lists again what it listed then, and the particle-file
// counters and series are taken back. The files of an uninterrupted run come out byte for byte.
#include <filesystem>

#include "run_output.h"

namespace sph::cli {

RunOutput::RunOutput(const std::string& dir, const World& world, const OutputOptions& options,
                     const OutputResume& resume)
    : dir_(dir), options_(options), manifest_(dir), files_(resume.files), series_(resume.series),
      steps_(resume.steps) {
  remove_stale_temporaries(dir);
  manifest_.restore(resume.manifest);
  put("scene.json", world.config().to_json());  // the end time may have changed (--until)
  check(diag_.resume(dir + "/diagnostics.csv", resume.diag));
  if (world.report().has_reference()) {
    check(errors_.resume(dir + "/errors.csv", resume.errors));
    valid_until_ = world.report().reference()->valid_until();
  }
  columns_ = particle_columns(world);
}

OutputResume RunOutput::resume_state() {
  check(diag_.flush());
  OutputResume r;
  r.files = files_;
  r.series = series_;
  r.steps = steps_;
  r.diag = diag_.stamp();
  if (errors_.is_open()) {
    check(errors_.flush());
    r.errors = errors_.stamp();
  }
  r.manifest = manifest_.entries();
  return r;
}

}  // namespace sph::cli
