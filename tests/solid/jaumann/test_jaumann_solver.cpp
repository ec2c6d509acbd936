// The solid solver alone: its neighbour passes on an analytic velocity field,
// failure, the oscillating plate's period (short mode), a result that does not
// depend on the thread count, and a runaway run.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

#include "bending_mode.hpp"
#include "clamp_reach.hpp"
#include "jaumann_dynamics.hpp"
#include "jaumann_rate.hpp"
#include "jaumann_solver.hpp"
#include "momentum_pair.hpp"
#include "runaway_spoils.hpp"
#include "solid_test_cases.hpp"
#include "sphcore/kernel.hpp"
#include "sphcore/permutation.hpp"
#include "sphcore/renormalisation.hpp"
#include "thread_count.hpp"
#include "von_mises_failure.hpp"

namespace cosph::solid::jaumann {
namespace {

using testing::plate_case_path;

// The coarse plate (6 particles across) swings 9 % slower than thin-plate
// theory (measured; the error falls with resolution, see
// docs/results/oscillating_plate.md). The test guards against regressions
// beyond that, not the 3 % target: the linear-exact velocity gradient gives
// +15 % here, and fails it.
constexpr double kCoarsePeriodTolerance = 0.12;

// CFL 1 and a tip speed near the sound speed: the plate tears within 0.01 s.
const char* kRunawayOverrides =
    "--set solid.spacing=0.0033333333333333 --set run.cfl=1 --set run.end_time=0.05 "
    "--set solid.initial_velocity.tip_speed=60";

const char* kBlock = R"(
run { end_time: 0.01 }
solid {
  spacing: 0.01 density: 1000 youngs_modulus: 1e6 poisson_ratio: 0.3
  body { min { x: 0 y: 0 } max { x: 0.1 y: 0.06 } }
}
)";

// A linear velocity field v = A x: every particle, the surface and corners
// included, must see the gradient A (renormalisation makes it exact) and so
// the Jaumann rate of A.
TEST(SolidDynamics, LinearVelocityFieldGivesItsGradientEverywhere) {
  const sph::CaseFile case_file = sph::load_case(testing::write_case("block", kBlock));
  const SolidParameters par = read_solid_parameters(case_file);
  JaumannSolver solver(case_file, par);
  JaumannParticles P = solver.particles();
  sph::CellGrid grid;
  grid.build(P.x, 2.0 * par.h);
  sph::permute(grid.order(), P.id, P.x, P.v, P.rho, P.m, P.s, P.G);
  sph::CandidateList candidates;
  candidates.build(grid, P.x, 2.0 * par.h, [](long) { return true; });
  Mat2 A;
  A << 0.3, -1.1, 0.7, -0.2;
  for (std::size_t i = 0; i < P.size(); ++i) P.v[i] = A * P.x[i];
  compute_rates(P, candidates, par);
  const Mat2 expected = jaumann_rate(par.G, Mat2::Zero(), A);
  int corners = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    // At a corner a quarter-kernel is too sparse to invert reliably, and the
    // renormalisation falls back to the identity (sphcore/renormalisation.hpp).
    const bool corner =
        (P.x[i].x() < 0.01 || P.x[i].x() > 0.09) && (P.x[i].y() < 0.01 || P.x[i].y() > 0.05);
    if (corner) {
      ++corners;
      continue;
    }
    EXPECT_LT((P.ds[i] - expected).norm(), 1e-9 * expected.norm()) << "particle " << P.id[i];
  }
  EXPECT_EQ(corners, 4);
}

// With a tiny yield stress the plate fails at once; failed particles carry
// their pressure if compressed and nothing else.
TEST(JaumannSolver, FailedParticlesCarryCompressionOnly) {
  const sph::CaseFile case_file = sph::load_case(
      plate_case_path(), {"solid.fracture.enabled=true", "solid.fracture.yield_stress=200"});
  JaumannSolver solver(case_file, read_solid_parameters(case_file));
  for (int k = 0; k < 100; ++k) solver.step(solver.step_limits().smallest());
  const JaumannParticles& P = solver.particles();
  long failed = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (!P.failed[i]) continue;
    ++failed;
    EXPECT_EQ(P.s[i], Mat2::Zero());
    EXPECT_EQ(P.sigma[i], failed_stress(P.p[i]));
    EXPECT_LE(P.sigma[i].trace(), 0.0);
  }
  EXPECT_GT(failed, 0);
  EXPECT_EQ(failed, solver.gauges().failed);
}

