// The particle inspector: one particle's fields, neighbours and equation terms, from a re-evaluation of
// the current state on a copy (inspect/fresh_evaluation.h) split term by term (inspect/force_terms.h).
#include <algorithm>
#include <cmath>

#include "inspect/force_terms.h"
#include "inspect/fresh_evaluation.h"
#include "sph/world.h"

namespace sph {
namespace {

double field_or_nan(const Particles& p, Field f, std::size_t i) { return p.has(f) ? p[f][i] : std::nan(""); }

}  // namespace

std::optional<Inspection> World::inspect(std::int64_t id) const {
  const auto it = std::lower_bound(by_id_.begin(), by_id_.end(), id,
                                   [&](std::uint32_t k, std::int64_t want) { return p_.id[k] < want; });
  if (it == by_id_.end() || p_.id[*it] != id) return std::nullopt;
  const std::size_t i = *it;
  Inspection out;
  out.id = id;
  out.step = step_;
  out.t = t_;
  out.wall = p_.is_wall(i);
  out.x = p_.pos(i);
  out.v = p_.vel(i);
  out.speed = out.v.norm();
  out.m = p_[Field::Mass][i];
  out.h = p_[Field::H][i];
  out.rho = field_or_nan(p_, Field::Density, i);
  out.P = field_or_nan(p_, Field::Pressure, i);
  out.u = field_or_nan(p_, Field::Energy, i);
  out.omega = field_or_nan(p_, Field::Omega, i);
  out.c = field_or_nan(p_, Field::SoundSpeed, i);
  out.neighbours = field_or_nan(p_, Field::Neighbours, i);
  out.h_iterations = field_or_nan(p_, Field::HIterations, i);
  out.drhodt = field_or_nan(p_, Field::DensityRate, i);
  out.a_stored = {p_.a[0][i], p_.a[1][i], p_.a[2][i]};
  out.has_energy = p_.has(Field::EnergyRate);
  out.dudt_stored = out.has_energy ? p_[Field::EnergyRate][i] : 0.0;
  if (out.wall) return out;  // walls do not move: no equations to take apart

  const FreshInputs in{cfg_.params, kernel_, domain_, eta(), spacing_, wall_strength_};
  FreshEvaluation e = evaluate_fresh(in, p_, i);
  const StageContext ctx = fresh_context(in, e);
  out.formulation = force_terms(ctx, i, &out.terms, &out.neighbour_list);
  // After the force stage (which sets the accelerations), every stage that adds to the rates is a term
  // of its own: walls, body forces, self-gravity. Stages before it are overwritten by it.
  const bool has_setter = std::any_of(e.deltas.begin(), e.deltas.end(), [](const StageDelta& d) { return d.sets; });
  bool counting = !has_setter;
  for (const StageDelta& d : e.deltas) {
    if (d.sets) { counting = true; continue; }
    if (!counting || (d.a.norm2() == 0.0 && d.dudt == 0.0)) continue;
    InspectTerm t;
    t.name = d.stage;
    t.source = "the whole stage";
    t.a = d.a;
    t.dudt = d.dudt;
    t.a_scale = d.a.norm();
    t.dudt_scale = std::abs(d.dudt);
    out.terms.push_back(std::move(t));
  }
  if (push_.active()) {  // the user's push: added after the stages (World::evaluate)
    const Vec3 a = push_acceleration(push_, domain_, p_.dim(), e.p.pos(i), e.p.vel(i));
    e.p.a[0][i] += a.x;
    e.p.a[1][i] += a.y;
    e.p.a[2][i] += a.z;
    if (a.norm2() > 0.0) {
      InspectTerm t;
      t.name = "push (right drag)";
      t.source = "a = w(r/R) (v_push - v) / tau, w(q) = (1 - q^2)^2 (sph/push.h)";
      t.a = a;
      t.a_scale = a.norm();
      out.terms.push_back(std::move(t));
    }
  }
  out.a_total = {e.p.a[0][i], e.p.a[1][i], e.p.a[2][i]};
  out.dudt_total = out.has_energy ? e.p[Field::EnergyRate][i] : 0.0;
  return out;
}

}  // namespace sph
