// The reduced-dimension SPH shell (cosph-solid-shell, solid.model "shell"):
// one line of particles on a thin plate's mid-line, each carrying the
// thickness as a property and a rotation as a degree of freedom, so that one
// particle across bends with the exact stiffness EI of the section. In 2-D
// the shell is Reissner's geometrically exact (Timoshenko) beam in plane
// strain (reissner_beam.hpp, shell_section.hpp), in total-Lagrangian SPH along
// the reference line with its strains at stress points between neighbours
// (shell_dynamics.hpp): Wu, Zhang & Hu 2024 (J. Comput. Phys. 113113)
// reduced to a line. The water sees the section filled with particles (shell_interface.hpp).
//
// Step from t to t + dt, kick-drift-kick on position and rotation alike:
//   v += dt/2 a, omega += dt/2 alpha;  x += dt v, theta += dt omega;
//   strains, resultants;  a, alpha;  v += dt/2 a, omega += dt/2 alpha
// with run.gravity added to every free particle's a (it acts on the centre
// line, so it makes no moment).
//
// Stable step (step_limits): the explicit step of SPEC.md on the axial wave,
// and the shear-rotation cut-off frequency of the Timoshenko beam,
//   dt <= C_cfl min( h / (c + |v|_max), 1 / omega_r ),
//   c = sqrt(E' / rho),  omega_r = sqrt(k G t / (rho t^3 / 12)) = sqrt(12 k G / rho) / t;
// the bending and shear waves of a Timoshenko beam are slower than c, and
// the force limit 0.25 sqrt(h / |a|_max) as for the other solids.
#pragma once

#include <optional>
#include <vector>

#include "shell_dynamics.hpp"
#include "shell_interface.hpp"
#include "shell_line.hpp"
#include "shell_particles.hpp"
#include "solid_gauges.hpp"
#include "solid_parameters.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/checkpoint.hpp"
#include "sphcore/damped_mode.hpp"
#include "sphcore/interface_particles.hpp"
#include "sphcore/particle_solver.hpp"
#include "sphcore/snapshot_writer.hpp"
#include "sphcore/time_step.hpp"

namespace cosph::solid::shell {

// A dead load on the free end's face (solid.end_load).
struct EndLoad {
  Vec2 force;        // N/m
  double ramp_time;  // s
  int particle;      // the end particle, farther from the clamps
  Vec2 at(double time) const;
};

class ShellSolver : public sph::ParticleSolver<ShellSolver, ShellParticles, SolidParameters> {
 public:
  // Throws sph::ConfigError unless the case's solid.model is shell and its
  // body is a thin box (shell_line.hpp).
  ShellSolver(const sph::CaseFile& case_file, const SolidParameters& parameters);

  sph::StepLimits step_limits() const;

  void begin_step(double dt);
  void end_step(double dt);

  void collect_interface(const sph::Region& region, sph::InterfaceParticles& out);
  void set_interface_accelerations(const std::vector<Vec2>& accelerations);
  sph::Region interaction_bounds() const;
  std::vector<sph::Gauge> gauge_values() const;
  // The water sees round(t / dx) layers across each mid-line particle
  // (shell_interface.hpp): the most particles a state can carry.
  std::size_t interface_particle_count() const {
    return particles_.size() *
           static_cast<std::size_t>(ShellInterface::layers(forces_.section, parameters_.dx));
  }
  // Without its damping (solid.shell_damping false) the shell dissipates
  // nothing, and says so in its Hello (coupling.proto, undamped_modes).
  bool undamped_modes() const { return !forces_.damping.any(); }
  // The fastest mode, the shear-rotation cut-off, and the damping ratio the
  // damping gives it (Hello fields fastest_mode_*): of all the shell's modes
  // the one with the least damping ratio per angular frequency
  // (shell_damping.hpp), from which the coupler bounds its windows.
  sph::DampedMode fastest_mode() const {
    return {forces_.section.rotation_frequency(),
            forces_.damping.rotation_damping_ratio(forces_.section)};
  }

  // For tests: the state set directly (particles()), then update() for
  // strains and forces.
  void update();
  const ShellForceParameters& force_parameters() const { return forces_; }
  const ShellLine& line() const { return line_; }
  sph::Snapshot snapshot() const;

  // Everything the next step reads, for a checkpoint; restore() takes it back
  // into a solver built from the same case (shell_checkpoint.cpp).
  void save(sph::Checkpoint& checkpoint) const;
  void restore(const sph::Checkpoint& checkpoint);

 private:
  // The particles are built on the line: read first, checked parameters.
  ShellSolver(const sph::CaseFile& case_file, const SolidParameters& parameters,
              const ShellLine& line);
  void check_state() const;

  ShellLine line_;
  ShellForceParameters forces_;
  ShellInterface interface_;
  std::optional<EndLoad> end_load_;
  std::vector<int> tip_ids_;
};

}  // namespace cosph::solid::shell
