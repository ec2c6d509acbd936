// The reference configuration of the total-Lagrangian solid (docs/physics.md,
// "Total-Lagrangian solid"): the particles of the case's scene
// (solid/common/solid_scene.hpp: lattice, clamp, weakened regions, initial
// bending mode) at their initial positions X, their
// neighbour lists and corrected kernel gradients, fixed for the whole run
// (Bonet & Lok 1999, CMAME 180; Vignjevic, Reveles & Campbell 2006):
//   L0_i = [ sum_j V0_j grad0 W_ij (x) (X_j - X_i) ]^-1,  grad~0 W_ij = L0_i grad0 W_ij,
// so that sum_j V0_j (f_j - f_i) (x) grad~0 W_ij is the exact gradient of any
// linear f, at the free surfaces and corners too. The matrix in brackets is
// symmetric (grad0 W_ij is parallel to X_i - X_j), so the order of the
// product does not matter. Fixed neighbours are what cures the tensile
// instability: particles cannot swap partners, however the body is stretched.
#pragma once

#include "solid_parameters.hpp"
#include "sphcore/case_file.hpp"
#include "tl_particles.hpp"

namespace cosph::solid::tl {

// The particles in cell order (neighbours close in memory), with their
// reference neighbours and L0; x = X, F = I.
TLParticles build_reference_configuration(const sph::CaseFile& case_file,
                                          const SolidParameters& parameters);

// Fills neighbours and L0 from X, V0 (the particles within 2h), and inert
// and reach_end from them and clamped.
void find_reference_neighbours(TLParticles& particles, double h);

// L0 = M^-1, or the identity where M is singular (a particle with no
// neighbours off one line). Unlike the fluid's renormalisation this inverts
// poorly conditioned matrices too: the reference lattice is regular, and at a
// corner a plain gradient would leave the body stressed at rest.
Mat2 reference_correction(const Mat2& M);

}  // namespace cosph::solid::tl
