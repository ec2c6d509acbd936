// The fluid solver's particles, struct-of-arrays: water and the rigid wall
// particles that hold it, in one set so that one neighbour grid serves both.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "sphcore/ordered_shares.hpp"
#include "sphcore/permutation.hpp"
#include "sphcore/types.hpp"
#include "total_stress.hpp"

namespace cosph::fluid {

using sph::Mat2;
using sph::Vec2;

// A moving wall follows one of fluid.moving_walls (wall_motion.hpp); every
// test for "not water" treats it as a wall.
enum class Kind : std::uint8_t { water = 0, wall = 1, moving_wall = 2 };

struct FluidParticles {
  // State, carried from step to step (permuted with the neighbour grid).
  std::vector<int> id;
  std::vector<Kind> kind;
  std::vector<Vec2> x, v;
  std::vector<double> rho, m;

  // Renormalised density gradient <grad rho> of the previous step: state too,
  // since the density diffusion reads it.
  std::vector<Vec2> grad_rho;
  // Acceleration from outside the fluid (the coupler's cross-phase term):
  // state too, since the next step's first kick reads it, and it tells which
  // water has the solid in reach (FluidSolver::is_spray).
  std::vector<Vec2> external_a;
  // delta-plus-SPH's particle shift (fluid.shifting), to be added at the next
  // drift: state, since it is found from one step's pairs and used in the next.
  std::vector<Vec2> shift;
  // Moving walls: where the particle was drawn (its place at zero
  // displacement or angle), and the wall's acceleration there now, which the
  // wall pressure needs (zero for the other particles).
  std::vector<Vec2> x_drawn, wall_a;

  // Derived each step from the state.
  std::vector<double> p;               // pressure (walls: extrapolated from the water)
  std::vector<Mat2> tau;               // viscous stress
  std::vector<SymmetricStress> sigma;  // total stress -p I + tau, for the momentum pass
  std::vector<double> inverse_rho;     // 1 / rho, once per particle rather than per pair
  std::vector<Vec2> grad_rho_next;     // being computed
  std::vector<double> volume;          // m / rho, once per particle rather than per pair
  std::vector<Vec2> a;                 // dv/dt
  std::vector<double> drho;            // drho/dt
  std::vector<double> external_drho;   // density rate from outside (a moving solid wall)
  // 1 for spray as the water alone sees it: no wall in reach, and the water
  // around the particle too sparse to renormalise (sph::can_renormalise).
  // FluidSolver::is_spray adds that no solid is in reach either.
  std::vector<std::uint8_t> spray;
  // Walls: the unit normal towards the water in reach, -sum_f rho_f (x_w - x_f)
  // W_wf normalised (the wall pressure's moment); zero with none in reach.
  // Kept only with fluid.wall_friction "normal", the one option that reads it.
  std::vector<Vec2> wall_n;
  // 1 for water on the free surface as particle shifting sees it
  // (DeltaPlusShifting::on_surface).
  std::vector<std::uint8_t> on_surface;
  // What each pair pass reads of a neighbour j, copied together at the start
  // of the pass: a pass waits on memory for j's values, and from one record
  // it loads one or two cache lines a neighbour, not one from each array.
  struct ContinuityNeighbour {
    Vec2 x, v;
    double rho, V, p;  // V = m / rho
  };
  std::vector<ContinuityNeighbour> continuity_neighbours;
  struct MomentumNeighbour {
    Vec2 x, v;
    SymmetricStress sigma;
    double rho, inverse_rho, m;
  };
  std::vector<MomentumNeighbour> momentum_neighbours;
  // The momentum pass's shares for later blocks of particles (sph::OrderedShares).
  sph::OrderedShares<Vec2> a_shares{Vec2::Zero()};

  // Scene, fixed: the wall particles of fluid.walls[k] have the ids from
  // first_wall_id[k] up to first_wall_id[k + 1] (the last box: up to the
  // largest id). Ids survive the sorts; a per-particle field would have to be
  // permuted with them. The fixed walls come first, then fluid.moving_walls:
  // wall fixed_walls + k is moving wall k.
  std::vector<int> first_wall_id;
  std::size_t fixed_walls = 0;

  std::size_t size() const { return x.size(); }
  bool is_water(std::size_t i) const { return kind[i] == Kind::water; }
  bool is_moving_wall(std::size_t i) const { return kind[i] == Kind::moving_wall; }
  // Which of fluid.walls wall particle i belongs to.
  int wall_of(std::size_t i) const {
    const auto after = std::upper_bound(first_wall_id.begin(), first_wall_id.end(), id[i]);
    return static_cast<int>(after - first_wall_id.begin()) - 1;
  }

  void add(int particle_id, Kind particle_kind, const Vec2& position, double density, double mass) {
    id.push_back(particle_id);
    kind.push_back(particle_kind);
    x.push_back(position);
    v.push_back(Vec2::Zero());
    rho.push_back(density);
    m.push_back(mass);
    x_drawn.push_back(position);
    wall_a.push_back(Vec2::Zero());
  }

  // Sizes the derived fields to match the state.
  void resize_derived() {
    const std::size_t n = size();
    grad_rho.assign(n, Vec2::Zero());
    p.assign(n, 0.0);
    tau.assign(n, Mat2::Zero());
    grad_rho_next.assign(n, Vec2::Zero());
    a.assign(n, Vec2::Zero());
    drho.assign(n, 0.0);
    external_a.assign(n, Vec2::Zero());
    shift.assign(n, Vec2::Zero());
    external_drho.assign(n, 0.0);
    spray.assign(n, 0);
    wall_n.assign(n, Vec2::Zero());
  }

  // Puts the fields marked as state above into `order`, the neighbour
  // grid's: new index k holds old particle order[k]. The derived fields are
  // computed again from it before anything reads them.
  void permute_state(const std::vector<int>& order) {
    sph::permute(order, id, kind, x, v, rho, m, grad_rho, external_a, shift, x_drawn, wall_a);
  }

  // Keeps the particles kept[0], kept[1], ... in that order; the others leave
  // with everything known of them.
  void keep_only(const std::vector<int>& kept) {
    sph::permute(kept, id, kind, x, v, rho, m, grad_rho, p, tau, sigma, inverse_rho, grad_rho_next,
                 volume, a, drho, external_a, shift, external_drho, spray, x_drawn, wall_a, wall_n);
  }
};

}  // namespace cosph::fluid
