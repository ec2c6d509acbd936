// Pressure of a rigid wall particle extrapolated from the water around it
// (Adami, Hu & Adams 2012, J. Comput. Phys. 231:7057, eq. 27):
//   P_w = ( sum_f P_f W_wf + (g - a_w) . sum_f rho_f (x_w - x_f) W_wf ) / sum_f W_wf
// Unlike walls that evolve their own density, this leaves no gap of about h
// between water and wall. The fluid's fixed walls have a_w = 0, its moving
// walls the acceleration of their prescribed motion; the coupler uses the same
// sum for solid particles seen by the water as a moving wall, with a_w the
// solid's acceleration when coupling.wall_acceleration asks for it
// (docs/physics.md, "Moving wall").
#pragma once

#include "sphcore/types.hpp"

namespace sph {

struct WallPressureSum {
  double weight = 0.0;         // sum_f W_wf
  double pressure = 0.0;       // sum_f P_f W_wf
  Vec2 moment = Vec2::Zero();  // sum_f rho_f (x_w - x_f) W_wf

  void add(double P_f, double rho_f, const Vec2& x_wf, double W_wf) {
    weight += W_wf;
    pressure += P_f * W_wf;
    moment += (rho_f * W_wf) * x_wf;
  }

  // Zero for a wall particle with no water in reach. `body_force` is g - a_w.
  double wall_pressure(const Vec2& body_force) const {
    return weight > 0.0 ? (pressure + body_force.dot(moment)) / weight : 0.0;
  }

  // The wall particle's unit normal towards the water in its reach, along
  // -moment (the water's kernel-weighted side), with no geometry needed;
  // zero with no water in reach (fluid.wall_friction "normal" reads it).
  Vec2 normal_to_water() const {
    const double length = moment.norm();
    return length > 0.0 ? Vec2(-moment / length) : Vec2::Zero();
  }
};

}  // namespace sph
