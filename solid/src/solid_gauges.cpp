#include "solid_gauges.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sphcore/pair_terms.hpp"

namespace cosph::solid {

std::vector<int> tip_gauge_ids(const SolidParticles& P, const sph::Vec2& p, double dx) {
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < P.size(); ++i) nearest = std::min(nearest, (P.x0[i] - p).norm());
  std::vector<int> ids;
  for (std::size_t i = 0; i < P.size(); ++i)
    if ((P.x0[i] - p).norm() <= nearest + 1e-6 * dx) ids.push_back(P.id[i]);
  std::sort(ids.begin(), ids.end());
  return ids;
}

SolidGauges measure(const SolidParticles& P, const std::vector<int>& tip_ids) {
  SolidGauges g{0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0};
  Vec2 tip = Vec2::Zero();
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (std::binary_search(tip_ids.begin(), tip_ids.end(), P.id[i])) tip += P.x[i] - P.x0[i];
    const double speed2 = P.v[i].squaredNorm();
    g.kinetic_energy += 0.5 * P.m[i] * speed2;
    g.max_speed = std::max(g.max_speed, speed2);
    // Strain energy density P^2/(2K) + s:s/(4G), with the out-of-plane
    // deviator s_zz = -(s_xx + s_yy) of plane strain.
    const double V = P.m[i] / P.rho[i];
    const double trace = P.s[i].trace();
    g.elastic_energy += V * (P.p[i] * P.p[i] / (2.0 * P.K[i]) +
                             (P.s[i].squaredNorm() + trace * trace) / (4.0 * P.G[i]));
    g.max_von_mises = std::max(g.max_von_mises, sph::von_mises(P.sigma[i]));
    g.failed += P.failed[i];
  }
  if (!tip_ids.empty()) tip /= static_cast<double>(tip_ids.size());
  g.tip_dx = tip.x();
  g.tip_dy = tip.y();
  g.max_speed = std::sqrt(g.max_speed);
  return g;
}

}  // namespace cosph::solid
