#include "particle_shifting.hpp"

#include "fluid_dynamics.hpp"
#include "sphcore/kernel_shape.hpp"
#include "sphcore/parallel.hpp"

namespace cosph::fluid {

namespace {
template <class Visit>
ShiftingSums shifting_sums(const FluidParticles& P, const sph::NeighbourList& pairs, long i,
                           const sph::kernel::ShapedValue& W_of, const DeltaPlusShifting& shifting,
                           Visit&& visit) {
  const Vec2 x_i = P.x[i];
  ShiftingSums sums;
  const auto neighbours = pairs.neighbours(i);
  const auto F = pairs.gradient_factors(i);
  for (std::size_t k = 0; k < neighbours.size(); ++k) {
    const int j = neighbours[k];
    const Vec2 x_ij = x_i - P.x[j];
    sums.add(shifting.pair_weight(W_of(x_ij.norm())), (P.volume[j] * F[k]) * x_ij, x_ij);
    visit(j);
  }
  return sums;
}
}  // namespace

// Two passes: which water is on the surface (lambda), then the shifts, which
// need to know whether a neighbour is on it.
void compute_particle_shifts(FluidParticles& P, const sph::NeighbourList& pairs,
                             const FluidParameters& par, double dt) {
  const long n = static_cast<long>(P.size());
  const sph::kernel::ShapedValue W_of(par.kernel, par.h);
  const DeltaPlusShifting shifting(par.c0 * dt / par.h, par.h, W_of(par.dx));
  P.shift.resize(P.size());
  P.on_surface.resize(P.size());
  const bool threaded = sph::worth_threads(P.size());
  sph::parallel_pass(n, threaded, [&](long i) {
    P.on_surface[i] =
        P.is_water(i) && DeltaPlusShifting::on_surface(smallest_eigenvalue(
                             shifting_sums(P, pairs, i, W_of, shifting, [](int) {}).M()));
  });
  sph::parallel_pass(n, threaded, [&](long i) {
    if (!P.is_water(i)) {
      P.shift[i].setZero();
      return;
    }
    bool near_surface = false;
    const ShiftingSums sums = shifting_sums(P, pairs, i, W_of, shifting,
                                            [&](int j) { near_surface |= P.on_surface[j] != 0; });
    P.shift[i] = shifting.shift(sums, near_surface);
  });
}

}  // namespace cosph::fluid
