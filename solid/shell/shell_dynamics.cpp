#include "shell_dynamics.hpp"

#include <algorithm>
#include <vector>

#include "reissner_beam.hpp"

namespace cosph::solid::shell {

namespace {

// The viscous resultants at stress point k from the strain rates, the time
// derivatives of reissner_beam.hpp's strains with t' = omega d, d' = -omega t:
//   eps' = v'.t + omega x'.d,  gamma' = v'.d - omega x'.t,  kappa' = omega',
// with v' = (v_j - v_i) / ds, omega = (omega_i + omega_j) / 2 and
// omega' = (omega_j - omega_i) / ds, as the strains are taken. They enter n
// and x' x n as the elastic ones do: their power is dissipated, never gained.
void add_damping(const ShellParticles& P, std::size_t k, double phi,
                 const ShellForceParameters& parameters, BeamResultants& r) {
  const ShellStressPoints& s = P.stress;
  const std::size_t i = static_cast<std::size_t>(s.i[k]), j = i + 1;
  const DirectorFrame frame = DirectorFrame::at(phi);
  const Vec2 dv_dS = (P.v[j] - P.v[i]) / s.ds[k];
  const double omega = 0.5 * (P.omega[i] + P.omega[j]);
  const double eps_rate = dv_dS.dot(frame.t) + omega * s.dx_dS[k].dot(frame.d);
  const double gamma_rate = dv_dS.dot(frame.d) - omega * s.dx_dS[k].dot(frame.t);
  const double kappa_rate = (P.omega[j] - P.omega[i]) / s.ds[k];
  const ShellSection& section = parameters.section;
  const double t = section.thickness;
  const double N_d = parameters.damping.eta_normal * t * eps_rate;
  const double Q_d = kShearCorrection * parameters.damping.eta_shear * t * gamma_rate;
  const double M_d = parameters.damping.eta_normal * t * t * t / 12.0 * kappa_rate;
  r.N += N_d;
  r.Q += Q_d;
  r.M += M_d;
  r.n += N_d * frame.t + Q_d * frame.d;
  r.couple = cross(s.dx_dS[k], r.n);
}

}  // namespace

void compute_strains(ShellParticles& P, const ShellForceParameters& parameters) {
  ShellStressPoints& s = P.stress;
  for (std::size_t k = 0; k < s.size(); ++k) {
    const std::size_t i = static_cast<std::size_t>(s.i[k]), j = i + 1;
    s.dx_dS[k] = (P.x[j] - P.x[i]) / s.ds[k];
    s.kappa[k] = (P.theta[j] - P.theta[i]) / s.ds[k];
    const double phi = s.phi0[k] + 0.5 * (P.theta[i] + P.theta[j]);
    BeamResultants r = beam_resultants(s.dx_dS[k], phi, s.kappa[k], parameters.section);
    if (parameters.damping.any()) add_damping(P, k, phi, parameters, r);
    s.N[k] = r.N;
    s.Q[k] = r.Q;
    s.M[k] = r.M;
    s.n[k] = r.n;
    s.couple[k] = r.couple;
    s.strain_energy[k] = r.strain_energy;
  }
  // The particles' resultants (for the faces, the gauges and the snapshots).
  std::vector<int> count(P.size(), 0);
  std::fill(P.N.begin(), P.N.end(), 0.0);
  std::fill(P.Q.begin(), P.Q.end(), 0.0);
  std::fill(P.M.begin(), P.M.end(), 0.0);
  for (std::size_t k = 0; k < s.size(); ++k) {
    const std::size_t i = static_cast<std::size_t>(s.i[k]);
    for (const std::size_t p : {i, i + 1}) {
      P.N[p] += s.N[k];
      P.Q[p] += s.Q[k];
      P.M[p] += s.M[k];
      ++count[p];
    }
  }
  for (std::size_t p = 0; p < P.size(); ++p)
    if (count[p] > 1) {
      P.N[p] /= count[p];
      P.Q[p] /= count[p];
      P.M[p] /= count[p];
    }
}

void compute_accelerations(ShellParticles& P) {
  const ShellStressPoints& s = P.stress;
  const std::size_t n = P.size();
  std::vector<Vec2> force(n, Vec2::Zero());
  std::vector<double> moment(n, 0.0);
  for (std::size_t k = 0; k < s.size(); ++k) {
    const std::size_t i = static_cast<std::size_t>(s.i[k]), j = i + 1;
    const double turning = 0.5 * s.ds[k] * s.couple[k];
    force[i] += s.n[k];
    force[j] -= s.n[k];
    moment[i] += s.M[k] + turning;
    moment[j] += -s.M[k] + turning;
  }
  for (std::size_t i = 0; i < n; ++i) {
    P.a[i] = P.clamped[i] ? Vec2::Zero() : Vec2(force[i] / P.m[i]);
    P.alpha[i] = P.clamped[i] ? 0.0 : moment[i] / P.J[i];
  }
}

}  // namespace cosph::solid::shell