// Short mode of scripts/validate_oscillating_plate.py: a coarse plate (6
// particles across) over one period.
TEST(OscillatingPlate, CoarsePeriodNearThinPlateTheory) {
  const sph::CaseFile case_file =
      sph::load_case(plate_case_path(), {"solid.spacing=0.0033333333333333", "run.end_time=0.3"});
  const SolidParameters par = read_solid_parameters(case_file);
  JaumannSolver solver(case_file, par);
  const double T = testing::tip_period_until(solver, par.run.end_time);
  const double T_theory = testing::thin_plate_period(par);
  EXPECT_NEAR(T / T_theory, 1.0, kCoarsePeriodTolerance) << "T = " << T << " s";
  EXPECT_GT(T, T_theory);  // SPH's truncated kernels at the surfaces make the plate softer
}

// The thread count changes nothing, to the last bit: each particle sums its
// own pairs in one order whatever thread owns it. On the plate at 1 mm (4 400
// particles), where the fluid's loops would take threads too.
TEST(JaumannSolver, ResultDoesNotDependOnTheThreadCount) {
  const sph::CaseFile case_file = sph::load_case(plate_case_path(), {"solid.spacing=0.001"});
  const SolidParameters par = read_solid_parameters(case_file);
  auto run = [&](int threads) {
    return cosph::testing::particles_after_steps<JaumannSolver>(case_file, par, threads, 100);
  };
  const JaumannParticles one = run(1), two = run(2);
  cosph::testing::expect_same_particles(one, two, &JaumannParticles::x, &JaumannParticles::v,
                                        &JaumannParticles::rho, &JaumannParticles::s);
  EXPECT_TRUE(std::any_of(one.v.begin(), one.v.end(),
                          [](const Vec2& v) { return v.norm() > 0.1; }));  // it swings
}

// The usual exponent of the artificial stress, n = 4, has a pass of its own
// (f^4 by two products): it agrees with the general one (std::pow) at an
// exponent next to 4, and another exponent changes the forces.
TEST(SolidDynamics, ArtificialStressExponentFourAgreesWithThePowerLaw) {
  const auto accelerations = [](const std::string& exponent) {
    const sph::CaseFile case_file = sph::load_case(
        plate_case_path(), {"solid.spacing=0.002", "solid.artificial_stress.exponent=" + exponent});
    JaumannSolver solver(case_file, read_solid_parameters(case_file));
    for (int step = 0; step < 50; ++step) solver.step(solver.step_limits().smallest());
    return solver.particles().a;
  };
  const auto largest_difference = [](const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
    double largest = 0.0, scale = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      largest = std::max(largest, (a[i] - b[i]).norm());
      scale = std::max(scale, a[i].norm());
    }
    return largest / scale;
  };
  const std::vector<Vec2> fourth = accelerations("4");
  EXPECT_LT(largest_difference(fourth, accelerations("4.000000001")), 1e-8);
  EXPECT_GT(largest_difference(fourth, accelerations("2")), 1e-3);
}

// The momentum pass works each pair out once and gives j the opposite of i's
// share: momentum is conserved only if the bracket is the same from either
// side of the pair. In a bending plate, with tension and so artificial stress
// at work, each listed pair's term from j's side is minus that from i's.
TEST(SolidDynamics, MomentumBracketIsTheSameFromEitherSideOfAPair) {
  const sph::CaseFile case_file = sph::load_case(plate_case_path(), {"solid.spacing=0.002"});
  JaumannSolver solver(case_file, read_solid_parameters(case_file));
  for (int step = 0; step < 50; ++step) solver.step(solver.step_limits().smallest());
  const JaumannParticles& P = solver.particles();
  const MomentumPair<ArtificialStressTerm::fourth_power> bracket(P, solver.parameters());
  double largest_sum = 0.0, largest_term = 0.0;
  int pairs_with_artificial_stress = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    for (const Neighbour& ij : P.neighbours[i]) {
      const Neighbour ji{static_cast<int>(i), ij.W_ij, -ij.grad_W_ij};
      const Vec2 from_i = bracket(PairSide(P, static_cast<long>(i)), ij);
      const Vec2 from_j = bracket(PairSide(P, ij.j), ji);
      largest_sum = std::max(largest_sum, (from_i + from_j).norm());
      largest_term = std::max(largest_term, from_i.norm());
      if (P.R[i].norm() + P.R[ij.j].norm() > 0.0) ++pairs_with_artificial_stress;
    }
  }
  EXPECT_GT(pairs_with_artificial_stress, 0);
  EXPECT_LT(largest_sum, 1e-12 * largest_term);
}

