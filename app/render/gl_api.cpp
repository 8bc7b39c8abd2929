#include "gl_api.h"

#include <cstring>

namespace sph::render {

namespace {
// Converts the loader's object pointer to a function pointer (conditionally supported; fine on every
// platform with dlsym-style loaders). memcpy keeps -Wpedantic quiet.
template <class Fn>
Fn to_function(void* p) {
  Fn f = nullptr;
  static_assert(sizeof(f) == sizeof(p));
  std::memcpy(&f, &p, sizeof(f));
  return f;
}
}  // namespace

bool GlApi::load(GetProcFn get_proc, std::string* err) {
  std::string missing;
  if (get_proc == nullptr) {
    if (err) *err = "no GL loader given";
    return false;
  }
#define SPH_GL_LOAD(type, name)                         \
  name = to_function<type>(get_proc("gl" #name));       \
  if (name == nullptr) missing += std::string(missing.empty() ? "" : ", ") + "gl" #name;
  SPH_GL_FUNCTIONS(SPH_GL_LOAD)
#undef SPH_GL_LOAD
  if (!missing.empty()) {
    if (err) *err = "GL entry points not found: " + missing;
    return false;
  }
  return true;
}

}  // namespace sph::render
