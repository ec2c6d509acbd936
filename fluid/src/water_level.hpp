// The water level on a vertical line, for the level gauges of timeseries.csv
// (proto/case.proto, Gauges.level_probes).
//
// The free surface is where the water's kernel-summed volume fraction
//   c(p) = sum_j V_j W(|p - x_j|, h),  V_j = m_j / rho_j,
// falls to 1/2: about 1 inside the water, 1/2 on a flat surface, 0 outside
// (the rule of DualSPHysics' GaugeSWL). The level is the highest point of the
// line x = const where c reaches 1/2, found by stepping down from above the
// highest water within 2h of the line and bisecting the last step. Walls are
// not in the sum: a probe within 2h of a wall reads low there.
#pragma once

#include <optional>

#include "fluid_particles.hpp"

namespace cosph::fluid {

// The height y of the surface on the line at x, or nothing when no water is
// within 2h of the line. A film too thin to reach c = 1/2 reads as its top
// particle's centre plus half a spacing, as the other water gauges do.
std::optional<double> water_level(const FluidParticles& particles, double x, double h, double dx);

}  // namespace cosph::fluid
