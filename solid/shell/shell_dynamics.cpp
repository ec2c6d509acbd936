#include "shell_dynamics.hpp"

#include <vector>

#include "line_hourglass.hpp"
#include "reissner_beam.hpp"

namespace cosph::solid::shell {

void compute_strains(ShellParticles& P, const ShellForceParameters& parameters) {
  for (std::size_t i = 0; i < P.size(); ++i) {
    Vec2 dx_dS = Vec2::Zero();
    double kappa = 0.0;
    for (const LineNeighbour& b : P.neighbours[i]) {
      dx_dS += (P.x[b.j] - P.x[i]) * b.G;
      kappa += (P.theta[b.j] - P.theta[i]) * b.G;
    }
    // A clamp's inner particle has no neighbours: it stays as built, unstrained.
    if (P.neighbours[i].empty()) dx_dS = DirectorFrame::at(parameters.phi0).t;
    P.dx_dS[i] = dx_dS;
    P.kappa[i] = kappa;
    const BeamResultants r =
        beam_resultants(dx_dS, parameters.phi0 + P.theta[i], kappa, parameters.section);
    P.N[i] = r.N;
    P.Q[i] = r.Q;
    P.M[i] = r.M;
    P.strain_energy[i] = r.strain_energy;
  }
}

void compute_accelerations(ShellParticles& P, const ShellForceParameters& parameters) {
  const std::size_t n = P.size();
  std::vector<Vec2> force(n, Vec2::Zero());
  std::vector<double> moment(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const BeamResultants r =
        beam_resultants(P.dx_dS[i], parameters.phi0 + P.theta[i], P.kappa[i], parameters.section);
    moment[i] += P.V[i] * r.couple;
    for (const LineNeighbour& b : P.neighbours[i]) {
      const Vec2 f = P.V[i] * b.G * r.n;
      const double m = P.V[i] * b.G * r.M;
      force[i] += f;
      force[b.j] -= f;
      moment[i] += m;
      moment[b.j] -= m;
    }
  }
  add_hourglass_control(P, parameters.section, parameters.hourglass_alpha, parameters.ds, force,
                        moment);
  for (std::size_t i = 0; i < n; ++i) {
    P.a[i] = P.clamped[i] ? Vec2::Zero() : Vec2(force[i] / P.m[i]);
    P.alpha[i] = P.clamped[i] ? 0.0 : moment[i] / P.J[i];
  }
}

}  // namespace cosph::solid::shell
