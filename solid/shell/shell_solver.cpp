#include "shell_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "reissner_beam.hpp"
#include "sphcore/first_runaway.hpp"
#include "sphcore/von_mises.hpp"

namespace cosph::solid::shell {

namespace {

const SolidParameters& checked(const sph::CaseFile& case_file, const SolidParameters& parameters) {
  require_model(case_file, parameters, SolidModel::shell);
  return parameters;
}

ShellSection section_of(const ShellLine& line, const SolidParameters& parameters) {
  return ShellSection::of(line.thickness, parameters.rho0, parameters.E, parameters.nu);
}

// The end particle farther from every clamped particle (the last one when
// nothing is clamped).
std::optional<EndLoad> read_end_load(const sph::CaseFile& case_file, const ShellParticles& P) {
  const auto& solid = case_file.config.solid();
  if (!solid.has_end_load()) return std::nullopt;
  const auto& load = solid.end_load();
  sph::require(load.ramp_time() >= 0.0, case_file, "solid.end_load.ramp_time",
               "must not be negative, got " + sph::format_number(load.ramp_time()) + " s");
  const int last = static_cast<int>(P.size()) - 1;
  auto distance_to_clamp = [&](int i) {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < P.size(); ++k)
      if (P.clamped[k]) nearest = std::min(nearest, std::abs(P.S[k] - P.S[i]));
    return nearest;
  };
  const bool at_start = distance_to_clamp(0) > distance_to_clamp(last);
  return EndLoad{Vec2(load.force().x(), load.force().y()), load.ramp_time(), at_start ? 0 : last};
}

}  // namespace

Vec2 EndLoad::at(double time) const {
  if (time >= ramp_time) return force;
  return 0.5 * (1.0 - std::cos(std::numbers::pi * time / ramp_time)) * force;
}

ShellSolver::ShellSolver(const sph::CaseFile& case_file, const SolidParameters& parameters)
    : ShellSolver(case_file, parameters,
                  read_shell_line(case_file, checked(case_file, parameters).dx)) {}

ShellSolver::ShellSolver(const sph::CaseFile& case_file, const SolidParameters& parameters,
                         const ShellLine& line)
    : ParticleSolver(parameters,
                     build_shell(case_file, parameters, line, section_of(line, parameters))),
      line_(line),
      forces_{section_of(line, parameters),
              parameters.shell_damping
                  ? ShellDamping::of(section_of(line, parameters), parameters.h)
                  : ShellDamping{}},
      end_load_(read_end_load(case_file, particles_)) {
  if (parameters_.tip_gauge)
    tip_ids_ = tip_gauge_ids(particles_.id, particles_.X, *parameters_.tip_gauge, line_.ds);
  update();
}

void ShellSolver::update() {
  ShellParticles& P = particles_;
  compute_strains(P, forces_);
  compute_accelerations(P);
  // Gravity acts on the section's mass, on its centre line: no moment.
  for (std::size_t i = 0; i < P.size(); ++i)
    if (!P.clamped[i]) P.a[i] += parameters_.run.gravity;
  // The end particle sits on the free end: the load acts on it.
  if (end_load_ && !P.clamped[end_load_->particle])
    P.a[end_load_->particle] += end_load_->at(time_) / P.m[end_load_->particle];
}

sph::StepLimits ShellSolver::step_limits() const {
  const ShellParticles& P = particles_;
  double v_max = 0.0, a_max = 0.0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    v_max = std::max(v_max, P.v[i].norm());
    a_max = std::max(a_max, P.a[i].norm());
  }
  sph::StepLimits limits = sph::step_limits(parameters_.run.cfl, parameters_.h,
                                            forces_.section.sound_speed(), v_max, a_max, 0.0);
  limits.sound *= forces_.damping.step_factor(forces_.section, line_.ds);
  limits.sound = std::min(limits.sound, parameters_.run.cfl / forces_.section.rotation_frequency());
  return limits;
}

void ShellSolver::begin_step(double dt) {
  ShellParticles& P = particles_;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.clamped[i]) continue;
    P.v[i] += (0.5 * dt) * (P.a[i] + P.external_a[i]);
    P.omega[i] += (0.5 * dt) * (P.alpha[i] + P.external_alpha[i]);
    P.x[i] += dt * P.v[i];
    P.theta[i] += dt * P.omega[i];
  }
  time_ += dt;  // the forces of the new state act at the new time (the end load's ramp)
  update();
  time_ -= dt;
  check_state();
}

void ShellSolver::end_step(double dt) {
  ShellParticles& P = particles_;
  for (std::size_t i = 0; i < P.size(); ++i) {
    P.kick_a[i] = P.clamped[i] ? Vec2::Zero() : Vec2(P.a[i] + P.external_a[i]);
    P.kick_alpha[i] = P.clamped[i] ? 0.0 : P.alpha[i] + P.external_alpha[i];
    P.v[i] += (0.5 * dt) * P.kick_a[i];
    P.omega[i] += (0.5 * dt) * P.kick_alpha[i];
  }
  time_ += dt;
  ++steps_;
  check_state();
}