// A block 40 mm above a clamped one, beyond the kernel's reach; the clamped
// block's lower rows are out of every free particle's reach (inert).
const char* kBlockAboveClampedBlock = R"(
run { gravity { x: 0 y: -9.81 } end_time: 1 }
solid {
  spacing: 0.01 density: 1000 youngs_modulus: 1e6 poisson_ratio: 0.3
  body { min { x: 0 y: 0.04 } max { x: 0.1 y: 0.08 } }
  body { min { x: -0.05 y: -0.06 } max { x: 0.15 y: 0 } }
  clamp { min { x: -0.05 y: -0.06 } max { x: 0.15 y: 0 } }
}
)";

// The Verlet list (sph::kSkinOverH) is rebuilt only when a particle has moved
// about skin / 2. A block 40 mm above a clamped one, beyond the kernel's reach,
// falls many skins towards it and meets particles it was not listed with: at every step each
// particle must still have exactly the neighbours a search of all pairs finds.
TEST(JaumannSolver, NeighboursStayCompleteAsABlockFallsOntoAnother) {
  const sph::CaseFile case_file =
      sph::load_case(testing::write_case("verlet", kBlockAboveClampedBlock));
  JaumannSolver solver(case_file, read_solid_parameters(case_file));
  const double support = 2.0 * solver.parameters().h,
               skin = sph::kSkinOverH * solver.parameters().h;
  const double start_y = testing::lowest_y(solver.particles(), 0.0);
  int steps = 0;
  while (solver.time() < 0.08) {
    solver.step(solver.step_limits().smallest());
    const JaumannParticles& P = solver.particles();
    for (std::size_t i = 0; i < P.size(); ++i) {
      if (P.inert[i]) continue;  // out of every free particle's reach: no list
      // Each pair is listed once, by its lower index, but for a pair of two
      // clamped particles, which moves neither.
      std::vector<int> listed, all;
      for (const Neighbour& neighbour : P.neighbours[i]) listed.push_back(neighbour.j);
      for (std::size_t j = i + 1; j < P.size(); ++j)
        if ((P.x[i] - P.x[j]).norm() < support && !(P.clamped[i] && P.clamped[j]))
          all.push_back(static_cast<int>(j));
      std::sort(listed.begin(), listed.end());
      ASSERT_EQ(listed, all) << "particle " << P.id[i] << " at step " << steps;
    }
    ++steps;
  }
  // The falling block came many skins closer to the clamped one.
  EXPECT_LT(testing::lowest_y(solver.particles(), 0.0), start_y - 4.0 * skin);
}

// The rates pass works each pair out once and lists the later half; an inert
// clamped particle has no list, and a particle after it takes their pair for
// itself. Every particle's renormalisation matrix must still be that of all
// its neighbours within 2h, the clamped block's too, where inert particles
// border active ones.
TEST(JaumannSolver, RenormalisationSumsOverEveryNeighbourInertOnesIncluded) {
  const sph::CaseFile case_file =
      sph::load_case(testing::write_case("halves", kBlockAboveClampedBlock));
  JaumannSolver solver(case_file, read_solid_parameters(case_file));
  for (int step = 0; step < 3; ++step) solver.step(solver.step_limits().smallest());
  const JaumannParticles& P = solver.particles();
  const double h = solver.parameters().h, support = 2.0 * h;
  const sph::kernel::GradientFactor gradient_factor(h);
  int inert = 0, bordering_inert = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.inert[i]) {
      ++inert;
      continue;
    }
    Mat2 M = Mat2::Zero();
    bool borders_inert = false;
    for (std::size_t j = 0; j < P.size(); ++j) {
      const Vec2 x_ij = P.x[i] - P.x[j];
      const double r = x_ij.norm();
      if (j == i || r >= support) continue;
      M += sph::renormalisation_term(P.volume[j], gradient_factor(r) * x_ij, x_ij);
      borders_inert = borders_inert || P.inert[j];
    }
    bordering_inert += borders_inert;
    const Mat2 L = sph::renormalisation_matrix(M);
    ASSERT_LT((L - P.L[i]).norm(), 1e-9 * L.norm()) << "particle " << P.id[i];
  }
  // The case has what the test is about.
  EXPECT_GT(inert, 0);
  EXPECT_GT(bordering_inert, 0);
}

