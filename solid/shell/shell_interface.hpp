// The shell as the water sees it: its section filled with particles, as a
// continuum solid of the same spacing presents its body. Each mid-line
// particle i stands for n = round(t / dx) interface particles across the
// thickness (dx the solid's spacing, at least one), at
//   x_k = x_i + r_k,   r_k = z_k d_i,   z_k = -t/2 + (k + 1/2) t / n
// (d_i the current director: the outer ones half a layer inside the faces),
// moving with the section as a rigid body,
//   v_k = v_i + omega_i e_z x r_k,
// each with its share of the section, mass m_i / n and volume V_i t / n (so
// the shell's density), the smoothing length h and the axial sound speed.
// Why the whole section and not its two faces: the water sees a solid as
// wall particles of their volume (coupler/src/cross_phase_forces.hpp,
// moving_wall), and a wall holds the water out only when it is as deep as the
// kernel's reach 2 h_fs (Adami, Hu & Adams 2012; the water's own walls are).
// A single line of particles on each face is a leaky wall: in the coupled
// elastic plate the water crossed it into the section from t = 0.025 s and
// the run blew up at 0.16 s. A shell thicker than the reach keeps its inner
// layers away from the water, where they find no pair.
// Stress: that of the layer's fibre, sigma = sigma_11 t (x) t with
//   sigma_11 = N / t - z_k M / I
// (the coupler's default moving_wall interface reads the water's pressure
// instead; stress_sum reads this). The coupler's accelerations a_k return to
// the mid-line particle as a force and a moment about it:
//   F_i = sum_k m_k a_k,   M_i = sum_k r_k x m_k a_k.
// Interface particle ids: n id + k.
#pragma once

#include <vector>

#include "shell_particles.hpp"
#include "shell_section.hpp"
#include "sphcore/interface_particles.hpp"
#include "sphcore/region.hpp"

namespace cosph::solid::shell {

class ShellInterface {
 public:
  // The section's particles inside `region`, on clamped particles too.
  void collect(const ShellParticles& P, const ShellSection& section, double h, double dx,
               const sph::Region& region, sph::InterfaceParticles& out);

  // The coupler's accelerations, in the order of the last collect, as linear
  // and angular accelerations of the mid-line particles (external_a,
  // external_alpha); particles without an interface particle sent get none.
  void scatter(const std::vector<Vec2>& accelerations, ShellParticles& P) const;

  // How many interface particles each mid-line particle presents across the
  // thickness at the solid's spacing dx.
  static int layers(const ShellSection& section, double dx);

  // Where the face of particle i on side +1 (+d) or -1 (-d) is.
  static Vec2 face_offset(const ShellSection& section, double phi, int side);

 private:
  struct Sent {
    long particle;
    Vec2 r;       // the interface particle's offset from the mid-line particle
    double mass;  // the interface particle's mass
  };
  std::vector<Sent> sent_;
};

}  // namespace cosph::solid::shell
