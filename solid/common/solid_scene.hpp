// The particles of a case's solid, before either model takes them: the body
// on a square lattice at its reference density, the clamp, weakened regions,
// and the initial velocity (at rest, or a cantilever's first bending mode).
// Both models build their own particles from it (docs/physics.md, "Jaumann
// solid" and "Total-Lagrangian solid"), so a case means one body to both.
#pragma once

#include <cstdint>
#include <vector>

#include "solid_parameters.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/types.hpp"

namespace cosph::solid {

using sph::Mat2;
using sph::Vec2;

// Struct-of-arrays, in the order the lattice fills the bodies.
struct SolidScene {
  std::vector<int> id;
  std::vector<Vec2> x, v;       // initial position and velocity
  std::vector<double> rho, m;   // reference density, mass
  std::vector<double> K, G, c;  // bulk and shear moduli, P-wave speed
  std::vector<double> sigma_y;  // von Mises yield stress (used when fracture is on)
  std::vector<std::uint8_t> clamped;

  std::size_t size() const { return x.size(); }
};

SolidScene build_solid_scene(const sph::CaseFile& case_file, const SolidParameters& parameters);

}  // namespace cosph::solid
