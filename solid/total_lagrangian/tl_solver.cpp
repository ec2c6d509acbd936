#include "tl_solver.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "kick_drift_kick.hpp"
#include "reference_configuration.hpp"
#include "sphcore/pair_terms.hpp"
#include "sphcore/parallel.hpp"
#include "sphcore/runaway_error.hpp"
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
    : parameters_(checked(case_file, parameters)),
      forces_{parameters.h, parameters.A, parameters.B, parameters.hourglass_alpha,
              parameters.run.gravity},
      particles_(build_reference_configuration(case_file, parameters)) {
  parameters_.unmet_walls =
      walls_no_free_particle_is_inside(particles_.x, particles_.clamped, parameters_.unmet_walls);
  if (parameters_.tip_gauge)
    tip_ids_ = tip_gauge_ids(particles_.id, particles_.X, *parameters_.tip_gauge, parameters_.dx);
  update();
}

void TLSolver::update() {
  compute_deformation_and_stress(particles_);
  compute_accelerations(particles_, forces_);
}

sph::StepLimits TLSolver::step_limits() const {
  return solid_step_limits(particles_, parameters_);
}

void TLSolver::begin_step(double dt) {
  TLParticles& P = particles_;
  sph::parallel_for(P.size(), sph::kTeamAtAnySize, [&](long i) {
    if (!P.clamped[i]) kick_and_drift(P, i, dt, parameters_);
  });
  update();
  check_state();  // before the state is shown to anyone, the coupler included
}

void TLSolver::end_step(double dt) {
  closing_kick(particles_, dt);
  time_ += dt;
  ++steps_;
  check_state();
  stop_if_in_unmet_wall(particles_, parameters_.unmet_walls, time_, steps_);
}

void TLSolver::collect_interface(const sph::Region& region, sph::InterfaceParticles& out) {
  interface_.collect(particles_, parameters_.h, region, out);
}

void TLSolver::set_interface_accelerations(const std::vector<Vec2>& accelerations) {
  interface_.scatter(accelerations, particles_.external_a);
}

sph::Region TLSolver::interaction_bounds() const {
  return sph::bounds_of(particles_.x);
}

SolidGauges TLSolver::gauges() const {
  const TLParticles& P = particles_;
  SolidGauges g{0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0};
  const Vec2 tip = mean_displacement(P.id, P.x, P.X, tip_ids_);
  for (std::size_t i = 0; i < P.size(); ++i) {
    const double speed2 = P.v[i].squaredNorm();
    g.kinetic_energy += 0.5 * P.m[i] * speed2;
    g.max_speed = std::max(g.max_speed, speed2);
    g.elastic_energy += P.V0[i] * P.strain_energy[i];
    g.max_von_mises = std::max(g.max_von_mises, sph::von_mises(P.sigma[i]));
  }
  g.tip_dx = tip.x();
  g.tip_dy = tip.y();
  g.max_speed = std::sqrt(g.max_speed);
  return g;
}

std::vector<sph::Gauge> TLSolver::gauge_values() const {
  std::vector<sph::Gauge> values = named_gauges(gauges());
  const TLParticles& P = particles_;
  for (const sph::Gauge& gauge :
       broken_part_gauges(parameters_.broken_part_below_y, P.X, P.x, P.m, P.clamped))
    values.push_back(gauge);
  return values;
}

bool TLSolver::may_have_run_away() const {
  namespace screen = sph::screen;
  const TLParticles& P = particles_;
  const double* const x = sph::doubles_of(P.x);
  const double* const v = sph::doubles_of(P.v);
  const double* const F = sph::doubles_of(P.F);
  const double* const J = P.J.data();
  const double* const c = P.c.data();
  return sph::parallel_any(P.size(), sph::kTeamAtAnySize, [&](long i) {
    return !(screen::finite_vector(x, i) & screen::finite_matrix(F, i) &
             screen::clearly_slower(v, i, c[i]) &
             screen::within(J[i], screen::kLowest, screen::kHighest));
  });
}

void TLSolver::check_state() const {
  if (!may_have_run_away()) return;
  const TLParticles& P = particles_;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const char* reason = nullptr;
    if (!P.x[i].allFinite() || !P.v[i].allFinite() || !P.F[i].allFinite())
      reason = "its state is not finite";
    else if (P.v[i].norm() > P.c[i])
      reason = "it moves faster than the solid's sound speed";
    else if (!sph::screen::within(P.J[i], sph::screen::kLowest, sph::screen::kHighest))
      reason = "its volume ratio J = det F left [0.5, 2] (far outside linear elasticity)";
    if (reason == nullptr) continue;
    std::ostringstream message = runaway_report(P, static_cast<long>(i), time_, steps_, reason);
    message << ", J " << P.J[i] << "); the run has blown up: try a smaller run.cfl";
    throw sph::RunawayError(message.str());
  }
}

sph::Snapshot TLSolver::snapshot() const {
  const TLParticles& P = particles_;
  const std::size_t n = P.size();
  std::vector<double> pressure(n), xx(n), xy(n), yy(n), vm(n);
  std::vector<int> failed(n, 0);
  std::vector<int> clamped(P.clamped.begin(), P.clamped.end());
  for (std::size_t i = 0; i < n; ++i) {
    // Mean normal stress of plane strain, sigma_zz included (as the Jaumann
    // solid's P = K (rho/rho0 - 1) is).
    pressure[i] = -(P.sigma[i].trace() + P.sigma_zz[i]) / 3.0;
    xx[i] = P.sigma[i](0, 0);
    xy[i] = P.sigma[i](0, 1);
    yy[i] = P.sigma[i](1, 1);
    vm[i] = sph::von_mises(P.sigma[i]);
  }
  sph::Snapshot snapshot(P.x);
  snapshot.add_scalar("id", P.id);
  snapshot.add_vector("velocity", P.v);
  snapshot.add_scalar("density", P.rho);
  snapshot.add_scalar("pressure", pressure);
  snapshot.add_scalar("stress_xx", xx);
  snapshot.add_scalar("stress_xy", xy);
  snapshot.add_scalar("stress_yy", yy);
  snapshot.add_scalar("von_mises", vm);
  snapshot.add_scalar("J", P.J);
  snapshot.add_scalar("failed", failed);
  snapshot.add_scalar("clamped", clamped);
  return snapshot;
}

}  // namespace cosph::solid::tl
