// Which dissipation the water's sound waves and pressure noise meet
// (fluid.dissipation, proto/case.proto):
//   delta_sph  density diffusion with renormalised gradients (density_diffusion.hpp)
//              and Monaghan's artificial viscosity;
//   fourtakas  density diffusion with the hydrostatic part removed
//              (hydrostatic_density_diffusion.hpp) and Monaghan's viscosity;
//   riemann    Riemann-solver SPH with the dissipation limiter in both
//              equations (sphcore/riemann_dissipation.hpp), no artificial viscosity:
//              the default (docs/physics.md, "Choice of water").
#pragma once

#include <type_traits>

#include "sphcore/artificial_viscosity.hpp"
#include "sphcore/riemann_dissipation.hpp"
#include "sphcore/types.hpp"

namespace cosph::fluid {

using sph::Vec2;

enum class Dissipation { delta_sph, fourtakas, riemann };

// How the momentum dissipation term acts between the water and its walls
// (fluid.wall_friction, proto/case.proto): as between water particles, along
// the line between the two (dissipation: it brakes water sliding along a
// wall); not at all (none: free-slip walls); or on the relative velocity's
// part along the wall's normal only (normal: free-slip walls that still damp
// water running into them, as a mirrored ghost particle would).
enum class WallFriction { dissipation, none, normal };

// f(std::integral_constant<Dissipation, d>{}) for the run's dissipation d: a
// pass written once and compiled for each, so that its pair loop holds only
// the chosen one's terms.
template <class F>
decltype(auto) with_dissipation(Dissipation dissipation, F&& f) {
  switch (dissipation) {
    case Dissipation::fourtakas:
      return f(std::integral_constant<Dissipation, Dissipation::fourtakas>{});
    case Dissipation::riemann:
      return f(std::integral_constant<Dissipation, Dissipation::riemann>{});
    case Dissipation::delta_sph:
      break;
  }
  return f(std::integral_constant<Dissipation, Dissipation::delta_sph>{});
}

// The Pi_ij of the momentum bracket for dissipation d: Monaghan's artificial
// viscosity or the Riemann solver's limited dissipation, chosen at compile
// time with the pass (with_dissipation).
template <Dissipation d>
class MomentumDissipation {
 public:
  MomentumDissipation(double h, double c0, double A, double B)
      : monaghan_(h, c0, A, B), riemann_limited_(c0) {}

  // r = |x_ij|: the neighbour list's, which the Riemann term reads.
  double operator()(const Vec2& x_ij, const Vec2& v_ij, double rho_bar, double r) const {
    if constexpr (d == Dissipation::riemann)
      return riemann_limited_(x_ij, v_ij, rho_bar, r);
    else
      return monaghan_(x_ij, v_ij, rho_bar);
  }

 private:
  sph::UniformArtificialViscosity monaghan_;
  sph::RiemannLimitedDissipation riemann_limited_;
};

// The Pi_ij of a water particle i and a wall particle j, whose normal towards
// the water is n_w, under fluid.wall_friction.
template <class MomentumPi>
double wall_dissipation(const MomentumPi& Pi, WallFriction friction, const Vec2& x_ij,
                        const Vec2& v_ij, const Vec2& n_w, double rho_bar, double r) {
  switch (friction) {
    case WallFriction::none:
      return 0.0;
    case WallFriction::normal:
      return Pi(x_ij, Vec2(n_w * n_w.dot(v_ij)), rho_bar, r);
    case WallFriction::dissipation:
      break;
  }
  return Pi(x_ij, v_ij, rho_bar, r);
}

}  // namespace cosph::fluid
