#include "tl_solver.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "clamp_reach.hpp"
#include "kick_drift_kick.hpp"
#include "reference_configuration.hpp"
#include "solid_runaway.hpp"
#include "solid_snapshot.hpp"
#include "sphcore/gauge.hpp"
#include "sphcore/parallel.hpp"
#include "sphcore/region.hpp"
#include "sphcore/runaway_screen.hpp"
#include "unmet_walls.hpp"

namespace cosph::solid::tl {

namespace {

const SolidParameters& checked(const sph::CaseFile& case_file, const SolidParameters& parameters) {
  require_model(case_file, parameters, SolidModel::total_lagrangian);
  return parameters;
}

}  // namespace

TLSolver::TLSolver(const sph::CaseFile& case_file, const SolidParameters& parameters)
    : ContinuumSolidSolver(
          parameters, build_reference_configuration(case_file, checked(case_file, parameters))),
      forces_{parameters.h, parameters.A, parameters.B, parameters.hourglass_alpha,
              parameters.run.gravity} {
  update();
}

void TLSolver::update() {
  compute_deformation_and_stress(particles_);
  compute_accelerations(particles_, forces_);
}

void TLSolver::begin_step(double dt) {
  TLParticles& P = particles_;
  sph::parallel_for(in_reach(P), sph::kTeamAtAnySize, [&](long i) {
    if (!P.clamped[i]) kick_and_drift(P, i, dt, parameters_);
  });
  update();
  check_state();  // before the state is shown to anyone, the coupler included
}

SolidGauges TLSolver::gauges() const {
  const TLParticles& P = particles_;
  return measure(P, P.X, tip_ids_, [&P](std::size_t i) { return P.V0[i] * P.strain_energy[i]; });
}

void TLSolver::check_state() const {
  namespace screen = sph::screen;
  const TLParticles& P = particles_;
  const double* const x = sph::doubles_of(P.x);
  const double* const v = sph::doubles_of(P.v);
  const double* const F = sph::doubles_of(P.F);
  const double* const J = P.J.data();
  const double* const c = P.c.data();
  stop_if_run_away(
      P, time_, steps_,
      [&](long i) {
        return screen::finite_vector(x, i) & screen::finite_matrix(F, i) &
               screen::clearly_slower(v, i, c[i]) &
               screen::within(J[i], screen::kLowest, screen::kHighest);
      },
      [&](std::size_t i) -> const char* {
        if (!P.x[i].allFinite() || !P.v[i].allFinite() || !P.F[i].allFinite())
          return "its state is not finite";
        if (P.v[i].norm() > P.c[i]) return "it moves faster than the solid's sound speed";
        if (!screen::within(P.J[i], screen::kLowest, screen::kHighest))
          return "its volume ratio J = det F left [0.5, 2] (far outside linear elasticity)";
        return nullptr;
      },
      [&](std::ostringstream& message, std::size_t i) {
        message << ", J " << P.J[i] << "); the run has blown up: try a smaller run.cfl";
      });
}

sph::Snapshot TLSolver::snapshot() const {
  const TLParticles& P = particles_;
  std::vector<double> pressure(P.size());
  // Mean normal stress of plane strain, sigma_zz included (as the Jaumann
  // solid's P = K (rho/rho0 - 1) is).
  for (std::size_t i = 0; i < P.size(); ++i)
    pressure[i] = -(P.sigma[i].trace() + P.sigma_zz[i]) / 3.0;
  sph::Snapshot snapshot = stress_snapshot(P, pressure);
  snapshot.add_scalar("J", P.J);
  // No model of failure: no particle fails.
  add_flags(snapshot, std::vector<std::uint8_t>(P.size(), 0), P.clamped);
  return snapshot;
}

}  // namespace cosph::solid::tl
