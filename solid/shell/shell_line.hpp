// How a case's body becomes a shell, and the shell's reference line.
//
// The thin-body rule: the shell model reads its one solid.body as a plate,
// of thickness t, when it is slender enough for a beam theory,
//   t <= length / kLeastSlenderness,
// and refuses any other (a continuum model suits it). The body may be
//  - a box, or a rectangle at any angle given as a polygon of 4 vertices:
//    a straight plate along its long side, t its short side;
//  - a band (proto/case.proto Band): the plate along the band's line, which
//    may be curved or kinked, t the band's thickness.
// The spacing dx is the mid-line's, not tied to t: the thickness is a
// property of the section, so a 5 mm plate may take 2, 1 or 0.5 mm along its
// line. The mid-line particles sit on the line at equal arc length
// ds = length / n, n = round(length / dx), from one end to the other (n + 1
// of them: a particle on each end, standing for ds / 2 of line, the others
// for ds), so that a free end and a clamp's face carry a particle. A particle
// inside a solid.clamp region is clamped (position and rotation fixed).
//
// The stress points (shell_dynamics.hpp) lie between neighbouring particles
// of which one at least is free: the line between two clamped particles
// neither moves nor strains, so the plate bends from the clamp's face. A
// curved line is the polygon through its particles: a stress point's
// reference tangent is its chord's, so that the line at rest is unstrained;
// a particle's director, which places the faces the water sees, is normal
// to the given line where the particle sits.
#pragma once

#include <optional>
#include <vector>

#include "shell_particles.hpp"
#include "shell_section.hpp"
#include "solid_parameters.hpp"
#include "sphcore/case_file.hpp"

namespace cosph::solid::shell {

inline constexpr double kLeastSlenderness = 4.0;

struct ShellLine {
  // The mid-line's vertices from one end to the other, the end-to-end chord
  // towards +x (towards +y when upright); 2 for a straight plate.
  std::vector<Vec2> points;
  double length;     // along the line, m
  double thickness;  // m
  int count;         // particles along
  double ds;         // length / (count - 1)

  bool straight() const { return points.size() == 2; }
  // The point at arc length S from the first end, and the line's unit
  // tangent there (at a vertex, the mean of its two segments').
  Vec2 at(double S) const;
  Vec2 tangent_at(double S) const;
};

// Throws sph::ConfigError naming solid.body unless the case gives one box,
// rectangle or band that the thin-body rule reads as a shell.
ShellLine read_shell_line(const sph::CaseFile& case_file, double dx);

// The particles of the line, at rest or with the first bending mode of a
// horizontal cantilever (solid.initial_velocity), and their stress points.
ShellParticles build_shell(const sph::CaseFile& case_file, const SolidParameters& parameters,
                           const ShellLine& line, const ShellSection& section);

}  // namespace cosph::solid::shell
