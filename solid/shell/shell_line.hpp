// How a case's body box becomes a shell, and the shell's reference line.
//
// The thin-box rule: the shell model reads its one solid.body box as a plate
// along the box's long side, of thickness t the short side, when
//   t <= kMostSpacingsAcross dx   and   t <= length / kLeastSlenderness;
// any other box is refused (a continuum model suits it). The mid-line
// particles sit on the box's centre line at spacing ds = length / n,
// n = round(length / dx), from one end of the line to the other (n + 1 of
// them: a particle on each end, standing for ds / 2 of line, the others for
// ds), so that a free end and a clamp's face carry a particle. A particle
// inside a solid.clamp box is clamped (position and rotation fixed).
//
// The clamp holds the line at its face: a clamped particle next to a free one
// (within 1.5 ds) is the face, and the strains are taken over the free
// particles and the faces only. The clamp's inner particles stand still and
// take part in nothing but the water's view of the plate: were they in the
// free particles' kernel sums, the kink of the curvature at the face (zero
// inside the clamp, largest at the root) would be smeared over the kernel's
// reach, and the plate would bend as if about one spacing longer.
#pragma once

#include <optional>

#include "shell_particles.hpp"
#include "shell_section.hpp"
#include "solid_parameters.hpp"
#include "sphcore/case_file.hpp"

namespace cosph::solid::shell {

inline constexpr double kMostSpacingsAcross = 6.0;
inline constexpr double kLeastSlenderness = 4.0;

struct ShellLine {
  Vec2 start;           // one end of the mid-line
  Vec2 tangent;         // unit vector along it, +x or +y
  double length;        // m
  double thickness;     // m
  int count;            // particles along
  double ds;            // length / count
  double phi0() const;  // reference angle of the tangent
};

// Throws sph::ConfigError naming solid.body unless the case gives one box
// that the thin-box rule reads as a shell.
ShellLine read_shell_line(const sph::CaseFile& case_file, double dx);

// The particles of the line, at rest or with the first bending mode of a
// horizontal cantilever (solid.initial_velocity), with their reference
// neighbours and corrected gradients (h: the smoothing length).
ShellParticles build_shell(const sph::CaseFile& case_file, const SolidParameters& parameters,
                           const ShellLine& line, const ShellSection& section);

// The neighbours within 2h along the reference line among the free particles
// and the clamps' faces, with gradient weights G_ij exact for fields
// quadratic in S, free ends and clamp faces included: the kernel-weighted
// least-squares fit of f_j - f_i = g S_ij + c S_ij^2 / 2 (weights V_j W_ij),
// whose g is sum_j G_ij (f_j - f_i). A gradient exact only for linear fields
// errs by O(ds f'') at the ends, where the shear strain w' - theta of a bent
// plate then reads nonzero and its large stiffness GA locks the bending: the
// plate came out 11 % too stiff at 8 particles, 3.5 % at 32.
void find_line_neighbours(ShellParticles& P, double h);

}  // namespace cosph::solid::shell
