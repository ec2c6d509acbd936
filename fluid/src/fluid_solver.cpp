#include "fluid_solver.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>

#include "fluid_dynamics.hpp"
#include "fluid_scene.hpp"
#include "sphcore/first_runaway.hpp"
#include "sphcore/gauge.hpp"
#include "sphcore/kernel.hpp"
#include "sphcore/parallel.hpp"
#include "sphcore/permutation.hpp"
#include "sphcore/region.hpp"
#include "sphcore/runaway_error.hpp"
#include "sphcore/runaway_screen.hpp"
#include "water_level.hpp"

namespace cosph::fluid {

FluidSolver::FluidSolver(const sph::CaseFile& case_file, const FluidParameters& parameters)
    : ParticleSolver(parameters, build_fluid_scene(case_file, parameters)),
      eos_(parameters.rho0, parameters.c0),
      verlet_(parameters.h, 2) {
  for (std::size_t i = 0; i < particles_.size(); ++i)
    if (particles_.is_moving_wall(i)) place_moving_wall(i, 0.0, 0.0);
  find_neighbours(true);
  compute_continuity_and_gradients(particles_, pairs_, parameters_);  // only for grad_rho
  update_pressure();
  compute_forces();
}

void FluidSolver::find_neighbours(bool sort) {
  FluidParticles& P = particles_;
  if (sort) {
    // The grid, built for 2h + skin, also serves the wall pressure until the
    // next sort: a water particle within 2h of a wall particle now was within
    // 2h + skin of it then, since neither has moved skin / 2 (moving walls
    // count in the rebuild test too).
    verlet_.sort(
        P.x, [&P](const std::vector<int>& order) { P.permute_state(order); },
        [&P](long i) { return P.is_water(i); });
    // Walls far from the water cost nothing until the next sort.
    walls_in_reach_ = walls_in_reach(P, verlet_.grid(), verlet_.reach());
    rest_walls_out_of_reach(P, walls_in_reach_, eos_);
    ++sorts_;
  }
  pairs_.build(verlet_.candidates(), P.x, parameters_.h, parameters_.kernel);
}

void FluidSolver::update_pressure() {
  FluidParticles& P = particles_;
  sph::parallel_for(P.size(), [&](long i) {
    if (P.is_water(i)) P.p[i] = eos_.pressure(P.rho[i]);
  });
}

void FluidSolver::place_moving_wall(std::size_t i, double t, double t_velocity) {
  FluidParticles& P = particles_;
  const WallMotion& motion =
      parameters_.wall_motions[static_cast<std::size_t>(P.wall_of(i)) - P.fixed_walls];
  const WallKinematics k = motion.at(P.x_drawn[i], t);
  P.x[i] = k.x;
  P.v[i] = t_velocity == t ? k.v : motion.at(P.x_drawn[i], t_velocity).v;
  P.wall_a[i] = k.a;
}

void FluidSolver::compute_forces() {
  compute_wall_pressure(particles_, verlet_.grid(), walls_in_reach_, parameters_, eos_);
  compute_accelerations(particles_, pairs_, parameters_);
}

sph::StepLimits FluidSolver::step_limits() const {
  const FluidParticles& P = particles_;
  const auto [v_max2, a_max2] =
      sph::parallel_max(P.size(), std::array{0.0, 0.0}, sph::worth_threads(P.size()), [&](long i) {
        return P.is_water(i) ? std::array{P.v[i].squaredNorm(), P.a[i].squaredNorm()}
                             : std::array{0.0, 0.0};
      });
  fastest_water_ = std::max(fastest_water_, std::sqrt(v_max2));
  return sph::step_limits(parameters_.run.cfl, parameters_.h, parameters_.c0, std::sqrt(v_max2),
                          std::sqrt(a_max2), parameters_.mu / parameters_.rho0);
}

void FluidSolver::begin_step(double dt) {
  advance_state(dt);
  compute_forces();
}

void FluidSolver::advance_state(double dt) {
  FluidParticles& P = particles_;
  const double half = 0.5 * dt;
  // The largest squared displacement since the last sort. Moving walls are
  // placed as the drift places the water: at the step's end, with the
  // velocity of its middle, which is what the water carries into the pair
  // terms until the last kick. With the end's velocity instead, the walls
  // would approach the water at a dt / 2 in every pair term of the step: an
  // accelerated floor compressed the water above it and read 1.4 % high.
  // Each share's arrays are held in locals: the Eigen stores to v and x may
  // alias anything, and through P every address was loaded again after them.
  const double moved2 = sph::parallel_max_of_shares(
      P.size(), 0.0, sph::worth_threads(P.size()), [&](long begin, long end, double largest) {
        const Kind* const kind = P.kind.data();
        Vec2 *const x = P.x.data(), *const v = P.v.data();
        const Vec2 *const a = P.a.data(), *const external_a = P.external_a.data(),
                          *const shift = P.shift.data(),
                          *const x_at_sort = verlet_.x_at_sort().data();
        for (long i = begin; i < end; ++i) {
          if (kind[i] == Kind::moving_wall) {
            place_moving_wall(static_cast<std::size_t>(i), time_ + dt, time_ + half);
            largest = std::max(largest, sph::SortedVerletList::moved2(x[i], x_at_sort[i]));
            continue;
          }
          if (kind[i] != Kind::water) continue;  // fixed walls
          v[i] += half * (a[i] + external_a[i]);
          x[i] += dt * v[i] + shift[i];
          largest = std::max(largest, sph::SortedVerletList::moved2(x[i], x_at_sort[i]));
        }
        return largest;
      });
  find_neighbours(spray_left_ || verlet_.stale(moved2));
  spray_left_ = false;
  compute_continuity_and_gradients(P, pairs_, parameters_);
  if (parameters_.delta_plus_shifting) compute_particle_shifts(P, pairs_, parameters_, dt);
  sph::parallel_for(P.size(), [&](long i) {
    if (P.is_water(i)) P.rho[i] += dt * P.drho[i];
  });
  update_pressure();
  check_state();  // before the state is shown to anyone, the coupler included
}

void FluidSolver::end_step(double dt) {
  FluidParticles& P = particles_;
  const double half = 0.5 * dt;
  // The arrays in locals over each share, as in advance_state.
  sph::for_each_share(P.size(), sph::worth_threads(P.size()), [&](long begin, long end, long) {
    const Kind* const kind = P.kind.data();
    Vec2* const v = P.v.data();
    const Vec2 *const a = P.a.data(), *const external_a = P.external_a.data();
    double* const rho = P.rho.data();
    const double* const external_drho = P.external_drho.data();
    for (long i = begin; i < end; ++i) {
      if (kind[i] != Kind::water) continue;
      v[i] += half * (a[i] + external_a[i]);
      // Computed by the coupler at the same positions as this step's drho,
      // after the pressure was taken from rho: it acts from the next step on.
      rho[i] += dt * external_drho[i];
    }
  });
  time_ += dt;
  ++steps_;
  // The screen is one pass over the particles; a sound state needs no second.
  if (!may_have_run_away()) return;
  remove_thinned_spray();
  check_state();
}

bool FluidSolver::is_spray(std::size_t i) const {
  const FluidParticles& P = particles_;
  // The coupler's acceleration is exactly zero where no solid is in reach.
  return P.is_water(i) && P.spray[i] && P.external_a[i] == Vec2::Zero();
}

bool FluidSolver::is_thinned_spray(std::size_t i) const {
  return is_spray(i) && particles_.rho[i] < sph::screen::kLowest * parameters_.rho0;
}

void FluidSolver::remove_thinned_spray() {
  FluidParticles& P = particles_;
  std::vector<int> kept;
  kept.reserve(P.size());
  for (std::size_t i = 0; i < P.size(); ++i)
    if (!is_thinned_spray(i)) kept.push_back(static_cast<int>(i));
  const long leaving = static_cast<long>(P.size() - kept.size());
  if (leaving == 0) return;
  // Spray trickles away; when much of the water thins at once, the flow has
  // blown up. Counted per step, so that a long run's spray adds up freely.
  constexpr long kMostSprayPercent = 1;
  const long water = std::count(P.kind.begin(), P.kind.end(), Kind::water);
  if (100 * leaving > kMostSprayPercent * water) {
    std::ostringstream message;
    message << "t = " << time_ << " s, step " << steps_ << ": " << leaving << " of " << water
            << " water particles thinned to spray below " << sph::screen::kLowest
            << " rho0 in one step, more than " << kMostSprayPercent
            << " % of the water; the run has blown up: try a smaller run.cfl";
    throw sph::RunawayError(message.str());
  }
  spray_removed_ += leaving;
  wall_forces_before_removal_ = forces_on_walls(P, pairs_, parameters_);
  P.keep_only(kept);
  verlet_.keep_only(kept);
  spray_left_ = true;  // the grid and the Verlet list still hold the old indices
}

void FluidSolver::collect_interface(const sph::Region& region, sph::InterfaceParticles& out) {
  const FluidParticles& P = particles_;
  out.clear();
  interface_index_.clear();
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (!P.is_water(i) || !region.contains(P.x[i])) continue;
    interface_index_.push_back(static_cast<long>(i));
    out.add(P.id[i], P.x[i], P.v[i], -P.p[i] * Mat2::Identity() + P.tau[i], P.m[i], P.rho[i],
            parameters_.h, parameters_.c0);
  }
}

