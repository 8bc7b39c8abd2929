#include "inspect/force_terms.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "physics/corrected_kernel.h"
#include "physics/pair_block.h"
#include "physics/pair_fields.h"
#include "physics/pair_terms.h"
#include "physics/terms/conduction.h"
#include "physics/terms/visc_terms.h"
#include "physics/viscous_stress.h"

namespace sph {
namespace {

enum Term { kPressure, kViscPi, kViscLaplacian, kViscStress, kConduction, kTermCount };

struct TermInfo {
  const char* name;
  const char* source;
};

/// Names and equations of the terms, per formulation (empty name: the formulation has no such term).
using TermTable = std::array<TermInfo, kTermCount>;

const TermTable kStandard = {{
    {"pressure", "-sum m_b [P_a/(Omega_a rho_a^2) grad W(h_a) + P_b/(Omega_b rho_b^2) grad W(h_b)]; du: "
                 "P_a/(Omega_a rho_a^2) sum m_b v_ab . grad W(h_a) (seed 000 eqs. 3.3.17, 3.3.19)"},
    {"artificial viscosity Pi", "-sum m_b Pi_ab grad W(mean h); du: 1/2 sum m_b Pi_ab v_ab . grad W "
                                "(seed 003 eq. 3.16)"},
    {"Laplacian viscosity", "sum m_b nu (rho_a + rho_b)/(rho_a rho_b) (r . grad W)/(r^2 + eps h^2) v_ab "
                            "(Morris et al. 1997, seed 004)"},
    {"", ""},
    {"conduction", "sum m_b alpha_u v_sig,u (u_a - u_b)/rho_ab r_hat . grad W (Price 2008)"},
}};

const TermTable kStandardCorrected = {{
    {"pressure", "-sum m_b [P_a/rho_a^2 G_a(b) - P_b/rho_b^2 G_b(a)] (seed 001 eq. 53, pair form)"},
    {"artificial viscosity Pi", "-sum m_b Pi_ab (G_a(b) - G_b(a))/2 (seed 001 eqs. 41-43)"},
    {"Laplacian viscosity", "sum m_b nu (rho_a + rho_b)/(rho_a rho_b) (r . G)/(r^2 + eps h^2) v_ab (seed 004)"},
    {"", ""},
    {"", ""},
}};

const TermTable kCorrected = {{
    {"pressure", "sum m_b [T_a/rho_a^2 . G_a(b) - T_b/rho_b^2 . G_b(a)] with T = -P I (seed 001 eqs. 48-51)"},
    {"artificial viscosity Pi", "-sum m_b Pi_ab (G_a(b) - G_b(a))/2"},
    {"", ""},
    {"viscous stress", "the same sum with T = 2 mu (D - tr D / 3 I), mu = rho nu, D from eq. 52 (seed 001 eq. 51)"},
    {"", ""},
}};

/// One pair's contribution to each term.
struct PairOut {
  std::array<Vec3, kTermCount> a{};
  std::array<double, kTermCount> du{};
};

/// The pair loop: particle i's interacting neighbours in list order (pair_block.h, as the force
/// loops take them), each pair split by `pair(j, r_vec, r, out)`, summed per term and per neighbour.
/// Which terms the scene's physics runs (the others are left out of the list).
using Active = std::array<bool, kTermCount>;

template <class Pair>
void sum_pairs(const StageContext& c, std::size_t i, bool skip_walls, const TermTable& table, const Active& active,
               Pair&& pair, std::vector<InspectTerm>* terms, std::vector<InspectNeighbour>* nb) {
  const Particles& p = c.p;
  const auto& h = p[Field::H];
  const auto& m = p[Field::Mass];
  const double rho_i = p.has(Field::Density) ? p[Field::Density][i] : std::nan("");
  std::vector<double> R2;  // (support h)^2 of every particle, ghosts included [length^2]
  support_radii2(p, c.kernel.support(), R2);
  PairBlock<0> near;
  const std::size_t count = gather_pairs(p, R2.data(), i, c.nl.of(i), skip_walls, near);
  std::array<InspectTerm, kTermCount> sum{};
  for (std::size_t k = 0; k < count; ++k) {
    const std::uint32_t j = near.j[k];
    const Vec3 r{p.x[0][i] - p.x[0][j], p.x[1][i] - p.x[1][j], p.x[2][i] - p.x[2][j]};
    const double rr = r.norm();
    PairOut o;
    pair(j, r, rr, o);
    InspectNeighbour n;
    n.id = p.id[j];
    n.ghost = j >= p.size();
    n.wall = p.kind[j] != 0;
    n.x = {p.x[0][j], p.x[1][j], p.x[2][j]};
    n.r = rr;
    n.W = c.kernel.W(rr, h[i]);
    n.share = m[j] * n.W / rho_i;
    for (int t = 0; t < kTermCount; ++t) {
      sum[t].a += o.a[t];
      sum[t].dudt += o.du[t];
      sum[t].a_scale += o.a[t].norm();
      sum[t].dudt_scale += std::abs(o.du[t]);
      n.a += o.a[t];
      n.dudt += o.du[t];
    }
    nb->push_back(n);
  }
  for (int t = 0; t < kTermCount; ++t) {
    if (table[t].name[0] == '\0' || !active[t]) continue;
    sum[t].name = table[t].name;
    sum[t].source = table[t].source;
    terms->push_back(std::move(sum[t]));
  }
}

/// Pi_ab of the pair from the pair loops' own viscosity term (terms/visc_terms.h); 0 unless it has one.
double pi_of(const StageContext& c, std::size_t i, std::size_t j, double vdotr, double r2) {
  const Particles& p = c.p;
  const auto& h = p[Field::H];
  return terms::with_viscosity(c.prm.physics, [&](auto tag) -> double {
    using V = typename decltype(tag)::type;
    if constexpr (V::kPi) {
      const auto& rho = p[Field::Density];
      const auto& cs = p[Field::SoundSpeed];
      return V(c).pi(i, static_cast<std::uint32_t>(j), vdotr, r2, h[i], h[j], rho[i], rho[j], cs[i], cs[j]);
    } else {
      return 0.0;
    }
  });
}

/// The Laplacian viscosity's k_ab of the pair (terms/visc_laplacian.h).
double laplacian_of(const StageContext& c, std::size_t i, std::size_t j, double rdW, double r2) {
  const Particles& p = c.p;
  const auto& rho = p[Field::Density];
  const auto& h = p[Field::H];
  return terms::ViscLaplacian(c).factor(static_cast<std::uint32_t>(j), p[Field::Mass][j], rho[i], rho[j], rdW, r2, 0.5 * (h[i] + h[j]));
}

Vec3 velocity_difference(const Particles& p, std::size_t i, std::size_t j) {
  return {p.v[0][i] - p.v[0][j], p.v[1][i] - p.v[1][j], p.v[2][i] - p.v[2][j]};
}

// forces_standard.cpp, term by term.
void standard(const StageContext& c, std::size_t i, std::vector<InspectTerm>* terms, std::vector<InspectNeighbour>* nb) {
  const Particles& p = c.p;
  const Physics& ph = c.prm.physics;
  const Kernel& K = c.kernel;
  const auto& m = p[Field::Mass];
  const auto& rho = p[Field::Density];
  const auto& h = p[Field::H];
  const auto& P = p[Field::Pressure];
  const bool grad_h = ph.density == DensityMode::Summation || ph.density == DensityMode::Volume;
  const bool energy = ph.energy == Toggle::On;
  const terms::Conduction cond(c);
  const bool conduction = cond.on;
  auto A = [&](std::size_t b) { return pressure_factor(P[b], grad_h ? p[Field::Omega][b] : 1.0, rho[b]); };
  const double Ai = A(i);
  const Active active = {true, ph.viscosity == ViscType::Monaghan, ph.viscosity == ViscType::Laplacian, false, conduction};
  sum_pairs(c, i, ph.walls == WallType::LennardJones, kStandard, active,
            [&](std::size_t j, const Vec3& r, double rr, PairOut& o) {
              double Wi, dWi, Wj, dWj;
              K.eval(K.scale(h[i]), rr, Wi, dWi);
              K.eval(K.scale(h[j]), rr, Wj, dWj);
              const double dWm = 0.5 * (dWi + dWj);
              const Vec3 dv = velocity_difference(p, i, j);
              const double vdotr = dv.dot(r), w = vdotr / rr;
              o.a[kPressure] = r * (-m[j] * (Ai * dWi + A(j) * dWj) / rr);
              if (energy) o.du[kPressure] = Ai * m[j] * w * dWi;
              const double Pi = pi_of(c, i, j, vdotr, rr * rr);
              o.a[kViscPi] = r * (-m[j] * Pi * dWm / rr);
              if (energy) o.du[kViscPi] = terms::ViscMonaghan::heat(m[j], Pi, w, dWm);
              if (ph.viscosity == ViscType::Laplacian) {
                const double k = laplacian_of(c, i, j, rr * dWm, rr * rr);
                o.a[kViscLaplacian] = dv * k;
                if (energy) o.du[kViscLaplacian] = -terms::ViscLaplacian::work(k, dv.norm2());
              }
              if (conduction) {
                const auto& u = p[Field::Energy];
                o.du[kConduction] = cond.pair(m[j], u[i], u[j], P[i], P[j], rho[i], rho[j], dWm);
              }
            },
            terms, nb);
}

/// The fields the corrected formulations' term splits read, and a pair's corrected gradients.
struct CorrectedView {
  const StageContext& c;
  const std::vector<double>&m, &rho, &P;
  const CorrectionFields corr;
  explicit CorrectedView(const StageContext& ctx)
      : c(ctx), m(ctx.p[Field::Mass]), rho(ctx.p[Field::Density]), P(ctx.p[Field::Pressure]), corr(ctx.p) {}

