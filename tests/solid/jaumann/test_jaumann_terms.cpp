// Analytic tests of the solid's physical terms, one per header.
#include <gtest/gtest.h>

#include <cmath>

#include "artificial_stress.hpp"
#include "bending_mode.hpp"
#include "hooke_pressure.hpp"
#include "jaumann_rate.hpp"
#include "sphcore/von_mises.hpp"
#include "von_mises_failure.hpp"

namespace cosph::solid::jaumann {
namespace {

Mat2 rotation(double angle) {
  Mat2 Q;
  Q << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  return Q;
}

// A body turning rigidly at rate Omega: v = Omega (-y, x), so the stress must
// turn with it, s(t) = Q(Omega t) s0 Q^T, and keep its size.
TEST(JaumannRate, RigidRotationRotatesTheStressWithoutGrowingIt) {
  const double G = 1e6, Omega = 2.0, angle = 0.6;
  Mat2 grad_v;
  grad_v << 0.0, -Omega, Omega, 0.0;
  Mat2 s0;
  s0 << 1.0e3, 2.0e2, 2.0e2, -5.0e2;
  Mat2 s = s0;
  const int steps = 2000;
  const double dt = angle / Omega / steps;
  for (int k = 0; k < steps; ++k) {  // midpoint rule
    const Mat2 s_half = s + 0.5 * dt * jaumann_rate(G, s, grad_v);
    s += dt * jaumann_rate(G, s_half, grad_v);
  }
  const Mat2 expected = rotation(angle) * s0 * rotation(angle).transpose();
  EXPECT_LT((s - expected).norm(), 1e-6 * s0.norm());
  EXPECT_NEAR(s.norm(), s0.norm(), 1e-6 * s0.norm());
  // Turning the other way would give a different tensor: the test sees the sign.
  const Mat2 wrong_way = rotation(-angle) * s0 * rotation(-angle).transpose();
  EXPECT_GT((s - wrong_way).norm(), 0.1 * s0.norm());
}

// The by-components form against the matrix form of docs/physics.md,
// "Jaumann solid",
//   2G (e - (1/3) tr(e) I) + s w^T + w s,
// for a velocity gradient and a stress with no symmetry to hide an index.
TEST(JaumannRate, ByComponentsIsTheMatrixForm) {
  const double G = 3.0e6;
  Mat2 grad_v, s;
  grad_v << 0.7, -1.9, 0.4, -0.2;
  s << 2.0e3, -3.0e2, 5.0e2, -1.5e3;
  const Mat2 e = 0.5 * (grad_v + grad_v.transpose()), w = 0.5 * (grad_v - grad_v.transpose());
  const Mat2 expected =
      2.0 * G * (e - e.trace() / 3.0 * Mat2::Identity()) + s * w.transpose() + w * s;
  EXPECT_LT((jaumann_rate(G, s, grad_v) - expected).norm(), 1e-14 * expected.norm());
}

// Uniaxial strain eps along x (e_yy = 0), loaded slowly through the rates:
// sigma_xx = (K + 4G/3) eps, sigma_yy = (K - 2G/3) eps, sigma_xy = 0.
TEST(HookeAndJaumann, UniaxialStrainGivesTheLongitudinalAndLateralModuli) {
  const double E = 2.0e6, nu = 0.3975, rho0 = 1000.0;
  const double K = bulk_modulus(E, nu), G = shear_modulus(E, nu);
  const double eps = 1e-5, rate = 1.0;
  Mat2 grad_v;
  grad_v << rate, 0.0, 0.0, 0.0;
  const int steps = 1000;
  const double dt = eps / rate / steps;
  double rho = rho0;
  Mat2 s = Mat2::Zero();
  for (int k = 0; k < steps; ++k) {
    rho += dt * -rho * grad_v.trace();  // continuity, drho/dt = -rho div v
    s += dt * jaumann_rate(G, s, grad_v);
  }
  const Mat2 sigma = -hooke_pressure(K, rho, rho0) * Mat2::Identity() + s;
  EXPECT_NEAR(sigma(0, 0), (K + 4.0 * G / 3.0) * eps, 1e-4 * K * eps);
  EXPECT_NEAR(sigma(1, 1), (K - 2.0 * G / 3.0) * eps, 1e-4 * K * eps);
  EXPECT_NEAR(sigma(0, 1), 0.0, 1e-12 * K * eps);
}

TEST(HookePressure, ModuliOfTheOscillatingPlate) {
  const double K = bulk_modulus(2.0e6, 0.3975), G = shear_modulus(2.0e6, 0.3975);
  EXPECT_NEAR(K, 2.0e6 / (3.0 * 0.205), 1e-6 * K);
  EXPECT_NEAR(G, 2.0e6 / 2.795, 1e-6 * G);
  EXPECT_GT(hooke_pressure(K, 1001.0, 1000.0), 0.0);  // compression: positive pressure
  EXPECT_NEAR(longitudinal_sound_speed(K, G, 1000.0), 64.85, 0.01);
}

TEST(VonMises, KnownTensors) {
  const double sigma = 3.0e5, tau = 1.0e5;
  Mat2 uniaxial, shear, biaxial;
  uniaxial << sigma, 0.0, 0.0, 0.0;
  shear << 0.0, tau, tau, 0.0;
  biaxial << sigma, 0.0, 0.0, -sigma;
  EXPECT_NEAR(sph::von_mises(uniaxial), sigma, 1e-9 * sigma);
  EXPECT_NEAR(sph::von_mises(shear), std::sqrt(3.0) * tau, 1e-9 * tau);
  EXPECT_NEAR(sph::von_mises(biaxial), std::sqrt(3.0) * sigma, 1e-9 * sigma);
  EXPECT_TRUE(yields(uniaxial, sigma));
  EXPECT_FALSE(yields(uniaxial, 1.01 * sigma));
}

TEST(VonMisesFailure, FailedParticleCarriesCompressionOnly) {
  EXPECT_EQ(failed_stress(-2.0e4), Mat2::Zero());              // tension: nothing
  EXPECT_EQ(failed_stress(3.0e4), -3.0e4 * Mat2::Identity());  // compression: its pressure
}

TEST(ArtificialStress, ActsOnlyOnTensilePrincipalStresses) {
  const double rho = 1000.0, epsilon = 0.3, angle = 0.4;
  const Mat2 Q = rotation(angle);
  const Mat2 sigma = Q * Eigen::Vector2d(2.0e4, -5.0e4).asDiagonal() * Q.transpose();
  const Mat2 R = artificial_stress(sigma, rho, epsilon);
  const Mat2 expected =
      Q * Eigen::Vector2d(-epsilon * 2.0e4 / (rho * rho), 0.0).asDiagonal() * Q.transpose();
  EXPECT_LT((R - expected).norm(), 1e-12 * expected.norm());
  EXPECT_EQ(artificial_stress(-1e4 * Mat2::Identity(), rho, epsilon), Mat2::Zero());
  EXPECT_LT((artificial_stress(1e4 * Mat2::Identity(), rho, epsilon) +
             epsilon * 1e4 / (rho * rho) * Mat2::Identity())
                .norm(),
            1e-15);
}

TEST(BendingMode, ClampedAtTheRootAndTheoreticalPeriod) {
  const double L = 0.2;
  EXPECT_NEAR(cantilever_mode_shape(0.0, L), 0.0, 1e-12);
  const double slope = (cantilever_mode_shape(1e-6, L) - cantilever_mode_shape(0.0, L)) / 1e-6;
  EXPECT_NEAR(slope, 0.0, 1e-4);
  EXPECT_NEAR(cantilever_mode_shape(L, L), 2.0, 1e-3);  // the usual normalisation
  // A free end: no bending moment (f'' = 0) and no shear force (f''' = 0),
  // small against the root's curvature f''(0) = 2 k^2 and its k f''(0).
  const double k = kFirstModeKL / L, d = 1e-3 * L;
  auto f = [&](double s) { return cantilever_mode_shape(s, L); };
  const double second = (f(L) - 2.0 * f(L - d) + f(L - 2.0 * d)) / (d * d);
  const double third =
      (f(L) - 3.0 * f(L - d) + 3.0 * f(L - 2.0 * d) - f(L - 3.0 * d)) / (d * d * d);
  EXPECT_LT(std::abs(second), 0.02 * 2.0 * k * k) << second;
  EXPECT_LT(std::abs(third), 0.02 * 2.0 * k * k * k) << third;
  // The period of the oscillating plate, T = 2 pi / omega = 0.254 s.
  const double omega = cantilever_angular_frequency(2.0e6, 0.3975, 1000.0, 0.02, L);
  EXPECT_NEAR(2.0 * M_PI / omega, 0.2537, 0.0005);
}

}  // namespace
}  // namespace cosph::solid::jaumann
