#include "shell_interface.hpp"

#include <algorithm>
#include <cmath>

#include "reissner_beam.hpp"

namespace cosph::solid::shell {

int ShellInterface::layers(const ShellSection& section, double dx) {
  return std::max(1, static_cast<int>(std::lround(section.thickness / dx)));
}

Vec2 ShellInterface::face_offset(const ShellSection& section, double phi, int side) {
  return (0.5 * side * section.thickness) * DirectorFrame::at(phi).d;
}

void ShellInterface::collect(const ShellParticles& P, const ShellSection& section, double h,
                             double dx, const sph::Region& region, sph::InterfaceParticles& out) {
  out.clear();
  sent_.clear();
  const double t = section.thickness, I = t * t * t / 12.0;
  const int n = layers(section, dx);
  const double layer = t / n;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const DirectorFrame frame = DirectorFrame::at(P.phi0[i] + P.theta[i]);
    const sph::Mat2 along = frame.t * frame.t.transpose();
    const double mass = P.m[i] / n, volume = P.V[i] * layer;
    for (int k = 0; k < n; ++k) {
      const double z = -0.5 * t + (k + 0.5) * layer;
      const Vec2 r = z * frame.d;
      const Vec2 x = P.x[i] + r;
      if (!region.contains(x)) continue;
      const Vec2 turn(-r.y(), r.x());  // e_z x r
      const Vec2 v = P.v[i] + P.omega[i] * turn;
      // The point turns with the section: tangential and centripetal parts.
      const Vec2 a = P.kick_a[i] + P.kick_alpha[i] * turn - P.omega[i] * P.omega[i] * r;
      const sph::Mat2 sigma = (P.N[i] / t - z * P.M[i] / I) * along;
      sent_.push_back({static_cast<long>(i), r, mass});
      out.add(static_cast<long>(n) * P.id[i] + k, x, v, a, sigma, mass, mass / volume, h, P.c[i]);
    }
  }
}

void ShellInterface::scatter(const std::vector<Vec2>& accelerations, ShellParticles& P) const {
  std::fill(P.external_a.begin(), P.external_a.end(), Vec2::Zero());
  std::fill(P.external_alpha.begin(), P.external_alpha.end(), 0.0);
  for (std::size_t k = 0; k < sent_.size() && k < accelerations.size(); ++k) {
    const Sent& sent = sent_[k];
    const Vec2 force = sent.mass * accelerations[k];
    P.external_a[sent.particle] += force / P.m[sent.particle];
    P.external_alpha[sent.particle] += cross(sent.r, force) / P.J[sent.particle];
  }
}

}  // namespace cosph::solid::shell
