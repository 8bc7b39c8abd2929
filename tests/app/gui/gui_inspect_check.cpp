// Checks the particle inspector's numbers that sph-gui printed at exit (its report of the state it
// showed, see smoke.cmake's "ab" mode) against the engine API: the same scene stepped as the GUI's
// stepper steps it (to t_end, the last step shortened to land on it), Report::inspect of the same id.
// Also checks that the particle lies behind Sod's shock (between the contact and the shock of the exact
// solution). Usage: gui_inspect_check REPORT SCENE T_END  (REPORT: sph-gui's stdout).
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "sph/world.h"

namespace {

/// "name = value" pairs of the report line that starts with `head` (nullopt: none).
bool parse(const std::string& path, const std::string& head, std::map<std::string, double>* out, long long* id) {
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(head, 0) != 0) continue;
    if (std::sscanf(line.c_str() + head.size(), "%lld", id) != 1) return false;
    for (const char* key : {"x", "rho", "u", "a_x", "du/dt", "t"}) {
      const std::string k = std::string(key) + " = ";
      const auto at = line.find(k);
      if (at != std::string::npos) (*out)[key] = std::stod(line.substr(at + k.size()));
    }
    return true;
  }
  return false;
}

bool close(const char* what, double gui, double engine, double tol) {
  const bool ok = std::abs(gui - engine) <= tol * std::max(1.0, std::abs(engine));
  std::printf("%-8s GUI %.17g  engine %.17g  %s\n", what, gui, engine, ok ? "ok" : "FAIL");
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: gui_inspect_check REPORT SCENE T_END\n");
    return 2;
  }
  std::map<std::string, double> gui;
  long long id = -1;
  if (!parse(argv[1], "sph-gui: inspected particle ", &gui, &id) || gui.size() < 6) {
    std::fprintf(stderr, "%s: no inspector report\n", argv[1]);
    return 1;
  }
  sph::RunConfig cfg = sph::RunConfig::load(argv[2]);
  const double t_end = std::stod(argv[3]);
  cfg.params.time.t_end = t_end;
  sph::World w(cfg);
  while (w.time() < t_end * (1.0 - 1e-12)) w.step(t_end - w.time());  // as the stepper does
  const auto in = w.report().inspect(id);
  if (!in) {
    std::fprintf(stderr, "no particle %lld\n", id);
    return 1;
  }
  bool ok = true;
  ok &= close("t", gui["t"], in->t, 1e-12);
  ok &= close("x", gui["x"], in->x.x, 1e-12);
  ok &= close("rho", gui["rho"], in->rho, 1e-12);
  ok &= close("u", gui["u"], in->u, 1e-12);
  ok &= close("a_x", gui["a_x"], in->a_total.x, 1e-9);
  ok &= close("du/dt", gui["du/dt"], in->dudt_total, 1e-9);
  // behind the shock: Sod's exact contact and shock move at u* = 0.92745 and 1.75216 (Toro, Table 4.1 test 1)
  const double contact = 0.92745 * in->t, shock = 1.75216 * in->t;
  const bool behind = in->x.x > contact && in->x.x < shock - 2.0 * in->h;
  std::printf("particle %lld at x = %.4f: %s (contact %.4f, shock %.4f)\n", id, in->x.x,
              behind ? "behind the shock" : "NOT behind the shock", contact, shock);
  return ok && behind ? 0 : 1;
}
