// The shell's dissipation: a Kelvin-Voigt stress on the section's strain
// rates, the numerical damping SPHinXsys gives its thin-structure shells
// (Wu, Zhang & Hu 2024, J. Comput. Phys. 113113; SPHinXsys's
// NumericalDampingRightCauchy): a viscous stress 0.5 rho c l times the
// strain-rate tensor's component, with c a wave speed and l a length of the
// discretisation, so that it damps the modes a few spacings long and leaves
// the long ones (the plate's bending) nearly untouched. For the normal rates
// (membrane, and bending through the thickness) l = h and c the section's
// membrane wave speed sqrt(E' / rho), where SPHinXsys takes the 3-D bulk
// speed sqrt(K / rho), which a plate's membrane does not carry (and which
// grows without bound as nu -> 1/2); for the transverse shear c_G =
// sqrt(G / rho) and l = min(t, h), as SPHinXsys scales its out-of-plane
// component. Integrated through the thickness, with the engineering shear
// rate gamma' = 2 x the tensor's component and the shear correction k:
//   N_d = eta_n t eps',  M_d = eta_n t^3 / 12 kappa',  Q_d = k eta_s t gamma',
//   eta_n = 0.5 rho c h,  eta_s = 0.25 rho c_G min(t, h).
// Its damping ratios for the elastic plate (first bending mode, the
// shear-rotation cut-off, the zigzags h / (2 ds)) are computed by
// scripts/shell_window_vibration.py.
#pragma once

#include <algorithm>
#include <cmath>

#include "shell_section.hpp"

namespace cosph::solid::shell {

struct ShellDamping {
  double eta_normal = 0.0;  // Pa s, on the membrane and bending strain rates
  double eta_shear = 0.0;   // Pa s, on the engineering shear rate

  static ShellDamping of(const ShellSection& section, double h) {
    const double shear_speed = std::sqrt(section.G / section.rho);
    return {0.5 * section.rho * section.sound_speed() * h,
            0.25 * section.rho * shear_speed * std::min(section.thickness, h)};
  }
  bool any() const { return eta_normal > 0.0 || eta_shear > 0.0; }

  // Damping ratio of the stiffest modes, the axial and the rotation zigzag
  // between neighbours ds apart (omega = 2 c / ds): eta_n / (rho c ds).
  double zigzag_damping_ratio(const ShellSection& section, double ds) const {
    return eta_normal / (section.rho * section.sound_speed() * ds);
  }
  // Damping ratio of the shear-rotation cut-off (the section turning against
  // its shear, omega_r = sqrt(GA / (rho I))): k eta_s t / (2 sqrt(GA rho I)),
  // so zeta / omega_r = eta_s / (2 G) = min(t, h) / (8 c_G). Every mode has
  // zeta / omega = eta / (2 modulus) of the damping it strains: h / (4 c) on
  // the normal rates, min(t, h) / (8 c_G) on the shear; the shear's is the
  // smaller, min(t, h) / h sqrt(1 / (2 (1 - nu))) <= 1 times the other.
  double rotation_damping_ratio(const ShellSection& section) const {
    return kShearCorrection * eta_shear * section.thickness /
           (2.0 * std::sqrt(section.GA() * section.inertia_per_length()));
  }
  // Explicit (leapfrog) stepping of a damped oscillator is stable for
  // omega dt <= 2 (sqrt(1 + zeta^2) - zeta), the undamped bound shrunk by
  // this factor: the shell's sound limit takes it for its zigzags.
  double step_factor(const ShellSection& section, double ds) const {
    const double zeta = zigzag_damping_ratio(section, ds);
    return std::sqrt(1.0 + zeta * zeta) - zeta;
  }
};

}  // namespace cosph::solid::shell
