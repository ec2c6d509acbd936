// The shell as the water sees it: both of its faces. Each mid-line particle i
// presents two interface particles, one on each face, at
//   x_f = x_i + r_f,   r_f = +-(t/2) d_i   (d_i the current director)
// moving with the section as a rigid body,
//   v_f = v_i + omega_i e_z x r_f,
// each carrying half the particle's mass m_i / 2, the smoothing length h and
// the axial sound speed, and the volume of one layer of wall particles at the
// solid's spacing dx, V_f = V_i dx (V_i the particle's length of line; the
// density sent is m_f / V_f). The water sees a solid as wall particles of
// their volume (coupler/src/cross_phase_forces.hpp, moving_wall): a face
// standing for the half-thickness, V_f = V_i t / 2, pushed the water with
// about t / (2 dx) times the pressure's force, twice it at t = 4 dx. Its stress is
// that of the face's fibre, sigma = sigma_11 t (x) t with
//   sigma_11 = N / t - z M / I,  z = +-t/2 along d
// (zero shear and zero normal stress: a free face's; the coupler's default
// moving_wall interface reads the water's pressure instead, stress_sum reads
// this). The coupler's accelerations a_f on the face particles return to the
// mid-line particle as a force and a moment about it:
//   F_i = sum_f m_f a_f,   M_i = sum_f r_f x m_f a_f.
// Face particle ids: 2 id + 0 on the +d face, 2 id + 1 on the -d face.
#pragma once

#include <vector>

#include "shell_particles.hpp"
#include "shell_section.hpp"
#include "sphcore/interface_particles.hpp"
#include "sphcore/region.hpp"

namespace cosph::solid::shell {

class ShellFaces {
 public:
  // The face particles inside `region`, on clamped particles too.
  void collect(const ShellParticles& P, const ShellSection& section, double phi0, double h,
               double dx, const sph::Region& region, sph::InterfaceParticles& out);

  // The coupler's accelerations, in the order of the last collect, as linear
  // and angular accelerations of the mid-line particles (external_a,
  // external_alpha); particles without a face sent get none.
  void scatter(const std::vector<Vec2>& accelerations, ShellParticles& P) const;

  // Where the face of particle i on side +1 (+d) or -1 (-d) is.
  static Vec2 offset(const ShellSection& section, double phi, int side);

 private:
  struct Sent {
    long particle;
    Vec2 r;       // the face's offset from the mid-line particle
    double mass;  // the face particle's mass
  };
  std::vector<Sent> sent_;
};

}  // namespace cosph::solid::shell
