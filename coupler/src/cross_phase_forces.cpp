#include "cross_phase_forces.hpp"

#include <algorithm>
#include <cmath>

#include "sphcore/cell_grid.hpp"
#include "sphcore/kernel.hpp"
#include "sphcore/pair_terms.hpp"

namespace cosph::coupler {

CrossPhaseForces compute_cross_phase_forces(const sph::InterfaceParticles& F,
                                            const sph::InterfaceParticles& S,
                                            const CrossPhaseParameters& par) {
  CrossPhaseForces out;
  out.fluid_a.assign(F.size(), Vec2::Zero());
  out.solid_a.assign(S.size(), Vec2::Zero());
  if (F.size() == 0 || S.size() == 0) return out;

  // 2 h_fs = h_f + h_s, so no pair reaches farther than the two largest h.
  const double range =
      *std::max_element(F.h.begin(), F.h.end()) + *std::max_element(S.h.begin(), S.h.end());
  sph::CellGrid grid;
  grid.build(S.x, range);
  const std::vector<int>& order = grid.order();

  for (std::size_t f = 0; f < F.size(); ++f) {
    const Vec2 x_f = F.x[f];
    grid.for_each_candidate_range(x_f, [&](int begin, int end) {
      for (int k = begin; k < end; ++k) {
        const int s = order[k];
        const Vec2 x_fs = x_f - S.x[s];
        const double reach = F.h[f] + S.h[s];
        const double r2 = x_fs.squaredNorm();
        if (r2 >= reach * reach || r2 == 0.0) continue;
        const double h_fs = 0.5 * reach, r = std::sqrt(r2);
        const Vec2 grad_W = sph::kernel::grad_W(x_fs, r, h_fs);
        const double Pi_fs =
            sph::artificial_viscosity(x_fs, F.v[f] - S.v[s], h_fs, 0.5 * (F.c[f] + S.c[s]),
                                      0.5 * (F.rho[f] + S.rho[s]), par.A, par.B);
        const Vec2 a_f =
            sph::momentum_pair(S.m[s], F.sigma[f], S.sigma[s], F.rho[f], S.rho[s], Pi_fs, grad_W);
        const Vec2 force = F.m[f] * a_f;  // on f, from s
        out.fluid_a[f] += a_f;
        out.solid_a[s] -= force / S.m[s];
        ++out.pairs;
      }
    });
  }
  // The totals the solvers will feel, summed from what they are sent: that
  // they cancel is a check, not an identity.
  for (std::size_t f = 0; f < F.size(); ++f) out.force_on_fluid += F.m[f] * out.fluid_a[f];
  for (std::size_t s = 0; s < S.size(); ++s) out.force_on_solid += S.m[s] * out.solid_a[s];
  return out;
}

}  // namespace cosph::coupler
