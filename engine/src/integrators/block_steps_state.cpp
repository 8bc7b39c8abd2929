// The state of individual time steps in a checkpoint: the block's clock and every particle's step,
// half-kicked state and opening rates, as arrays of doubles (integers below 2^53 are exact).
#include "block_steps.h"

namespace sph {
namespace {

std::vector<double> as_doubles(const std::vector<std::int64_t>& v) { return {v.begin(), v.end()}; }

bool as_integers(const std::vector<double>& v, std::vector<std::int64_t>& out) {
  out.assign(v.size(), 0);
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!(v[i] >= 0.0 && v[i] < 9007199254740992.0) || v[i] != static_cast<double>(static_cast<std::int64_t>(v[i])))
      return false;
    out[i] = static_cast<std::int64_t>(v[i]);
  }
  return true;
}

}  // namespace

std::string block_steps_refusal(const Params& p) {
  if (p.time.levels <= 1) return {};
  const std::string key = "time.levels = " + std::to_string(p.time.levels);
  const Physics& ph = p.physics;
  if (p.time.integrator != IntegratorType::Leapfrog)
    return key + " steps particles by kick-drift-kick leapfrog, but time.integrator = " +
           to_string(p.time.integrator) + " (set time.integrator = leapfrog, or time.levels = 1)";
  if (p.time.dt > 0.0)
    return key + " chooses each particle's step, but time.dt is fixed (set time.dt = 0, or time.levels = 1)";
  if (ph.xsph == Toggle::On || ph.fpm != FpmType::None)
    return key + " does not yet drift particles with a correction velocity (physics.xsph, physics.fpm): set "
                 "time.levels = 1";
  if (ph.eos == EosType::Dfsph)
    return key + " steps particles on their own, but physics.eos = dfsph solves one pressure for all of them: set "
                 "time.levels = 1";
  if (ph.visc_switch != ViscSwitch::None)
    return key + " does not yet give the viscosity switch each particle's own step (visc.switch = " +
           to_string(ph.visc_switch) + "): set visc.switch = none, or time.levels = 1";
  if (ph.density == DensityMode::Continuity && p.density.reinit_every > 0)
    return key + " does not yet re-initialise the density between particles' steps (density.reinit_every = " +
           std::to_string(p.density.reinit_every) + "): set it to 0, or time.levels = 1";
  return {};
}

std::vector<std::vector<double>> BlockSteps::history() const {
  std::vector<std::vector<double>> h;
  h.push_back({static_cast<double>(levels_), in_block_ ? 1.0 : 0.0, static_cast<double>(tick_),
               static_cast<double>(next_tick_), tau_, static_cast<double>(too_long_),
               static_cast<double>(yhalf_.size())});
  h.push_back(as_doubles(len_));
  h.push_back(as_doubles(begin_));
  h.emplace_back(wake_.begin(), wake_.end());
  h.push_back(as_doubles(level_));
  for (int k = 0; k < 3; ++k) { h.push_back(vhalf_[k]); h.push_back(a0_[k]); }
  for (std::size_t e = 0; e < yhalf_.size(); ++e) { h.push_back(yhalf_[e]); h.push_back(r0_[e]); }
  return h;
}

bool BlockSteps::set_history(const std::vector<std::vector<double>>& h) {
  if (h.size() < 11 || h[0].size() != 7 || h[0][0] != levels_) return false;
  const auto evolved = static_cast<std::size_t>(h[0][6]);
  if (h[0][6] != static_cast<double>(evolved) || h.size() != 11 + 2 * evolved) return false;
  std::vector<std::int64_t> len, begin, level;
  if (!as_integers(h[1], len) || !as_integers(h[2], begin) || !as_integers(h[4], level) || len.size() != begin.size())
    return false;
  const std::size_t n = len.size();
  for (std::size_t k = 3; k < h.size(); ++k)  // wake flags, levels, then the state arrays
    if (!h[k].empty() && h[k].size() != n) return false;
  in_block_ = h[0][1] != 0.0;
  tick_ = static_cast<std::int64_t>(h[0][2]);
  next_tick_ = static_cast<std::int64_t>(h[0][3]);
  tau_ = h[0][4];
  too_long_ = static_cast<std::int64_t>(h[0][5]);
  len_ = std::move(len);
  begin_ = std::move(begin);
  wake_.assign(h[3].begin(), h[3].end());
  for (double w : h[3])
    if (w != 0.0 && w != 1.0) return false;
  level_ = std::move(level);
  for (int k = 0; k < 3; ++k) { vhalf_[k] = h[5 + 2 * k]; a0_[k] = h[6 + 2 * k]; }
  yhalf_.assign(evolved, {});
  r0_.assign(evolved, {});
  for (std::size_t e = 0; e < evolved; ++e) { yhalf_[e] = h[11 + 2 * e]; r0_[e] = h[12 + 2 * e]; }
  on_.assign(n, 0);
  active_.clear();
  return true;
}

}  // namespace sph