void FluidSolver::set_interface_accelerations(const std::vector<Vec2>& accelerations) {
  sph::scatter_interface_accelerations(interface_index_, accelerations, particles_.external_a);
}

void FluidSolver::set_interface_density_rates(const std::vector<double>& density_rates) {
  sph::scatter_interface_values(interface_index_, density_rates, 0.0, particles_.external_drho);
}

sph::Region FluidSolver::interaction_bounds() const {
  return sph::bounds_of(particles_.x, [this](long i) { return particles_.is_water(i); });
}

std::vector<Vec2> FluidSolver::wall_forces() const {
  // Thinned spray has no wall in reach: leaving, it took no wall force along.
  return spray_left_ ? wall_forces_before_removal_
                     : forces_on_walls(particles_, pairs_, parameters_);
}

std::vector<sph::Gauge> FluidSolver::gauge_values() const {
  const WaterGauges g = gauges();
  std::vector<sph::Gauge> values = {
      {"front", "m", g.front},
      {"height", "m", g.height},
      {"kinetic_energy", "J/m", g.kinetic_energy},
      {"max_speed", "m/s", g.max_speed},
      {"water_particles", "1", static_cast<double>(g.water_particles)},
      {"spray_removed", "1", static_cast<double>(spray_removed_)}};
  for (std::size_t k = 0; k < parameters_.pressure_probes.size(); ++k)
    values.push_back({"probe" + std::to_string(k) + "_pressure", "Pa",
                      probe_pressure(particles_, parameters_, parameters_.pressure_probes[k])});
  for (std::size_t k = 0; k < parameters_.level_probes.size(); ++k) {
    const auto level =
        water_level(particles_, parameters_.level_probes[k], parameters_.h, parameters_.dx);
    values.push_back(
        {"level" + std::to_string(k), "m", level ? *level - parameters_.floor_y : 0.0});
  }
  const std::vector<Vec2> forces = wall_forces();
  const std::size_t fixed = particles_.fixed_walls;
  for (std::size_t k = 0; k < forces.size(); ++k) {
    const std::string wall =
        k < fixed ? "wall" + std::to_string(k) : "moving_wall" + std::to_string(k - fixed);
    values.push_back({wall + "_force_x", "N/m", forces[k].x()});
    values.push_back({wall + "_force_y", "N/m", forces[k].y()});
  }
  return values;
}

