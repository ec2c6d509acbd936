// How a case's body box becomes a shell, and the shell's reference line.
//
// The thin-box rule: the shell model reads its one solid.body box, or a
// rectangle at any angle given as a polygon of 4 vertices, as a plate along
// its long side, of thickness t the short side, when it is slender enough for
// a beam theory,
//   t <= length / kLeastSlenderness;
// any other box is refused (a continuum model suits it). The spacing dx is
// the mid-line's, not tied to t: the thickness is a property of the section,
// so a 5 mm plate may take 2, 1 or 0.5 mm along its line. The mid-line
// particles sit on the box's centre line at spacing ds = length / n,
// n = round(length / dx), from one end of the line to the other (n + 1 of
// them: a particle on each end, standing for ds / 2 of line, the others for
// ds), so that a free end and a clamp's face carry a particle. A particle
// inside a solid.clamp box is clamped (position and rotation fixed).
//
// The stress points (shell_dynamics.hpp) lie between neighbouring particles
// of which one at least is free: the line between two clamped particles
// neither moves nor strains, so the plate bends from the clamp's face.
#pragma once

#include <optional>

#include "shell_particles.hpp"
#include "shell_section.hpp"
#include "solid_parameters.hpp"
#include "sphcore/case_file.hpp"

namespace cosph::solid::shell {

inline constexpr double kLeastSlenderness = 4.0;

struct ShellLine {
  Vec2 start;           // one end of the mid-line
  Vec2 tangent;         // unit vector along it (x >= 0; +y when upright)
  double length;        // m
  double thickness;     // m
  int count;            // particles along
  double ds;            // length / count
  double phi0() const;  // reference angle of the tangent
};

// Throws sph::ConfigError naming solid.body unless the case gives one box or
// rectangle that the thin-box rule reads as a shell.
ShellLine read_shell_line(const sph::CaseFile& case_file, double dx);

// The particles of the line, at rest or with the first bending mode of a
// horizontal cantilever (solid.initial_velocity), and their stress points.
ShellParticles build_shell(const sph::CaseFile& case_file, const SolidParameters& parameters,
                           const ShellLine& line, const ShellSection& section);

}  // namespace cosph::solid::shell