// A plate flung at a large fraction of its sound speed blows up; cosph-solid-jaumann
// must stop with a clear error (exit 1) and keep the last good state.
TEST(CosphSolid, RunawayStopsWithLastGoodSnapshot) {
  const std::string out = testing::temporary_path("runaway");
  std::filesystem::remove_all(out);
  const std::string err = testing::temporary_path("runaway_stderr.txt");
  const std::string command = std::string(COSPH_BIN_DIR) + "/cosph-solid-jaumann --case " +
                              plate_case_path() + " --out " + out + " " + kRunawayOverrides +
                              " > /dev/null 2> " + err;
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
  std::stringstream message;
  message << std::ifstream(err).rdbuf();
  EXPECT_NE(message.str().find("blown up"), std::string::npos) << message.str();
  EXPECT_NE(message.str().find("last_good"), std::string::npos) << message.str();
  EXPECT_TRUE(std::filesystem::exists(out + "/solid_last_good.h5"));
}

// Every way a particle can run away stops the step; a speed between the
// screen's margin and the sound speed does not.
TEST(JaumannSolver, EveryKindOfRunawayStopsTheStepAndNothingElseDoes) {
  const sph::CaseFile case_file = sph::load_case(testing::write_case("block", kBlock));
  const SolidParameters par = read_solid_parameters(case_file);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  using Spoil = cosph::testing::Spoil<JaumannParticles>;
  const std::vector<Spoil> spoils{
      {"x not finite", [&](JaumannParticles& P, std::size_t i) { P.x[i].y() = nan; }, true},
      {"v infinite",
       [](JaumannParticles& P, std::size_t i) {
         P.v[i].x() = std::numeric_limits<double>::infinity();
       },
       true},
      {"s not finite", [&](JaumannParticles& P, std::size_t i) { P.s[i](1, 0) = nan; }, true},
      {"rho below 0.5 rho0",
       [&](JaumannParticles& P, std::size_t i) { P.rho[i] = 0.49 * par.rho0; }, true},
      {"rho above 2 rho0", [&](JaumannParticles& P, std::size_t i) { P.rho[i] = 2.01 * par.rho0; },
       true},
      {"faster than c",
       [](JaumannParticles& P, std::size_t i) { P.v[i] = Vec2(0.6, 0.8) * 1.001 * P.c[i]; }, true},
      {"just below c",
       [](JaumannParticles& P, std::size_t i) { P.v[i] = Vec2(0.6, 0.8) * 0.995 * P.c[i]; }, false},
  };
  const auto make_solver = [&] { return JaumannSolver(case_file, par); };
  const std::size_t n = make_solver().particles().size();
  cosph::testing::expect_exactly_the_runaways_stop(make_solver, spoils, {0, n / 2, n - 1});
}

// A plate hanging from a clamp 100 mm deep, pushed sideways: 4 particles
// across at 5 mm (h = 6.5 mm, a support 13 mm), the clamp's 20 rows last in
// the cell order.
const char* kDeepClamp = R"(
run { end_time: 1 gravity { x: 100 y: 0 } }
solid {
  spacing: 0.005 density: 1000 youngs_modulus: 2e6 poisson_ratio: 0.3
  body { min { x: 0 y: 0 } max { x: 0.02 y: 0.16 } }
  clamp { min { x: 0 y: 0.06 } max { x: 0.02 y: 0.16 } }
  artificial_stress { enabled: true epsilon: 0.3 exponent: 4 }
}
)";

