// Particle fields as NumPy arrays without copying: each array views the engine's own std::vector for the
// real particles (fluid first, then walls, in the engine's storage order), is read-only, and keeps the
// world alive. A view is valid until the world next changes (a step, run_to, set_params): the engine
// reorders its particles every few steps and may reallocate. by_id() copies in increasing id instead.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstring>
#include <stdexcept>

#include "py_bindings.h"
#include "sph/fields.h"
#include "sph/particles.h"

namespace sph::py {
namespace {

namespace pyb = pybind11;

constexpr const char* kAxes[3] = {"x", "y", "z"};

/// The engine's storage of `name` (found false if the scene has no such field).
struct Storage {
  const void* data = nullptr;
  pyb::dtype type = pyb::dtype::of<double>();
  bool found = true;
};

Storage find_storage(const Particles& p, const std::string& name) {
  for (int k = 0; k < 3; ++k) {
    if (name == kAxes[k]) return {p.x[k].data()};
    if (name == std::string("v") + kAxes[k]) return {p.v[k].data()};
    if (name == std::string("a") + kAxes[k]) return {p.a[k].data()};
  }
  if (name == "id") return {p.id.data(), pyb::dtype::of<std::int64_t>()};
  if (name == "kind") return {p.kind.data(), pyb::dtype::of<std::uint8_t>()};
  for (std::size_t f = 0; f < kFieldCount; ++f)
    if (kFieldInfo[f].key == name && p.has(static_cast<Field>(f))) return {p[static_cast<Field>(f)].data()};
  return {nullptr, pyb::dtype::of<double>(), false};
}

std::vector<std::string> field_names(const Particles& p) {
  std::vector<std::string> names{"id", "kind"};
  for (const char* k : kAxes) names.emplace_back(k);
  for (const char* k : kAxes) names.push_back(std::string("v") + k);
  for (const char* k : kAxes) names.push_back(std::string("a") + k);
  p.fields().for_each([&](Field f) { names.emplace_back(info(f).key); });
  return names;
}

Storage storage_or_throw(const Particles& p, const std::string& name) {
  Storage s = find_storage(p, name);
  if (!s.found) {
    std::string known;
    for (const std::string& n : field_names(p)) known += (known.empty() ? "" : ", ") + n;
    throw pyb::key_error("field '" + name + "': not a field of this scene (it has: " + known + ")");
  }
  return s;
}

/// A read-only array of the real particles over the engine's storage, with `owner` as its base.
pyb::array view(const Particles& p, const std::string& name, pyb::handle owner) {
  const Storage s = storage_or_throw(p, name);
  pyb::array a(s.type, std::vector<pyb::ssize_t>{static_cast<pyb::ssize_t>(p.size())}, std::vector<pyb::ssize_t>{}, s.data, owner);
  a.attr("flags").attr("writeable") = false;
  return a;
}

}  // namespace

void bind_fields(WorldClass& cls) {
  cls.def("field_names", [](const PyWorld& w) { return field_names(w.world().particles()); },
          "Names field() takes: id, kind, x..z, vx..vz, ax..az and the scalar fields this scene's stages allocate.");
  cls.def(
      "field",
      [](pyb::object self, const std::string& name) { return view(self.cast<const PyWorld&>().world().particles(), name, self); },
      pyb::arg("name"),
      "A read-only NumPy view of one field over the engine's storage, no copy: the real particles (fluid first,\n"
      "then walls) in the engine's storage order. Valid until the world next changes (step, run_to,\n"
      "set_params): copy it (numpy.array(a)) to keep it. KeyError names the fields there are.");
  cls.def(
      "by_id",
      [](const PyWorld& w, const std::string& name) {
        const Particles& p = w.world().particles();
        pyb::array src = view(p, name, pyb::none());
        const auto& order = w.world().by_id();
        pyb::array out(src.dtype(), std::vector<pyb::ssize_t>{static_cast<pyb::ssize_t>(order.size())}, std::vector<pyb::ssize_t>{});
        const auto item = static_cast<std::size_t>(src.itemsize());
        const auto* from = static_cast<const char*>(src.data());
        auto* to = static_cast<char*>(out.mutable_data());
        for (std::size_t r = 0; r < order.size(); ++r) std::memcpy(to + r * item, from + order[r] * item, item);
        return out;
      },
      pyb::arg("name"), "A copy of one field with the particles in increasing id (the rows of sph run's particle files).");
  cls.def(
      "address",
      [](const PyWorld& w, const std::string& name) {
        return reinterpret_cast<std::uintptr_t>(storage_or_throw(w.world().particles(), name).data);
      },
      pyb::arg("name"), "The address of the engine's storage of a field (field(name) views it from there).");
}

}  // namespace sph::py
