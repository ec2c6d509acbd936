#include "shell_faces.hpp"

#include "reissner_beam.hpp"

namespace cosph::solid::shell {

Vec2 ShellFaces::offset(const ShellSection& section, double phi, int side) {
  return (0.5 * side * section.thickness) * DirectorFrame::at(phi).d;
}

void ShellFaces::collect(const ShellParticles& P, const ShellSection& section, double phi0,
                         double h, double dx, const sph::Region& region,
                         sph::InterfaceParticles& out) {
  out.clear();
  sent_.clear();
  const double t = section.thickness, I = t * t * t / 12.0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const double phi = phi0 + P.theta[i];
    const Vec2 tangent = DirectorFrame::at(phi).t;
    for (const int side : {+1, -1}) {
      const Vec2 r = offset(section, phi, side);
      const Vec2 x = P.x[i] + r;
      if (!region.contains(x)) continue;
      const Vec2 v = P.v[i] + P.omega[i] * Vec2(-r.y(), r.x());
      // The face point turns with the section: tangential and centripetal parts.
      const Vec2 a =
          P.kick_a[i] + P.kick_alpha[i] * Vec2(-r.y(), r.x()) - P.omega[i] * P.omega[i] * r;
      const double z = 0.5 * side * t;
      const double sigma_11 = P.N[i] / t - z * P.M[i] / I;
      const sph::Mat2 sigma = sigma_11 * tangent * tangent.transpose();
      const double mass = 0.5 * P.m[i], volume = P.V[i] * dx;
      sent_.push_back({static_cast<long>(i), r, mass});
      out.add(2L * P.id[i] + (side > 0 ? 0 : 1), x, v, a, sigma, mass, mass / volume, h, P.c[i]);
    }
  }
}

void ShellFaces::scatter(const std::vector<Vec2>& accelerations, ShellParticles& P) const {
  std::fill(P.external_a.begin(), P.external_a.end(), Vec2::Zero());
  std::fill(P.external_alpha.begin(), P.external_alpha.end(), 0.0);
  for (std::size_t k = 0; k < sent_.size() && k < accelerations.size(); ++k) {
    const Sent& face = sent_[k];
    const Vec2 force = face.mass * accelerations[k];
    P.external_a[face.particle] += force / P.m[face.particle];
    P.external_alpha[face.particle] += cross(face.r, force) / P.J[face.particle];
  }
}

}  // namespace cosph::solid::shell
