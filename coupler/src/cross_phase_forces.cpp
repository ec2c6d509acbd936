#include "cross_phase_forces.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "sphcore/artificial_viscosity.hpp"
#include "sphcore/cell_grid.hpp"
#include "sphcore/continuity_pair.hpp"
#include "sphcore/kernel.hpp"
#include "sphcore/kernel_shape.hpp"
#include "sphcore/momentum_bracket.hpp"
#include "sphcore/riemann_dissipation.hpp"
#include "sphcore/wall_pressure.hpp"

namespace cosph::coupler {

namespace {

struct Pair {
  int f, s;
  Vec2 x_fs;  // x_f - x_s
  double h_fs, W_fs;
  Vec2 grad_W;  // grad_f W_fs
};

// h_fs is the mean of the two phases' h for both interface models
// (docs/physics.md, "Coupling"). A moving wall with the water's own h, as the
// water's walls have, shrinks the mismatch of the kernel sums over water and
// wall where a fine plate meets coarser water, and with it the pressure pulse
// a clamped plate sends into still water; but at the elastic plate's
// resolutions that support spans the plate, so the wall pressure mixes the
// water of both sides once it flows past, and the free plate bent less.
// W and grad W are of `shape` (the GradientFactor's): both shapes reach 2h, so
// which pairs there are does not depend on it.
template <class GradientFactor>
std::vector<Pair> find_pairs(const sph::InterfaceParticles& F, const sph::InterfaceParticles& S,
                             sph::kernel::Shape shape) {
  std::vector<Pair> pairs;
  // Either shape's support kSupport h_fs is 2 h_fs = h_f + h_s, so no pair
  // reaches farther than the two largest h.
  static_assert(sph::kernel::kSupport == 2.0, "the reach h_f + h_s is the support");
  const double range =
      *std::max_element(F.h.begin(), F.h.end()) + *std::max_element(S.h.begin(), S.h.end());
  sph::CellGrid grid;
  grid.build(S.x, range);
  // The solid's positions and h in the grid's order: a candidate range
  // streams memory instead of gathering through the order.
  const std::vector<int>& order = grid.order();
  std::vector<Vec2> x_s(S.size());
  std::vector<double> h_s(S.size());
  for (std::size_t k = 0; k < order.size(); ++k) x_s[k] = S.x[order[k]], h_s[k] = S.h[order[k]];
  std::vector<int> candidate(S.size());
  std::vector<double> candidate_r2(S.size());
  // Each phase has one h in practice, so the kernel's constants are taken
  // again only when h_fs changes, not for every pair.
  double kernel_h = 1.0;
  sph::kernel::ShapedValue W_of(shape, kernel_h);
  GradientFactor gradient_factor(kernel_h);
  for (std::size_t f = 0; f < F.size(); ++f) {
    const Vec2 x_f = F.x[f];
    const double h_f = F.h[f];
    grid.for_each_candidate_range(x_f, [&](int begin, int end) {
      // Every candidate is written, and the count moves past it only if it is
      // a pair: no branch to mispredict.
      std::size_t count = 0;
      for (int k = begin; k < end; ++k) {
        const double r2 = (x_f - x_s[k]).squaredNorm(), reach = h_f + h_s[k];
        candidate[count] = k;
        candidate_r2[count] = r2;
        count += static_cast<std::size_t>(r2 < reach * reach && r2 > 0.0);
      }
      for (std::size_t n = 0; n < count; ++n) {
        const int k = candidate[n];
        const double h_fs = 0.5 * (h_f + h_s[k]), r = std::sqrt(candidate_r2[n]);
        if (h_fs != kernel_h) {
          kernel_h = h_fs;
          W_of = sph::kernel::ShapedValue(shape, h_fs);
          gradient_factor = GradientFactor(h_fs);
        }
        const Vec2 x_fs = x_f - x_s[k];
        pairs.push_back(
            {static_cast<int>(f), order[k], x_fs, h_fs, W_of(r), gradient_factor(r) * x_fs});
      }
    });
  }
  return pairs;
}

std::vector<Pair> find_pairs(const sph::InterfaceParticles& F, const sph::InterfaceParticles& S,
                             sph::kernel::Shape shape) {
  return sph::kernel::with_gradient_factor(shape, 1.0, [&](const auto gradient_factor) {
    return find_pairs<std::decay_t<decltype(gradient_factor)>>(F, S, shape);
  });
}

void add_stress_sum(const sph::InterfaceParticles& F, const sph::InterfaceParticles& S,
                    const std::vector<Pair>& pairs, const CrossPhaseParameters& par,
                    CrossPhaseForces& out) {
  for (const Pair& p : pairs) {
    const double Pi_fs =
        sph::artificial_viscosity(p.x_fs, F.v[p.f] - S.v[p.s], p.h_fs, 0.5 * (F.c[p.f] + S.c[p.s]),
                                  0.5 * (F.rho[p.f] + S.rho[p.s]), par.A, par.B);
    const Vec2 a_f = sph::momentum_pair(S.m[p.s], F.sigma[p.f], S.sigma[p.s], F.rho[p.f],
                                        S.rho[p.s], Pi_fs, p.grad_W);
    out.fluid_a[p.f] += a_f;
    out.solid_a[p.s] -= (F.m[p.f] * a_f) / S.m[p.s];
  }
}

// Compiled once with the water's Riemann terms and once without, as the
// fluid's continuity pass is (with_dissipation): the other waters' pair loop
// holds only its own terms, and its results do not move with the Riemann
// water's.
template <bool kRiemann>
void add_moving_wall(const sph::InterfaceParticles& F, const sph::InterfaceParticles& S,
                     const std::vector<Pair>& pairs, const CrossPhaseParameters& par,
                     CrossPhaseForces& out) {
  std::vector<sph::WallPressureSum> sums(S.size());
  for (const Pair& p : pairs)
    sums[p.s].add(-0.5 * F.sigma[p.f].trace(), F.rho[p.f], -p.x_fs, p.W_fs);
  // a_w: the solid's total acceleration from its last closing kick
  // (docs/physics.md, "Moving wall"), if the case asks for it
  // (coupling.wall_acceleration); otherwise, or when the solid does not send
  // it, the wall is treated as fixed (a_w = 0), as the water's own walls are.
  const bool accelerating = par.wall_acceleration && S.has_acceleration();
  std::vector<double>& P_w = out.wall_pressure;
  P_w.resize(S.size());
  for (std::size_t s = 0; s < S.size(); ++s)
    P_w[s] = sums[s].wall_pressure(accelerating ? Vec2(par.gravity - S.a[s]) : par.gravity);
  // Each solid particle's normal once, not per pair: only "normal" reads it.
  std::vector<Vec2> n_s(S.size(), Vec2::Zero());
  if (par.wall_friction == fluid::WallFriction::normal)
    for (std::size_t s = 0; s < S.size(); ++s) n_s[s] = sums[s].normal_to_water();

  for (const Pair& p : pairs) {
    const double rho_f = F.rho[p.f], V_s = S.m[p.s] / S.rho[p.s];
    const Vec2 v_fs = F.v[p.f] - S.v[p.s];
    // The water's own c0 (the sound speed it sends) and density, as against
    // its own walls.
    const auto Pi = [&](const Vec2& x_fs, const Vec2& v, double rho, double r) {
      if constexpr (kRiemann)
        return sph::RiemannLimitedDissipation(F.c[p.f])(x_fs, v, rho, r);
      else
        return sph::artificial_viscosity(x_fs, v, p.h_fs, F.c[p.f], rho, par.A, par.B);
    };
    const double Pi_fs = fluid::wall_dissipation(Pi, par.wall_friction, p.x_fs, v_fs, n_s[p.s],
                                                 rho_f, p.x_fs.norm());
    // The wall particle has the water's density and the solid particle's volume.
    const Vec2 a_f =
        sph::momentum_pair(V_s * rho_f, F.sigma[p.f], -P_w[p.s] * sph::Mat2::Identity(), rho_f,
                           rho_f, Pi_fs, p.grad_W);
    out.fluid_a[p.f] += a_f;
    out.solid_a[p.s] -= (F.m[p.f] * a_f) / S.m[p.s];
    out.fluid_drho[p.f] += sph::continuity_pair(rho_f, V_s, v_fs, p.grad_W);
    if constexpr (kRiemann) {
      // The wall's side of the Riemann problem mirrors the water particle, as
      // the water's own walls do (not P_w, the kernel mean that lies below the
      // water's pressure where a flow stagnates on the plate), with the body
      // force P_w takes. The pressure is the one P_w is extrapolated from,
      // the trace of the stress sent.
      const double P_f = -0.5 * F.sigma[p.f].trace();
      const Vec2 body_force = accelerating ? Vec2(par.gravity - S.a[p.s]) : par.gravity;
      const double P_s = sph::riemann_wall_pressure(P_f, rho_f, body_force, p.x_fs);
      // grad_f W_fs = F_fs x_fs, F_fs taken again as find_pairs took it.
      const double F_fs = sph::kernel::with_gradient_factor(
          par.kernel, p.h_fs,
          [&](const auto gradient_factor) { return gradient_factor(p.x_fs.norm()); });
      out.fluid_drho[p.f] += sph::riemann_density_dissipation_pair(
          rho_f, V_s, P_f, P_s, F_fs, p.x_fs, 1.0 / (par.rho0 * F.c[p.f]));
    }
  }
}

}  // namespace

CrossPhaseForces compute_cross_phase_forces(const sph::InterfaceParticles& F,
                                            const sph::InterfaceParticles& S,
                                            const CrossPhaseParameters& par) {
  CrossPhaseForces out;
  out.fluid_a.assign(F.size(), Vec2::Zero());
  out.solid_a.assign(S.size(), Vec2::Zero());
  if (par.model == InterfaceModel::moving_wall) {
    out.fluid_drho.assign(F.size(), 0.0);
    out.wall_pressure.assign(S.size(), 0.0);
  }
  if (F.size() == 0 || S.size() == 0) return out;

  const std::vector<Pair> pairs = find_pairs(F, S, par.kernel);
  out.pairs = static_cast<long>(pairs.size());
  if (par.model == InterfaceModel::stress_sum)
    add_stress_sum(F, S, pairs, par, out);
  else if (par.riemann_dissipation)
    add_moving_wall<true>(F, S, pairs, par, out);
  else
    add_moving_wall<false>(F, S, pairs, par, out);

  // The totals the solvers will feel, summed from what they are sent: that
  // they cancel is a check, not an identity.
  for (std::size_t f = 0; f < F.size(); ++f) out.force_on_fluid += F.m[f] * out.fluid_a[f];
  for (std::size_t s = 0; s < S.size(); ++s) out.force_on_solid += S.m[s] * out.solid_a[s];
  return out;
}

}  // namespace cosph::coupler
