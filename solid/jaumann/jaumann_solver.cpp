#include "jaumann_solver.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "artificial_stress.hpp"
#include "clamp_reach.hpp"
#include "hooke_pressure.hpp"
#include "jaumann_dynamics.hpp"
#include "kick_drift_kick.hpp"
#include "solid_runaway.hpp"
#include "solid_scene.hpp"
#include "solid_snapshot.hpp"
#include "sphcore/gauge.hpp"
#include "sphcore/kernel.hpp"
#include "sphcore/parallel.hpp"
#include "sphcore/permutation.hpp"
#include "sphcore/region.hpp"
#include "sphcore/runaway_screen.hpp"
#include "unmet_walls.hpp"
#include "von_mises_failure.hpp"

namespace cosph::solid::jaumann {

JaumannSolver::JaumannSolver(const sph::CaseFile& case_file, const SolidParameters& parameters)
    : ContinuumSolidSolver(parameters,
                           JaumannParticles::from_scene(build_solid_scene(case_file, parameters))),
      verlet_(parameters.h) {
  set_clamp_reach();
  sort();
  compute_rates(particles_, verlet_.candidates(), parameters_);  // for the renormalisation matrices
  update_stress(Including::inert);
  compute_accelerations(particles_, parameters_);
}

void JaumannSolver::sort() {
  JaumannParticles& P = particles_;
  // The rates pass works each pair out once, from its lower index: it needs
  // a particle's later candidates only, and its inert ones (an inert
  // particle has no list of its own). The quadratic fit needs them all.
  // Particles out of reach are candidates of none (candidate_filter).
  verlet_.sort(
      P.x,
      [&P](const std::vector<int>& order) {
        sph::permute(order, P.id, P.x, P.v, P.x0, P.rho, P.m, P.s, P.K, P.G, P.c, P.sigma_y,
                     P.clamped, P.failed, P.inert, P.out_of_reach, P.external_a, P.kick_a);
      },
      [&P](long i) { return !P.inert[i]; }, candidate_filter());
  P.reach_end = reach_end(P.out_of_reach);
}

void JaumannSolver::set_clamp_reach() {
  JaumannParticles& P = particles_;
  // What a free particle's acceleration reads of a neighbour j within 2h:
  // x, v, rho, c and sigma L, R (of j's stress and density). A clamped j's
  // density and stress change only through its rates, which are zero unless
  // a free particle lies within 2h of it (its clamped neighbours are at rest
  // with it); they and its L are sums over j's own neighbours k within 2h,
  // of their positions, velocities and volumes. So a clamped particle needs
  // its rates within one support (2h) of a free particle, and is read at
  // all within two (a k's volume changes only if k is such a j itself). A
  // free particle may come closer than it started; the margin for that is
  // one more support (a clamp's root moves little). Hence rates within two
  // supports of where the free particles start (the others are inert), and
  // nothing at all beyond three: those are out of reach. Taken from the
  // start's positions x0, so that a restored run finds the same sets without
  // storing them.
  const double support = sph::kernel::kSupport * parameters_.h;
  P.inert = clamped_beyond(P.x0, P.clamped, 2.0 * support);
  P.out_of_reach = clamped_beyond(P.x0, P.clamped, 3.0 * support);
}

void JaumannSolver::update_stress(Including including) {
  JaumannParticles& P = particles_;
  const SolidParameters& par = parameters_;
  // At the start every particle gets its stress, for the output and the
  // coupler; later only those in reach.
  const std::size_t n = including == Including::inert ? P.size() : in_reach(P);
  sph::parallel_for(n, sph::kTeamAtAnySize, [&](long i) {
    // An inert particle's rates are zero: its stress is the one it started with.
    if (P.inert[i] && including == Including::active_only) return;
    // A failed particle carries no tension, so it has no expanded state: as it
    // separates from the body, continuity would thin its density without
    // limit; it stays at rho0, and resists at once when pushed back.
    if (P.failed[i]) P.rho[i] = std::max(P.rho[i], par.rho0);
    P.p[i] = hooke_pressure(P.K[i], P.rho[i], par.rho0);
    const Mat2 sigma = -P.p[i] * Mat2::Identity() + P.s[i];
    if (par.fracture.enabled && !P.failed[i] && yields(sigma, P.sigma_y[i])) P.failed[i] = 1;
    if (P.failed[i]) P.s[i] = Mat2::Zero();
    P.sigma[i] = P.failed[i] ? failed_stress(P.p[i]) : sigma;
    P.sigma_L[i] = sph::product_2x2(P.sigma[i], P.L[i]);
    P.R[i] = par.artificial_stress.enabled
                 ? artificial_stress(P.sigma[i], P.rho[i], par.artificial_stress.epsilon)
                 : Mat2::Zero();
  });
}

void JaumannSolver::begin_step(double dt) {
  advance_state(dt);
  compute_forces();
}

void JaumannSolver::advance_state(double dt) {
  JaumannParticles& P = particles_;
  // The largest squared displacement since the last sort.
  const std::size_t n = in_reach(P);
  const double moved2 = sph::parallel_max(n, 0.0, sph::kTeamAtAnySize, [&](long i) {
    if (P.clamped[i]) return 0.0;
    kick_and_drift(P, i, dt, parameters_);
    return verlet_.moved2(P.x[i], i);
  });
  if (verlet_.stale(moved2)) sort();
  compute_rates(P, verlet_.candidates(), parameters_);
  sph::parallel_for(n, sph::kTeamAtAnySize, [&](long i) {
    P.rho[i] += dt * P.drho[i];
    P.s[i] += dt * P.ds[i];
  });
  update_stress(Including::active_only);
  check_state();  // before the state is shown to anyone, the coupler included
}

void JaumannSolver::compute_forces() {
  compute_accelerations(particles_, parameters_);
}

SolidGauges JaumannSolver::gauges() const {
  const JaumannParticles& P = particles_;
  return measure(P, P.x0, tip_ids_, [&P](std::size_t i) {
    // Strain energy density P^2/(2K) + s:s/(4G), with the out-of-plane
    // deviator s_zz = -(s_xx + s_yy) of plane strain.
    const double V = P.m[i] / P.rho[i];
    const double trace = P.s[i].trace();
    return V * (P.p[i] * P.p[i] / (2.0 * P.K[i]) +
                (P.s[i].squaredNorm() + trace * trace) / (4.0 * P.G[i]));
  });
}

void JaumannSolver::check_state() const {
  namespace screen = sph::screen;
  const JaumannParticles& P = particles_;
  const double* const x = sph::doubles_of(P.x);
  const double* const v = sph::doubles_of(P.v);
  const double* const s = sph::doubles_of(P.s);
  const double* const rho = P.rho.data();
  const double* const c = P.c.data();
  const double rho_min = screen::kLowest * parameters_.rho0,
               rho_max = screen::kHighest * parameters_.rho0;
  stop_if_run_away(
      P, time_, steps_,
      [&](long i) {
        return screen::finite_vector(x, i) & screen::finite_matrix(s, i) &
               screen::clearly_slower(v, i, c[i]) & screen::within(rho[i], rho_min, rho_max);
      },
      [&](std::size_t i) -> const char* {
        if (!P.x[i].allFinite() || !P.v[i].allFinite() || !std::isfinite(P.rho[i]) ||
            !P.s[i].allFinite())
          return "its state is not finite";
        if (P.v[i].norm() > P.c[i]) return "it moves faster than the solid's sound speed";
        if (!screen::within(P.rho[i], rho_min, rho_max))
          return "its density left [0.5, 2] rho0 (far outside linear elasticity)";
        return nullptr;
      },
      [&](std::ostringstream& message, std::size_t i) {
        message << ", density " << P.rho[i]
                << " kg/m^3); the run has blown up: try a smaller run.cfl, or turn on "
                   "solid.artificial_stress if the body is under tension";
      });
}

sph::Snapshot JaumannSolver::snapshot() const {
  sph::Snapshot snapshot = stress_snapshot(particles_, particles_.p);
  add_flags(snapshot, particles_.failed, particles_.clamped);
  return snapshot;
}

}  // namespace cosph::solid::jaumann
