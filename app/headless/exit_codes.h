// Exit codes of the sph program (documented in README.md and `sph --help`).
#pragma once

namespace sph::cli {

enum ExitCode : int {
  kOk = 0,            ///< success
  kInternal = 1,      ///< unexpected internal error
  kUsage = 2,         ///< bad command line (unknown flag, malformed value)
  kInvalidScene = 3,  ///< unknown scene, malformed scene file, unknown key or value out of range; a checkpoint
                      ///< that is missing, truncated, damaged, of another version or not one (sph resume)
  kIoError = 4,       ///< cannot create or write the output
  kDiverged = 5,      ///< NaN/inf, a finite blow-up (energy, timestep), a particle through a wall or a start
                      ///< the h solve cannot reach: the run stopped, nothing of the bad state was written
  kBadLesson = 6,     ///< `sph lesson`: malformed lesson file (the message names the file and the key)
  kClaimFalse = 7,    ///< `sph lesson check`: a step's claim is false (the measured numbers are printed)
  kInaccurate = 8,    ///< a gravity scene's energy drifted beyond its bound: the run ended and wrote its
                      ///< outputs and the warning, but its result is not to be trusted
  kInterrupted = 130, ///< SIGINT (Ctrl-C): the run stopped after a step and wrote a checkpoint (sph resume DIR)
  kTerminated = 143,  ///< SIGTERM: the same
};

}  // namespace sph::cli
