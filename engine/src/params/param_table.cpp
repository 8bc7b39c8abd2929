// The declaration of every run parameter (see sph/param_table.h).
#include "sph/param_table.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace sph {
namespace {

std::string format(double v) {
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}

ParamInfo real(std::string_view key, double Params::*member, double lo, double hi, std::string_view unit,
               bool live, std::string_view what) {
  ParamInfo p;
  p.key = key;
  p.unit = unit;
  p.description = what;
  p.min = lo;
  p.max = hi;
  p.live = live;
  p.get = [member](const Params& prm) { return format(prm.*member); };
  p.set = [member, lo, hi, key](Params& prm, const std::string& text, std::string& err) {
    double v = 0.0;
    if (!parse_number(text, v)) { err = "'" + text + "' is not a number"; return false; }
    if (v < lo || v > hi) {
      err = std::string(key) + " = " + text + " is out of range [" + format(lo) + ", " + format(hi) + "]";
      return false;
    }
    prm.*member = v;
    return true;
  };
  return p;
}

ParamInfo integer(std::string_view key, int Params::*member, int lo, int hi, bool live, std::string_view what) {
  ParamInfo p = real(key, nullptr, lo, hi, "-", live, what);
  p.get = [member](const Params& prm) { return std::to_string(prm.*member); };
  p.set = [member, lo, hi, key](Params& prm, const std::string& text, std::string& err) {
    double v = 0.0;
    if (!parse_number(text, v) || v != std::floor(v)) { err = "'" + text + "' is not an integer"; return false; }
    if (v < lo || v > hi) {
      err = std::string(key) + " = " + text + " is out of range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
      return false;
    }
    prm.*member = static_cast<int>(v);
    return true;
  };
  return p;
}

template <class E>
ParamInfo choice(std::string_view key, E Params::*member, std::vector<E> values, bool live, std::string_view what) {
  ParamInfo p;
  p.key = key;
  p.unit = "-";
  p.description = what;
  p.live = live;
  for (E e : values) p.choices.emplace_back(to_string(e));
  p.get = [member](const Params& prm) { return std::string(to_string(prm.*member)); };
  p.set = [member, key, names = p.choices](Params& prm, const std::string& text, std::string& err) {
    E e{};
    if (!parse(text, e)) {
      err = std::string(key) + " = '" + text + "' is not one of:";
      for (const auto& n : names) err += " " + n;
      return false;
    }
    prm.*member = e;
    return true;
  };
  return p;
}

std::vector<ParamInfo> build() {
  using K = KernelType;
  using I = IntegratorType;
  return {
      choice("kernel", &Params::kernel, {K::M4, K::M5, K::M6, K::Gaussian, K::WendlandC2, K::WendlandC4}, true,
             "smoothing kernel W (seed 000 eqs. 3.2.6-3.2.9)"),
      real("eta", &Params::eta, 0.0, 4.0, "-", true,
           "h = eta (m/rho)^(1/d) (seed 000 eq. 3.3.33); 0 = the kernel's default"),
      choice("h_mode", &Params::h_mode, {HMode::Variable, HMode::Fixed}, true,
             "variable h with grad-h Omega terms (seed 000 eq. 3.3.2) or fixed h"),
      real("h_tol", &Params::h_tol, 1e-15, 1e-2, "-", true, "Newton-Raphson relative tolerance on h (seed 000 eq. 3.5.1)"),
      integer("h_max_iter", &Params::h_max_iter, 1, 1000, true, "Newton-Raphson iteration cap per particle"),
      real("gamma", &Params::gamma, 1.0001, 10.0, "-", false, "adiabatic index, P = (gamma-1) rho u (seed 000 eq. 3.3.23)"),
      real("alpha", &Params::alpha, 0.0, 10.0, "-", true, "artificial viscosity, linear term (seed 003 eq. 3.16)"),
      real("beta", &Params::beta, 0.0, 20.0, "-", true, "artificial viscosity, quadratic term (seed 003 eq. 3.16)"),
      real("visc_eps", &Params::visc_eps, 1e-6, 1.0, "-", true, "eta^2 = visc_eps h^2 in the viscosity (seed 003 eq. 3.16)"),
      real("alpha_u", &Params::alpha_u, 0.0, 10.0, "-", true, "artificial thermal conductivity (Price 2008); 0 = off"),
      choice("integrator", &Params::integrator, {I::Euler, I::RK4, I::Leapfrog, I::PredictorCorrector}, true,
             "time integrator (seed 000 App. A; seed 001 eqs. 56-59)"),
      real("dt", &Params::dt, 0.0, 1e6, "time", true, "fixed timestep; 0 = adaptive from cfl"),
      real("cfl", &Params::cfl, 1e-4, 2.0, "-", true, "Courant factor: dt = cfl min(h/v_sig, sqrt(h/|a|))"),
      real("t_end", &Params::t_end, 0.0, 1e9, "time", true, "end time of a run"),
      real("dt_out", &Params::dt_out, 0.0, 1e9, "time", true, "interval between particle outputs; 0 = end only"),
  };
}

}  // namespace

bool parse_number(const std::string& s, double& out) {
  if (s.empty()) return false;
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && std::isfinite(out);
}

const std::vector<ParamInfo>& param_table() {
  static const std::vector<ParamInfo> table = build();
  return table;
}

const ParamInfo* find_param(std::string_view key) {
  for (const auto& p : param_table())
    if (p.key == key) return &p;
  return nullptr;
}

}  // namespace sph
