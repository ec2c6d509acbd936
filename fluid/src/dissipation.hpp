// Which dissipation the water's sound waves and pressure noise meet
// (fluid.dissipation, proto/case.proto):
//   delta_sph  density diffusion with renormalised gradients (density_diffusion.hpp)
//              and Monaghan's artificial viscosity: the default;
//   fourtakas  density diffusion with the hydrostatic part removed
//              (hydrostatic_density_diffusion.hpp) and Monaghan's viscosity;
//   riemann    Riemann-solver SPH with the dissipation limiter in both
//              equations (sphcore/riemann_dissipation.hpp), no artificial viscosity.
#pragma once

#include <type_traits>

#include "sphcore/artificial_viscosity.hpp"
#include "sphcore/riemann_dissipation.hpp"
#include "sphcore/types.hpp"

namespace cosph::fluid {

using sph::Vec2;

enum class Dissipation { delta_sph, fourtakas, riemann };

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

  double operator()(const Vec2& x_ij, const Vec2& v_ij, double rho_bar) const {
    if constexpr (d == Dissipation::riemann)
      return riemann_limited_(x_ij, v_ij, rho_bar);
    else
      return monaghan_(x_ij, v_ij, rho_bar);
  }

 private:
  sph::UniformArtificialViscosity monaghan_;
  sph::RiemannLimitedDissipation riemann_limited_;
};

}  // namespace cosph::fluid
