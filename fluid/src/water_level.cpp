#include "water_level.hpp"

#include <algorithm>
#include <cmath>

#include "sphcore/kernel.hpp"

namespace cosph::fluid {

std::optional<double> water_level(const FluidParticles& P, double x, double h, double dx) {
  const double reach = sph::kernel::kSupport * h;
  std::vector<Vec2> near;
  std::vector<double> volume;
  double top = -INFINITY, bottom = INFINITY;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (!P.is_water(i) || std::abs(P.x[i].x() - x) >= reach) continue;
    near.push_back(P.x[i]);
    volume.push_back(P.m[i] / P.rho[i]);
    top = std::max(top, P.x[i].y());
    bottom = std::min(bottom, P.x[i].y());
  }
  if (near.empty()) return std::nullopt;
  const sph::kernel::Value W(h);
  const auto fraction = [&](double y) {
    double c = 0.0;
    for (std::size_t j = 0; j < near.size(); ++j) c += volume[j] * W((Vec2(x, y) - near[j]).norm());
    return c;
  };
  // Steps of dx / 4 cannot step over a layer of water one spacing thick.
  const double step = 0.25 * dx;
  double above = top + reach;  // c = 0 here
  for (double y = above - step; y > bottom - reach; above = y, y -= step) {
    if (fraction(y) < 0.5) continue;
    double below = y;  // c(below) >= 1/2 > c(above)
    for (int k = 0; k < 30; ++k) {
      const double middle = 0.5 * (above + below);
      (fraction(middle) >= 0.5 ? below : above) = middle;
    }
    return 0.5 * (above + below);
  }
  return top + 0.5 * dx;
}

}  // namespace cosph::fluid