// The rates and the momentum pass over the particles Q as the solver takes
// them, on a neighbour search of their own: inert particles have no list, and
// those out of reach are no one's candidates. The stress is the one Q has.
void evaluate(JaumannParticles& Q, const SolidParameters& par) {
  const double range = (2.0 + sph::kSkinOverH) * par.h;
  sph::CellGrid grid;
  grid.build(Q.x, range);
  sph::permute(grid.order(), Q.id, Q.x, Q.v, Q.rho, Q.m, Q.s, Q.K, Q.G, Q.c, Q.clamped, Q.failed,
               Q.inert, Q.out_of_reach, Q.sigma, Q.R);
  Q.reach_end = reach_end(Q.out_of_reach);
  sph::CandidateList candidates;
  candidates.build(
      grid, Q.x, range, [&Q](long i) { return !Q.inert[i]; },
      [&Q](long i, int j) { return (j > i || Q.inert[j]) && !Q.out_of_reach[j]; });
  compute_rates(Q, candidates, par);
  for (std::size_t i = 0; i < in_reach(Q); ++i) Q.sigma_L[i] = sph::product_2x2(Q.sigma[i], Q.L[i]);
  compute_accelerations(Q, par);
}

// The clamped particles out of reach are those three supports or more from
// every free particle's start, inert ones (no rates) two supports or more, and
// the passes stop at the last particle in reach. A free particle's
// acceleration, and the rates wherever they are taken, are the same to
// round-off when every particle is searched and given rates: nothing the
// particles left out would compute reaches a free one.
TEST(JaumannSolver, ClampOutOfReachIsWhatTheReachRuleSaysAndChangesNoFreeParticle) {
  const sph::CaseFile case_file = sph::load_case(testing::write_case("deep_clamp", kDeepClamp));
  const SolidParameters par = read_solid_parameters(case_file);
  JaumannSolver solver(case_file, par);
  for (int k = 0; k < 300; ++k) solver.step(solver.step_limits().smallest());
  const JaumannParticles& P = solver.particles();
  const double support = 2.0 * par.h;
  long inert_in_reach = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    double nearest_free = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < P.size(); ++j)
      if (!P.clamped[j]) nearest_free = std::min(nearest_free, (P.x0[i] - P.x0[j]).norm());
    ASSERT_EQ(P.out_of_reach[i] != 0, P.clamped[i] && nearest_free >= 3.0 * support)
        << "particle " << P.id[i];
    ASSERT_EQ(P.inert[i] != 0, P.clamped[i] && nearest_free >= 2.0 * support)
        << "particle " << P.id[i];
    ASSERT_TRUE(i < in_reach(P) || P.out_of_reach[i]) << "particle " << P.id[i];
    inert_in_reach += P.inert[i] && !P.out_of_reach[i];
  }
  ASSERT_LT(in_reach(P), P.size());  // the case has particles no pass visits
  ASSERT_GT(inert_in_reach, 0);

  JaumannParticles some = P, all = P;
  std::fill(all.out_of_reach.begin(), all.out_of_reach.end(), 0);
  std::fill(all.inert.begin(), all.inert.end(), 0);
  evaluate(some, par);
  evaluate(all, par);
  double largest_a = 0.0, largest_ds = 0.0;
  for (std::size_t i = 0; i < all.size(); ++i) {
    largest_a = std::max(largest_a, all.a[i].norm());
    largest_ds = std::max(largest_ds, all.ds[i].norm());
  }
  ASSERT_GT(largest_a, 0.0);
  int free = 0, clamped_with_rates = 0;
  for (std::size_t i = 0; i < all.size(); ++i) {
    const auto k = std::find(some.id.begin(), some.id.end(), all.id[i]) - some.id.begin();
    if (!all.clamped[i]) {
      ASSERT_LT((some.a[k] - all.a[i]).norm(), 1e-12 * largest_a) << "particle " << all.id[i];
      ++free;
    }
    // Where rates are taken they see every neighbour they would with all visited.
    if (some.inert[k]) continue;
    ASSERT_LT((some.L[k] - all.L[i]).norm(), 1e-12 * all.L[i].norm()) << "particle " << all.id[i];
    ASSERT_LT((some.ds[k] - all.ds[i]).norm(), 1e-12 * largest_ds) << "particle " << all.id[i];
    clamped_with_rates += all.clamped[i];
  }
  EXPECT_GT(free, 0);
  EXPECT_GT(clamped_with_rates, 0);
}

}  // namespace
}  // namespace cosph::solid::jaumann
