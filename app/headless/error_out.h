// The error out-parameter of the frame-writing code: a message stored where the caller asked for one.
#pragma once
#include <string>

namespace sph::cli {

/// Sets *err to msg (nothing when err is null).
inline void fail(std::string* err, const std::string& msg) {
  if (err) *err = msg;
}

}  // namespace sph::cli