const char* FluidSolver::runaway_reason(std::size_t i) const {
  const FluidParticles& P = particles_;
  if (!P.is_water(i)) return nullptr;
  if (!P.x[i].allFinite() || !P.v[i].allFinite() || !std::isfinite(P.rho[i]))
    return "its state is not finite";
  if (P.v[i].norm() > parameters_.c0)
    return "it moves faster than the sound speed c0 (weak compressibility is lost)";
  if (is_thinned_spray(i)) return nullptr;  // it leaves the water at the end of the step
  if (!sph::screen::within(P.rho[i], sph::screen::kLowest * parameters_.rho0,
                           sph::screen::kHighest * parameters_.rho0))
    return "its density left [0.5, 2] rho0";
  return nullptr;
}

bool FluidSolver::may_have_run_away() const {
  namespace screen = sph::screen;
  const FluidParticles& P = particles_;
  const double* const x = sph::doubles_of(P.x);
  const double* const v = sph::doubles_of(P.v);
  const double* const rho = P.rho.data();
  const Kind* const kind = P.kind.data();
  const double c0 = parameters_.c0, rho_min = screen::kLowest * parameters_.rho0,
               rho_max = screen::kHighest * parameters_.rho0;
  return sph::parallel_any(P.size(), sph::worth_threads(P.size()), [&](long i) {
    const bool sound = screen::finite_vector(x, i) & screen::clearly_slower(v, i, c0) &
                       screen::within(rho[i], rho_min, rho_max);
    return (kind[i] == Kind::water) & !sound;
  });
}

void FluidSolver::check_state() const {
  if (!may_have_run_away()) return;
  const FluidParticles& P = particles_;
  sph::stop_at_first_runaway(
      P, "water particle", time_, steps_, [this](std::size_t i) { return runaway_reason(i); },
      [&P](std::ostringstream& message, std::size_t i) {
        message << ", density " << P.rho[i]
                << " kg/m^3); the run has blown up: try a smaller run.cfl";
      });
}

sph::Snapshot FluidSolver::snapshot() const {
  const FluidParticles& P = particles_;
  sph::Snapshot snapshot(P.x);
  std::vector<int> kind(P.size());
  std::transform(P.kind.begin(), P.kind.end(), kind.begin(),
                 [](Kind k) { return static_cast<int>(k); });
  snapshot.add_scalar("id", P.id);
  snapshot.add_scalar("kind", kind);
  snapshot.add_vector("velocity", P.v);
  snapshot.add_scalar("density", P.rho);
  snapshot.add_scalar("pressure", P.p);
  snapshot.add_vector("acceleration", P.a);
  snapshot.add_scalar("drho", P.drho);
  std::vector<int> spray(P.size());
  for (std::size_t i = 0; i < P.size(); ++i) spray[i] = is_spray(i);
  snapshot.add_scalar("spray", spray);
  return snapshot;
}

}  // namespace cosph::fluid