  /// G_a(b) and G_b(a) of a pair (corrected_kernel.h), r = x_a - x_b.
  void gradients(std::size_t i, std::size_t j, const Vec3& r, double rr, Vec3& Gi, Vec3& Gj) const {
    const auto& h = c.p[Field::H];
    double Wi, dWi, Wj, dWj;
    c.kernel.eval(c.kernel.scale(h[i]), rr, Wi, dWi);
    c.kernel.eval(c.kernel.scale(h[j]), rr, Wj, dWj);
    const double rv[3] = {r.x, r.y, r.z}, mr[3] = {-r.x, -r.y, -r.z};
    double gi[3], gj[3];
    corr.gradient(i, rv, Wi, dWi / rr, gi);
    corr.gradient(j, mr, Wj, dWj / rr, gj);
    Gi = {gi[0], gi[1], gi[2]};
    Gj = {gj[0], gj[1], gj[2]};
  }
};

// forces_standard_corrected.cpp, term by term.
void standard_corrected(const StageContext& c, std::size_t i, std::vector<InspectTerm>* terms,
                        std::vector<InspectNeighbour>* nb) {
  const Particles& p = c.p;
  const Physics& ph = c.prm.physics;
  const CorrectedView cv(c);
  const double Ai = pressure_factor(cv.P[i], 1.0, cv.rho[i]);
  const Active active = {true, ph.viscosity == ViscType::Monaghan, ph.viscosity == ViscType::Laplacian, false, false};
  sum_pairs(c, i, !c.walls_in_sums(), kStandardCorrected, active,
            [&](std::size_t j, const Vec3& r, double rr, PairOut& o) {
              Vec3 Gi, Gj;
              cv.gradients(i, j, r, rr, Gi, Gj);
              const Vec3 Gm = (Gi - Gj) * 0.5;
              const double Aj = pressure_factor(cv.P[j], 1.0, cv.rho[j]);
              const Vec3 dv = velocity_difference(p, i, j);
              o.a[kPressure] = (Gi * Ai - Gj * Aj) * -cv.m[j];
              o.a[kViscPi] = Gm * (-cv.m[j] * pi_of(c, i, j, dv.dot(r), rr * rr));
              if (ph.viscosity == ViscType::Laplacian) o.a[kViscLaplacian] = dv * laplacian_of(c, i, j, r.dot(Gm), rr * rr);
            },
            terms, nb);
}

// forces_corrected.cpp, term by term: the stress split into its pressure and viscous parts.
void corrected(const StageContext& c, std::size_t i, std::vector<InspectTerm>* terms, std::vector<InspectNeighbour>* nb) {
  const Particles& p = c.p;
  const Physics& ph = c.prm.physics;
  const CorrectedView cv(c);
  const int d = p.dim();
  const bool stress = ph.viscosity == ViscType::Laplacian;
  // 2 mu (D - tr D / 3 I) of particle b, row-major 3 x 3 (zero without the Laplacian viscosity)
  const ViscousStress vstress(p, d, c.prm.visc.nu, stress);
  auto viscous = [&](std::size_t b, double T[9]) {
    std::fill(T, T + 9, 0.0);
    if (stress) vstress.add(b, cv.rho[b], T);
  };
  double Tvi[9];
  viscous(i, Tvi);
  const Active active = {true, ph.viscosity == ViscType::Monaghan, false, stress, false};
  sum_pairs(c, i, !c.walls_in_sums(), kCorrected, active,
            [&](std::size_t j, const Vec3& r, double rr, PairOut& o) {
              Vec3 Gi, Gj;
              cv.gradients(i, j, r, rr, Gi, Gj);
              const double gi[3] = {Gi.x, Gi.y, Gi.z}, gj[3] = {Gj.x, Gj.y, Gj.z};
              const double ri2 = cv.rho[i] * cv.rho[i], rj2 = cv.rho[j] * cv.rho[j];
              double Tvj[9];
              viscous(j, Tvj);
              double press[3] = {}, visc[3] = {};
              for (int k = 0; k < d; ++k) {
                press[k] = cv.m[j] * (-cv.P[i] / ri2 * gi[k] + cv.P[j] / rj2 * gj[k]);
                for (int l = 0; l < d; ++l) visc[k] += cv.m[j] * (Tvi[3 * k + l] / ri2 * gi[l] - Tvj[3 * k + l] / rj2 * gj[l]);
              }
              o.a[kPressure] = {press[0], press[1], press[2]};
              o.a[kViscStress] = {visc[0], visc[1], visc[2]};
              o.a[kViscPi] = (Gi - Gj) * (-0.5 * cv.m[j] * pi_of(c, i, j, velocity_difference(p, i, j).dot(r), rr * rr));
            },
            terms, nb);
}

}  // namespace

std::string force_terms(const StageContext& c, std::size_t i, std::vector<InspectTerm>* terms,
                        std::vector<InspectNeighbour>* nb) {
  switch (c.prm.physics.force) {
    case ForceType::Standard: standard(c, i, terms, nb); return "standard";
    case ForceType::StandardCorrected: standard_corrected(c, i, terms, nb); return "standard-corrected";
    case ForceType::Corrected: corrected(c, i, terms, nb); return "corrected (stress form)";
    case ForceType::None: break;
  }
  return "";
}

}  // namespace sph
