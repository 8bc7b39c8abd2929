// Report::inspect, the particle inspector: one particle's fields, neighbours and equation terms, from a
// re-evaluation of the current state on a copy (inspect/fresh_evaluation.h) split term by term
// (inspect/force_terms.h).
#include <algorithm>
#include <cmath>

#include "inspect/force_terms.h"
#include "inspect/fresh_evaluation.h"
#include "sph/neighbour_cache.h"
#include "sph/report.h"

namespace sph {
namespace {

double field_or_nan(const Particles& p, Field f, std::size_t i) { return p.has(f) ? p[f][i] : std::nan(""); }

}  // namespace

std::optional<Inspection> Report::inspect(std::int64_t id) const {
  const auto it = std::lower_bound(in_.by_id.begin(), in_.by_id.end(), id,
                                   [&](std::uint32_t k, std::int64_t want) { return in_.p.id[k] < want; });
  if (it == in_.by_id.end() || in_.p.id[*it] != id) return std::nullopt;
  const std::size_t i = *it;
  Inspection out;
  out.id = id;
  out.step = in_.step;
  out.t = in_.t;
  out.wall = in_.p.is_wall(i);
  out.x = in_.p.pos(i);
  out.v = in_.p.vel(i);
  out.speed = out.v.norm();
  out.m = in_.p[Field::Mass][i];
  out.h = in_.p[Field::H][i];
  out.support = in_.kernel.support() * out.h;
  out.rho = field_or_nan(in_.p, Field::Density, i);
  out.P = field_or_nan(in_.p, Field::Pressure, i);
  out.u = field_or_nan(in_.p, Field::Energy, i);
  out.omega = field_or_nan(in_.p, Field::Omega, i);
  out.c = field_or_nan(in_.p, Field::SoundSpeed, i);
  out.neighbours = field_or_nan(in_.p, Field::Neighbours, i);
  out.h_iterations = field_or_nan(in_.p, Field::HIterations, i);
  out.drhodt = field_or_nan(in_.p, Field::DensityRate, i);
  out.a_stored = {in_.p.a[0][i], in_.p.a[1][i], in_.p.a[2][i]};
  out.has_energy = in_.p.has(Field::EnergyRate);
  out.dudt_stored = out.has_energy ? in_.p[Field::EnergyRate][i] : 0.0;
  if (out.wall) return out;  // walls do not move: no equations to take apart

  const FreshInputs in{in_.cfg.params, in_.kernel, in_.domain, in_.eta, in_.spacing, in_.wall_strength};
  FreshEvaluation e = evaluate_fresh(in, in_.p, i);
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
  if (in_.push.active()) {  // the user's push: added after the stages (World::evaluate)
    const Vec3 a = push_acceleration(in_.push, in_.domain, in_.p.dim(), e.p.pos(i), e.p.vel(i));
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
