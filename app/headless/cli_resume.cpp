#include "cli_resume.h"

#include <cstdio>
#include <filesystem>

#include "cli_run.h"
#include "exit_codes.h"
#include "run_checkpoint.h"

namespace sph::cli {

int resume_command(const std::string& dir, int threads, double until, bool quiet) {
  RunOptions opt;
  ResumePoint rp;
  try {
    rp = load_resume_point(dir, &opt);  // every check before anything on disk changes
  } catch (const CheckpointError& e) {
    std::fprintf(stderr, "sph: %s\n", e.what());
    return kInvalidScene;
  }
  if (threads > 0) opt.threads = threads;
  if (until >= 0.0) opt.until = until;
  if (quiet) opt.quiet = true;
  std::error_code ec;
  std::filesystem::remove(rp.path + ".tmp", ec);  // left by a process killed while writing a checkpoint
  return run_command(opt, &rp);
}

}  // namespace sph::cli