void ShellSolver::collect_interface(const sph::Region& region, sph::InterfaceParticles& out) {
  interface_.collect(particles_, forces_.section, parameters_.h, parameters_.dx, region, out);
}

void ShellSolver::set_interface_accelerations(const std::vector<Vec2>& accelerations) {
  interface_.scatter(accelerations, particles_);
}

sph::Region ShellSolver::interaction_bounds() const {
  const ShellParticles& P = particles_;
  sph::Region bounds;
  for (std::size_t i = 0; i < P.size(); ++i)
    for (const int side : {+1, -1})
      bounds.include(P.x[i] +
                     ShellInterface::face_offset(forces_.section, P.phi0[i] + P.theta[i], side));
  return bounds;
}

std::vector<sph::Gauge> ShellSolver::gauge_values() const {
  const ShellParticles& P = particles_;
  SolidGauges g{0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0};
  const Vec2 tip = mean_displacement(P.id, P.x, P.X, tip_ids_);
  g.tip_dx = tip.x();
  g.tip_dy = tip.y();
  const double t = forces_.section.thickness;
  for (std::size_t i = 0; i < P.size(); ++i) {
    g.kinetic_energy += 0.5 * (P.m[i] * P.v[i].squaredNorm() + P.J[i] * P.omega[i] * P.omega[i]);
    g.max_speed = std::max(g.max_speed, P.v[i].norm());
  }
  const ShellStressPoints& s = P.stress;
  for (std::size_t k = 0; k < s.size(); ++k) {
    g.elastic_energy += s.ds[k] * s.strain_energy[k];
    // The outer fibres' axial stress, uniaxial in the section's plane.
    const double fibre = std::abs(s.N[k]) / t + 6.0 * std::abs(s.M[k]) / (t * t);
    g.max_von_mises =
        std::max(g.max_von_mises, sph::von_mises(sph::Mat2{{fibre, 0.0}, {0.0, 0.0}}));
  }
  double rotation = 0.0;  // mean rotation of the tip gauge's particles
  for (const int id : tip_ids_) rotation += P.theta[static_cast<std::size_t>(id)];
  if (!tip_ids_.empty()) rotation /= static_cast<double>(tip_ids_.size());
  std::vector<sph::Gauge> values = named_gauges(g);
  values.push_back({"tip_rotation", "rad", rotation});
  return values;
}

void ShellSolver::check_state() const {
  const ShellParticles& P = particles_;
  // The largest axial strain of a particle's stress points.
  std::vector<double> strain(P.size(), 0.0);
  for (std::size_t k = 0; k < P.stress.size(); ++k) {
    const std::size_t i = static_cast<std::size_t>(P.stress.i[k]);
    const double eps = std::abs(P.stress.N[k] / forces_.section.EA());
    strain[i] = std::max(strain[i], eps);
    strain[i + 1] = std::max(strain[i + 1], eps);
  }
  sph::stop_at_first_runaway(
      P, "shell particle", time_, steps_,
      [&P, &strain](std::size_t i) -> const char* {
        if (!P.x[i].allFinite() || !P.v[i].allFinite() || !std::isfinite(P.theta[i]) ||
            !std::isfinite(P.omega[i]))
          return "its state is not finite";
        if (P.v[i].norm() > P.c[i]) return "it moves faster than the shell's axial sound speed";
        if (!(strain[i] < 0.5))
          return "its axial strain left (-0.5, 0.5) (far outside the linear law)";
        return nullptr;
      },
      [&P](std::ostringstream& message, std::size_t i) {
        message << ", sound speed " << P.c[i]
                << " m/s); the run has blown up: try a smaller run.cfl";
      });
}

sph::Snapshot ShellSolver::snapshot() const {
  const ShellParticles& P = particles_;
  std::vector<int> clamped(P.clamped.begin(), P.clamped.end());
  std::vector<double> density(P.size(), forces_.section.rho);
  sph::Snapshot snapshot(P.x);
  snapshot.add_scalar("id", P.id);
  snapshot.add_scalar("mass", P.m);  // half at the ends: the mid-line's lumped masses
  snapshot.add_vector("velocity", P.v);
  snapshot.add_scalar("density", density);
  snapshot.add_scalar("rotation", P.theta);
  snapshot.add_scalar("angular_velocity", P.omega);
  snapshot.add_scalar("axial_force", P.N);
  snapshot.add_scalar("shear_force", P.Q);
  snapshot.add_scalar("bending_moment", P.M);
  snapshot.add_scalar("clamped", clamped);
  return snapshot;
}

}  // namespace cosph::solid::shell
