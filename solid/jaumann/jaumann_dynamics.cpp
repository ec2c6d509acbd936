#include "jaumann_dynamics.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <vector>

#include "clamp_reach.hpp"
#include "jaumann_rate.hpp"
#include "momentum_pair.hpp"
#include "sphcore/kernel.hpp"
#include "sphcore/ordered_shares.hpp"
#include "sphcore/outer_product_sum.hpp"
#include "sphcore/parallel.hpp"
#include "sphcore/quadratic_gradient.hpp"
#include "sphcore/renormalisation.hpp"

namespace cosph::solid::jaumann {

namespace kernel = sph::kernel;

namespace {

// The pairs of particle i within 2h among its candidates: the first `count`
// entries, in the candidates' order (index order), of the neighbour's index J,
// W_ij and the gradient factor F_ij (grad_i W_ij = F_ij x_ij). The kernel is
// taken for all of them in one loop that vectorises: its division, one pair
// at a time, would set the pace of the pass.
struct PairsWithin {
  std::vector<int> J;
  std::vector<double> W, F;
  std::size_t count = 0;
};
void find_pairs(const JaumannParticles& P, long i, std::span<const int> candidates, double support2,
                const kernel::Value& W_of, const kernel::GradientFactor& gradient_factor,
                PairsWithin& pairs) {
  // Grown, never shrunk: a resize to fit each particle zeroed the new room.
  if (pairs.J.size() < candidates.size()) {
    pairs.J.resize(candidates.size()), pairs.W.resize(candidates.size());
    pairs.F.resize(candidates.size());
  }
  // F holds r^2 until the kernel loop.
  pairs.count =
      sph::filter_within(candidates, P.x, P.x[i], support2, pairs.J.data(), pairs.F.data());
  for (std::size_t k = 0; k < pairs.count; ++k) {
    const double r_ij = std::sqrt(pairs.F[k]);
    pairs.W[k] = W_of(r_ij);
    pairs.F[k] = gradient_factor(r_ij);
  }
}

// grad v_i fitted to be exact for quadratic fields (sphcore/quadratic_gradient.hpp),
// over all of i's pairs; none where the neighbourhood cannot fix a quadratic.
std::optional<Mat2> fitted_gradient(const JaumannParticles& P, long i, const PairsWithin& pairs,
                                    double h) {
  sph::QuadraticGradient fit(h);
  for (std::size_t k = 0; k < pairs.count; ++k) {
    const int j = pairs.J[k];
    fit.add(P.volume[j] * pairs.W[k], P.x[j] - P.x[i]);
  }
  if (!fit.solve()) return std::nullopt;
  // grad v_i = sum_j (v_j - v_i) (x) b_ij with the fit's weights b_ij.
  sph::OuterProductSum grad_v;
  for (std::size_t k = 0; k < pairs.count; ++k) {
    const int j = pairs.J[k];
    grad_v.add(P.v[j] - P.v[i], fit.gradient_weight(P.volume[j] * pairs.W[k], P.x[j] - P.x[i]));
  }
  return grad_v.matrix();
}

}  // namespace

void compute_rates(JaumannParticles& P, const sph::CandidateList& candidates,
                   const SolidParameters& par) {
  const long n = static_cast<long>(in_reach(P));  // the rest take no part (clamp_reach.hpp)
  const double h = par.h, reach = kernel::kSupport * h, support2 = reach * reach;
  const bool quadratic = par.velocity_gradient == VelocityGradient::quadratic;
  const kernel::Value W_of(h);
  const kernel::GradientFactor gradient_factor(h);
  const bool use_team = sph::kTeamAtAnySize;
  P.neighbours.resize(P.size());
  P.volume.resize(P.size());
  P.rate_sums.resize(P.size());
  if (quadratic) P.fitted_grad_v.resize(P.size());
  sph::parallel_for(n, use_team, [&](long i) { P.volume[i] = P.m[i] / P.rho[i]; });

  // Each pair is worked out once, by the lower index, which gives the higher
  // one its share (sph::OrderedShares), and is listed for the momentum pass
  // there only. An inert particle has no candidates: a particle after it
  // takes their pair's terms for itself alone.
  sph::OrderedShares<RateSums>& shares = P.rate_shares;
  const long blocks = shares.prepare(n, use_team, [&](long i) -> long {
    const auto c = candidates.candidates(i);
    return c.empty() ? i : c.back();
  });
  sph::parallel_for(blocks, use_team, [&](long b) {
    thread_local PairsWithin pairs;
    for (long i = shares.begin(b); i < shares.end(b); ++i) P.rate_sums[i] = RateSums{};
    for (long i = shares.begin(b); i < shares.end(b); ++i) {
      std::vector<Neighbour>& neighbours = P.neighbours[i];
      neighbours.clear();
      if (P.inert[i]) continue;
      find_pairs(P, i, candidates.candidates(i), support2, W_of, gradient_factor, pairs);
      // The fit needs all of i's pairs, which only this pass sees together.
      if (quadratic) P.fitted_grad_v[i] = fitted_gradient(P, i, pairs, h);
      const Vec2 x_i = P.x[i], v_i = P.v[i];
      const double V_i = P.volume[i];
      const std::size_t later = static_cast<std::size_t>(
          std::upper_bound(pairs.J.begin(), pairs.J.begin() + pairs.count, static_cast<int>(i)) -
          pairs.J.begin());
      RateSums own;
      for (std::size_t k = 0; k < later; ++k) {
        const int j = pairs.J[k];
        if (!P.inert[j]) continue;
        const Vec2 x_ij = x_i - P.x[j];
        own.add(P.volume[j], pairs.F[k] * x_ij, x_ij, v_i - P.v[j]);
      }
      neighbours.resize(pairs.count - later);
      std::size_t listed = 0;
      for (std::size_t k = later; k < pairs.count; ++k) {
        const int j = pairs.J[k];
        const Vec2 x_ij = x_i - P.x[j];
        const Vec2 grad_W_ij = pairs.F[k] * x_ij;
        const Vec2 v_ij = v_i - P.v[j];
        // A pair of two clamped particles moves neither: it is not listed
        // for the momentum pass.
        neighbours[listed] = {j, pairs.W[k], grad_W_ij};
        listed += static_cast<std::size_t>(!(P.clamped[i] & P.clamped[j]));
        own.add(P.volume[j], grad_W_ij, x_ij, v_ij);
        shares.share(b, P.rate_sums.data(), j).add(V_i, grad_W_ij, x_ij, v_ij);
      }
      neighbours.resize(listed);
      P.rate_sums[i] += own;
    }
  });
  shares.merge(P.rate_sums, use_team);

  sph::parallel_for(n, use_team, [&](long i) {
    if (P.inert[i]) {
      P.drho[i] = 0.0;
      P.ds[i] = Mat2::Zero();
      return;
    }
    const RateSums& sums = P.rate_sums[i];
    // Continuity (docs/physics.md, "Jaumann solid": as the fluid's, without
    // diffusion):
    //   drho_i/dt = rho_i sum_j V_j v_ij . grad_i W_ij.
    P.drho[i] = P.rho[i] * sums.volume_divergence;
    const sph::RenormalisedGradient gradient = sph::renormalised_gradient(sums.gradients);
    P.L[i] = gradient.L;
    // grad_v(a, b) = dv_a/dx_b, exact for a linear velocity field even at the
    // free surface, where the bending stress of a plate is largest, or, when
    // fitted, for a quadratic one, which is what bending is. Continuity keeps
    // the form of docs/physics.md, "Continuity and delta-SPH": the fitted
    // trace in its place leaves the oscillating plate softer.
    const Mat2 grad_v = quadratic && P.fitted_grad_v[i] ? *P.fitted_grad_v[i] : gradient.grad_v;
    P.ds[i] = P.failed[i] ? Mat2::Zero() : jaumann_rate(P.G[i], P.s[i], grad_v);
  });
}

void compute_accelerations(JaumannParticles& P, const SolidParameters& par) {
  const long n = static_cast<long>(in_reach(P));  // the rest take no part (clamp_reach.hpp)
  const bool use_team = sph::kTeamAtAnySize;
  P.inverse_rho.resize(P.size());
  sph::parallel_for(n, use_team, [&](long i) { P.inverse_rho[i] = 1.0 / P.rho[i]; });

  // Each pair is worked out once, by the lower index, which lists it (the
  // rates pass), and which gives the higher one its share (sph::OrderedShares,
  // as the fluid's momentum pass): the bracket is symmetric in i and j, and
  // grad_j W_ji = -grad_i W_ij. A pair of two clamped particles (an inert
  // particle's are all such) acts on accelerations that are zero: none is listed.
  sph::OrderedShares<Vec2>& shares = P.a_shares;
  const long blocks = shares.prepare(n, use_team, [&](long i) -> long {
    const std::vector<Neighbour>& neighbours = P.neighbours[i];
    return neighbours.empty() ? i : neighbours.back().j;
  });
  const auto pass = [&]<class Bracket>(const Bracket& bracket) {
    sph::parallel_for(blocks, use_team, [&](long b) {
      for (long i = shares.begin(b); i < shares.end(b); ++i) P.a[i].setZero();
      for (long i = shares.begin(b); i < shares.end(b); ++i) {
        if (P.neighbours[i].empty()) continue;
        const PairSide side_i(P, i);
        Vec2 a_i = Vec2::Zero();
        for (const Neighbour& neighbour : P.neighbours[i]) {
          const Vec2 bracket_times_gradient_ij = bracket(side_i, neighbour);
          a_i += P.m[neighbour.j] * bracket_times_gradient_ij;
          shares.share(b, P.a.data(), neighbour.j) -= side_i.m * bracket_times_gradient_ij;
        }
        P.a[i] += a_i;
      }
    });
  };
  // The artificial stress's settings are fixed for the whole pass.
  const ArtificialStressParameters& stress = par.artificial_stress;
  if (!stress.enabled)
    pass(MomentumPair<ArtificialStressTerm::none>(P, par));
  else if (stress.exponent == 4.0)  // the usual exponent: f^4 by two products, not std::pow
    pass(MomentumPair<ArtificialStressTerm::fourth_power>(P, par));
  else
    pass(MomentumPair<ArtificialStressTerm::any_power>(P, par));
  shares.merge(P.a, use_team);
  // The coupling's external_a is added by the kicks.
  sph::parallel_for(n, use_team, [&](long i) {
    P.a[i] = P.clamped[i] ? Vec2::Zero() : Vec2(P.a[i] + par.run.gravity);
  });
}

}  // namespace cosph::solid::jaumann
