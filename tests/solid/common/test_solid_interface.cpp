// The solids' half of the exchange with the coupler: which particles are
// sent, and where the coupler's answers, given in the order sent, land.
#include <gtest/gtest.h>

#include <vector>

#include "jaumann_particles.hpp"
#include "solid_interface.hpp"
#include "sphcore/region.hpp"

namespace cosph::solid {
namespace {

// A row of particles at x = 0, 1, ..., n - 1 m, each with its own id, mass,
// density and stress, so that a particle sent in the wrong place shows.
jaumann::JaumannParticles row_of(int n) {
  jaumann::JaumannParticles P;
  for (int i = 0; i < n; ++i)
    P.add(100 + i, Vec2(i, 0.0), 1000.0 + i, 1.0 + i, 1e6, 1e5, 50.0 + i, /*is_clamped=*/i == 0);
  P.resize_derived();
  for (int i = 0; i < n; ++i) {
    P.v[i] = Vec2(0.1 * i, -0.1 * i);
    P.sigma[i] << i, 2.0 * i, 3.0 * i, 4.0 * i;
  }
  return P;
}

TEST(SolidInterface, SendsTheParticlesInsideTheRegionClampedOnesToo) {
  const jaumann::JaumannParticles P = row_of(6);
  SolidInterface link;
  sph::InterfaceParticles out;
  link.collect(P, 0.5, sph::Region{Vec2(-0.5, -1.0), Vec2(2.5, 1.0)}, out);
  ASSERT_EQ(out.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(out.id[k], 100 + k);
    EXPECT_EQ(out.x[k], P.x[k]);
    EXPECT_EQ(out.v[k], P.v[k]);
    EXPECT_EQ(out.sigma[k], P.sigma[k]);
    EXPECT_EQ(out.m[k], P.m[k]);
    EXPECT_EQ(out.rho[k], P.rho[k]);
    EXPECT_EQ(out.h[k], 0.5);
    EXPECT_EQ(out.c[k], P.c[k]);
  }
}

// Fracture and motion change the set sent from one exchange to the next: the
// answers follow the last one, and a particle no longer sent feels nothing.
TEST(SolidInterface, AnswersLandOnTheParticlesOfTheLastCollect) {
  const jaumann::JaumannParticles P = row_of(6);
  SolidInterface link;
  sph::InterfaceParticles out;
  std::vector<Vec2> external_a(P.size(), Vec2::Zero());
  link.collect(P, 0.5, sph::Region{Vec2(-0.5, -1.0), Vec2(2.5, 1.0)}, out);
  link.scatter({Vec2(1, 0), Vec2(2, 0), Vec2(3, 0)}, external_a);
  link.collect(P, 0.5, sph::Region{Vec2(2.5, -1.0), Vec2(4.5, 1.0)}, out);
  ASSERT_EQ(out.size(), 2u);
  link.scatter({Vec2(0, 7), Vec2(0, 8)}, external_a);
  const std::vector<Vec2> expected{Vec2::Zero(), Vec2::Zero(), Vec2::Zero(),
                                   Vec2(0, 7),   Vec2(0, 8),   Vec2::Zero()};
  for (std::size_t i = 0; i < P.size(); ++i)
    EXPECT_EQ(external_a[i], expected[i]) << "particle " << i;
}

}  // namespace
}  // namespace cosph::solid
