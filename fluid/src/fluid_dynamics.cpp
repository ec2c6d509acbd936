#include "fluid_dynamics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "density_diffusion.hpp"
#include "dissipation.hpp"
#include "hydrostatic_density_diffusion.hpp"
#include "sphcore/continuity_pair.hpp"
#include "sphcore/kernel.hpp"
#include "sphcore/kernel_shape.hpp"
#include "sphcore/momentum_bracket.hpp"
#include "sphcore/parallel.hpp"
#include "sphcore/renormalisation.hpp"
#include "sphcore/wall_pressure.hpp"
#include "viscous_stress.hpp"

namespace cosph::fluid {

namespace kernel = sph::kernel;

// The neighbour passes run through sph::parallel_pass rather than
// sph::parallel_for: flattened into its loop, the two pair passes ran slower
// on large scenes.

namespace {
double support_squared(const FluidParameters& par) {
  const double reach = kernel::kSupport * par.h;
  return reach * reach;
}
}  // namespace

void compute_continuity_and_gradients(FluidParticles& P, const sph::NeighbourList& pairs,
                                      const FluidParameters& par) {
  const long n = static_cast<long>(P.size());
  const double diffusion = par.delta * par.h * par.c0;
  const HydrostaticDensityDifference rho_hydrostatic(par.run.gravity,
                                                     TaitEquationOfState(par.rho0, par.c0));
  const double inverse_rho0_c0 = 1.0 / (par.rho0 * par.c0);
  P.grad_rho_next.resize(P.size());
  P.volume.resize(P.size());
  P.spray.resize(P.size());
  const bool threaded = sph::worth_threads(P.size());
  P.continuity_neighbours.resize(P.size());
  sph::parallel_pass(n, threaded, [&](long i) {
    P.volume[i] = P.m[i] / P.rho[i];
    P.continuity_neighbours[i] = {P.x[i], P.v[i], P.rho[i], P.volume[i], P.p[i]};
  });

  // The dissipation is chosen once for the whole pass, at compile time, so
  // that the pair loop holds only its terms: with a run-time branch there
  // delta-SPH's pass paid for the Riemann wall term it never takes.
  with_dissipation(par.dissipation, [&](auto dissipation) {
    sph::parallel_pass(n, threaded, [&](long i) {
      if (!P.is_water(i)) return;
      const Vec2 x_i = P.x[i], v_i = P.v[i], grad_rho_i = P.grad_rho[i];
      const double rho_i = P.rho[i];
      sph::GradientSums sums;
      Vec2 grad_rho_raw = Vec2::Zero();
      double drho_i = 0.0, diffusion_i = 0.0;
      bool wall_in_reach = false;
      const auto neighbours = pairs.neighbours(i);
      const auto F = pairs.gradient_factors(i);
      const auto r = pairs.distances(i);
      const FluidParticles::ContinuityNeighbour* const hot = P.continuity_neighbours.data();
      for (std::size_t k = 0; k < neighbours.size(); ++k) {
        const int j = neighbours[k];
        const FluidParticles::ContinuityNeighbour& n_j = hot[j];
        const Vec2 x_ij = x_i - n_j.x;
        const Vec2 grad_W_ij = F[k] * x_ij;
        const double rho_j = n_j.rho, V_j = n_j.V;
        const Vec2 v_ij = v_i - n_j.v;
        drho_i += sph::continuity_pair(rho_i, V_j, v_ij, grad_W_ij);
        // The Riemann problem is solved against the walls too, the wall's side
        // mirroring i (riemann_wall_pressure): left out, the water by a wall
        // would lose density to the water above it with nothing flowing back
        // from below.
        if constexpr (dissipation == Dissipation::riemann) {
          const double P_j =
              P.is_water(j)
                  ? n_j.p
                  : sph::riemann_wall_pressure(P.p[i], rho_i, par.run.gravity - P.wall_a[j], x_ij);
          drho_i += sph::riemann_density_dissipation_pair(rho_i, V_j, P.p[i], P_j, F[k], r[k],
                                                          inverse_rho0_c0);
        }
        if (!P.is_water(j)) {
          wall_in_reach = true;
          continue;
        }
        if constexpr (dissipation == Dissipation::delta_sph)
          diffusion_i +=
              density_diffusion_pair(rho_i, rho_j, F[k], grad_rho_i, P.grad_rho[j], V_j, grad_W_ij);
        if constexpr (dissipation == Dissipation::fourtakas)
          diffusion_i +=
              hydrostatic_density_diffusion_pair(rho_i, rho_j, rho_hydrostatic(x_ij), F[k], V_j);
        // Riemann: above, with the walls.
        const Vec2 Vg = V_j * grad_W_ij;
        sums.add(Vg, x_ij, v_ij);
        grad_rho_raw += (rho_j - rho_i) * Vg;
      }
      const sph::RenormalisedGradient gradient = sph::renormalised_gradient(sums);
      P.drho[i] = drho_i + diffusion * diffusion_i;
      P.spray[i] = !wall_in_reach && !gradient.renormalised;
      P.grad_rho_next[i] = gradient.L * grad_rho_raw;
      P.tau[i] = viscous_stress(par.mu, gradient.grad_v);
    });
  });
  P.grad_rho.swap(P.grad_rho_next);
}

std::vector<int> walls_in_reach(const FluidParticles& P, const sph::CellGrid& grid, double reach) {
  const long n = static_cast<long>(P.size());
  const double reach2 = reach * reach;
  std::vector<std::uint8_t> in_reach(P.size(), 0);
  sph::parallel_pass(n, sph::worth_threads(P.size()), [&](long w) {
    if (P.is_water(w)) return;
    const Vec2 x_w = P.x[w];
    bool found = false;
    grid.for_each_candidate_range(x_w, [&](int begin, int end) {
      for (int f = begin; f < end && !found; ++f)
        found = P.is_water(f) && (x_w - P.x[f]).squaredNorm() < reach2;
    });
    in_reach[w] = found;
  });
  std::vector<int> walls;
  for (long w = 0; w < n; ++w)
    if (in_reach[w]) walls.push_back(static_cast<int>(w));
  return walls;
}

void rest_walls_out_of_reach(FluidParticles& P, const std::vector<int>& walls_in_reach,
                             const TaitEquationOfState& eos) {
  auto next_in_reach = walls_in_reach.begin();
  for (std::size_t w = 0; w < P.size(); ++w) {
    if (P.is_water(w)) continue;
    if (next_in_reach != walls_in_reach.end() && *next_in_reach == static_cast<int>(w)) {
      ++next_in_reach;
      continue;
    }
    P.p[w] = 0.0;
    P.rho[w] = eos.rho0();
    P.tau[w] = Mat2::Zero();
    P.wall_n[w] = Vec2::Zero();
  }
}

void compute_wall_pressure(FluidParticles& P, const sph::CellGrid& grid,
                           const std::vector<int>& walls, const FluidParameters& par,
                           const TaitEquationOfState& eos) {
  const long n = static_cast<long>(walls.size());
  const double support2 = support_squared(par);
  const kernel::ShapedValue W_of(par.kernel, par.h);
  sph::parallel_pass(n, sph::worth_threads(P.size()), [&](long k) {
    const int w = walls[k];
    const Vec2 x_w = P.x[w];
    sph::WallPressureSum sum;
    grid.for_each_candidate_range(x_w, [&](int begin, int end) {
      for (int f = begin; f < end; ++f) {
        if (!P.is_water(f)) continue;
        const Vec2 x_wf = x_w - P.x[f];
        const double r2 = x_wf.squaredNorm();
        if (r2 >= support2) continue;
        sum.add(P.p[f], P.rho[f], x_wf, W_of(std::sqrt(r2)));
      }
    });
    // Bounded below so that the Tait law can still give the wall a density.
    // A moving wall's acceleration enters as g - a_w (fixed walls: a_w = 0).
    P.p[w] = std::max(sum.wall_pressure(par.run.gravity - P.wall_a[w]), -0.5 * eos.P0());
    // A wall in reach at the sort may have no water within 2h: rho0 without
    // the pow().
    P.rho[w] = P.p[w] == 0.0 ? eos.rho0() : eos.density(P.p[w]);
    P.tau[w] = Mat2::Zero();
    if (par.wall_friction == WallFriction::normal)  // only that option reads it
      P.wall_n[w] = sum.normal_to_water();
  });
}

void compute_accelerations(FluidParticles& P, const sph::NeighbourList& pairs,
                           const FluidParameters& par) {
  const long n = static_cast<long>(P.size());
  P.sigma.resize(P.size());
  P.inverse_rho.resize(P.size());
  P.momentum_neighbours.resize(P.size());
  const bool threaded = sph::worth_threads(P.size());
  sph::parallel_pass(n, threaded, [&](long i) {
    P.sigma[i] = total_stress(P.p[i], P.tau[i]);
    P.inverse_rho[i] = 1.0 / P.rho[i];
    P.momentum_neighbours[i] = {P.x[i], P.v[i], P.sigma[i], P.rho[i], P.inverse_rho[i], P.m[i]};
  });

  // Each pair of water particles is worked out once, by the lower index, which
  // gives the higher one its share (sph::OrderedShares): half the pair terms
  // of visiting every pair from both ends. A wall has no list and needs no
  // acceleration; the water visits its walls from its own side.
  P.a.resize(P.size());
  sph::OrderedShares<Vec2>& shares = P.a_shares;
  const long blocks = shares.prepare(n, threaded, [&](long i) -> long {
    const auto neighbours = pairs.neighbours(i);
    return neighbours.empty() ? i : neighbours.back();
  });
  with_dissipation(par.dissipation, [&](auto dissipation) {
    const MomentumDissipation<dissipation> Pi_of(par.h, par.c0, par.A, par.B);
    sph::parallel_pass(blocks, threaded, [&](long b) {
      // The arrays and Pi's constants held in locals: a share is stored
      // through Eigen's packet stores, which may alias anything, so read
      // through P, shares and Pi_of they were all loaded again for every pair.
      const Kind* const kind = P.kind.data();
      const FluidParticles::MomentumNeighbour* const hot = P.momentum_neighbours.data();
      Vec2* const a = P.a.data();
      const auto share = shares.block_shares(b, a);
      const MomentumDissipation<dissipation> Pi = Pi_of;
      const WallFriction wall_friction = par.wall_friction;
      const Vec2* const wall_n = P.wall_n.data();
      const long begin = shares.begin(b), end = shares.end(b);
      for (long i = begin; i < end; ++i) a[i].setZero();
      for (long i = begin; i < end; ++i) {
        if (kind[i] != Kind::water) continue;
        const Vec2 x_i = hot[i].x, v_i = hot[i].v;
        const double m_i = hot[i].m, rho_i = hot[i].rho, inverse_rho_i = hot[i].inverse_rho;
        const SymmetricStress sigma_i = hot[i].sigma;
        const auto bracket_times_gradient_of = [&](int j, double F_ij, double r_ij) {
          const FluidParticles::MomentumNeighbour& n_j = hot[j];
          const Vec2 x_ij = x_i - n_j.x, v_ij = v_i - n_j.v;
          const double rho_ij = 0.5 * (rho_i + n_j.rho);
          // The walls' friction's test first: it spares that pair loop a load of kind[j].
          const double Pi_ij =
              wall_friction == WallFriction::dissipation || kind[j] == Kind::water
                  ? Pi(x_ij, v_ij, rho_ij, r_ij)
                  : wall_dissipation(Pi, wall_friction, x_ij, v_ij, wall_n[j], rho_ij, r_ij);
          return sph::bracket_times_gradient(sigma_i, n_j.sigma, inverse_rho_i, n_j.inverse_rho,
                                             Pi_ij, F_ij * x_ij);
        };
        const auto neighbours = pairs.neighbours(i);
        const auto F = pairs.gradient_factors(i);
        const auto r = pairs.distances(i);
        const std::size_t later = static_cast<std::size_t>(
            std::upper_bound(neighbours.begin(), neighbours.end(), static_cast<int>(i)) -
            neighbours.begin());
        Vec2 a_i = Vec2::Zero();
        // The water before i has given i its share already; its walls have not.
        for (std::size_t k = 0; k < later; ++k) {
          const int j = neighbours[k];
          if (kind[j] == Kind::water) continue;
          a_i += hot[j].m * bracket_times_gradient_of(j, F[k], r[k]);
        }
        // A later wall is sent a share too, which nothing reads: cheaper than
        // telling walls apart here.
        for (std::size_t k = later; k < neighbours.size(); ++k) {
          const int j = neighbours[k];
          const Vec2 bracket_times_gradient_ij = bracket_times_gradient_of(j, F[k], r[k]);
          a_i += hot[j].m * bracket_times_gradient_ij;
          share(j) -= m_i * bracket_times_gradient_ij;
        }
        a[i] += a_i;
      }
    });
  });
  shares.merge(P.a, threaded);
  // The arrays in locals over each share: the Eigen store to a may alias
  // anything, and through P both addresses were loaded again after it.
  sph::for_each_share(P.size(), threaded, [&](long begin, long end, long) {
    const Kind* const kind = P.kind.data();
    Vec2* const a = P.a.data();
    const Vec2 g = par.run.gravity;
    for (long i = begin; i < end; ++i)
      a[i] = kind[i] == Kind::water ? Vec2(a[i] + g) : Vec2::Zero();
  });
}

std::vector<Vec2> forces_on_walls(const FluidParticles& P, const sph::NeighbourList& pairs,
                                  const FluidParameters& par) {
  std::vector<Vec2> force(P.first_wall_id.size(), Vec2::Zero());
  with_dissipation(par.dissipation, [&](auto dissipation) {
    const MomentumDissipation<dissipation> Pi_of(par.h, par.c0, par.A, par.B);
    for (std::size_t i = 0; i < P.size(); ++i) {
      if (!P.is_water(i)) continue;
      const auto neighbours = pairs.neighbours(static_cast<long>(i));
      const auto F = pairs.gradient_factors(static_cast<long>(i));
      const auto r = pairs.distances(static_cast<long>(i));
      for (std::size_t k = 0; k < neighbours.size(); ++k) {
        const int j = neighbours[k];
        if (P.is_water(j)) continue;
        const Vec2 x_ij = P.x[i] - P.x[j];
        const double Pi_ij = wall_dissipation(Pi_of, par.wall_friction, x_ij, P.v[i] - P.v[j],
                                              P.wall_n[j], 0.5 * (P.rho[i] + P.rho[j]), r[k]);
        force[P.wall_of(j)] -= P.m[i] * P.m[j] *
                               sph::bracket_times_gradient(P.sigma[i], P.sigma[j], P.inverse_rho[i],
                                                           P.inverse_rho[j], Pi_ij, F[k] * x_ij);
      }
    }
  });
  return force;
}

}  // namespace cosph::fluid
