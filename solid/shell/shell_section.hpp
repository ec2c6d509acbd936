// The shell's cross-section per unit depth (plane strain): the stiffnesses of
// the Reissner-Mindlin (Timoshenko) beam, integrated through the thickness t.
//   E' = E / (1 - nu^2)   plane strain, for both membrane and bending
//   EA = E' t,  GA = k G t (k = 5/6, shear correction),  EI = E' t^3 / 12
// One particle across gives the exact bending stiffness EI: the through-
// thickness integral is done here, not by particles.
#pragma once

#include <cmath>

namespace cosph::solid::shell {

// Reissner's shear correction of a rectangular section (Timoshenko beam).
inline constexpr double kShearCorrection = 5.0 / 6.0;

struct ShellSection {
  double thickness;  // t, m
  double rho;        // kg/m^3
  double E_plane;    // E' = E / (1 - nu^2), Pa
  double G;          // shear modulus E / (2 (1 + nu)), Pa

  static ShellSection of(double thickness, double rho, double E, double nu) {
    return {thickness, rho, E / (1.0 - nu * nu), E / (2.0 * (1.0 + nu))};
  }
  double EA() const { return E_plane * thickness; }
  double GA() const { return kShearCorrection * G * thickness; }
  double EI() const { return E_plane * thickness * thickness * thickness / 12.0; }
  double mass_per_length() const { return rho * thickness; }
  double inertia_per_length() const { return rho * thickness * thickness * thickness / 12.0; }
  // Axial (membrane) wave speed sqrt(E' / rho).
  double sound_speed() const { return std::sqrt(E_plane / rho); }
  // Cut-off angular frequency of the rotation against the shear, the highest
  // frequency of a Timoshenko beam at long wavelengths: sqrt(GA / (rho I)).
  double rotation_frequency() const { return std::sqrt(GA() / inertia_per_length()); }
};

}  // namespace cosph::solid::shell
