// The reduced-dimension shell (solid/shell): the thin-box rule refuses a thick
// body, the section the water sees (geometry, and forces back as force and
// moment), no zero-energy mode, the Antoci plate's first-mode period at 8
// particles along, the elastica, and a plate clamped at both ends under its
// own weight (run.gravity) against Timoshenko's static deflection.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "bending_mode.hpp"
#include "shell_interface.hpp"
#include "shell_solver.hpp"
#include "solid_test_cases.hpp"

namespace cosph::solid::shell {
namespace {

constexpr double kL = 0.079, kT = 0.005;

// The Antoci plate in vacuum (cases/shell_plate.pbtxt), n particles along.
std::string plate_case(const std::string& name, int n, const std::string& extra = "") {
  const double dx = kL / n;
  return testing::write_case(name, R"(
run { end_time: 0.2 cfl: 0.3 gravity { x: 0 y: 0 } }
solid {
  model: "shell"
  spacing: )" + std::to_string(dx) + R"(
  density: 1100 youngs_modulus: 12.0e6 poisson_ratio: 0.4
  body { min { x: )" + std::to_string(-4 * dx) +
                                       R"( y: -0.0025 } max { x: 0.079 y: 0.0025 } }
  clamp { min { x: )" + std::to_string(-4 * dx) +
                                       R"( y: -0.0025 } max { x: 0 y: 0.0025 } }
  tip_gauge { x: 0.079 y: 0 }
)" + extra + "\n}\n");
}

ShellSolver solver_of(const std::string& path) {
  const sph::CaseFile case_file = sph::load_case(path);
  return ShellSolver(case_file, read_solid_parameters(case_file));
}

// The ConfigError message of building the shell of the case at `path`; a
// failure of the calling test, and "", if the case is taken.
std::string refusal_of(const std::string& path, const std::string& what) {
  try {
    solver_of(path);
  } catch (const sph::ConfigError& error) {
    return error.what();
  }
  ADD_FAILURE() << what << " was read as a shell";
  return "";
}

TEST(Shell, RefusesABodyThatIsNotThin) {
  const std::string path = testing::write_case("shell_thick", R"(
run { end_time: 0.1 }
solid {
  model: "shell" spacing: 0.001 density: 1000 youngs_modulus: 1e6 poisson_ratio: 0.3
  body { min { x: 0 y: 0 } max { x: 0.1 y: 0.03 } }
}
)");
  const std::string message = refusal_of(path, "a 0.1 x 0.03 m box at spacing 1 mm");
  EXPECT_NE(message.find("solid.body[0]"), std::string::npos) << message;
  EXPECT_NE(message.find("not a thin plate"), std::string::npos) << message;
  // Thin but stubby: thickness more than a quarter of the length.
  const std::string stubby = testing::write_case("shell_stubby", R"(
run { end_time: 0.1 }
solid {
  model: "shell" spacing: 0.01 density: 1000 youngs_modulus: 1e6 poisson_ratio: 0.3
  body { min { x: 0 y: 0 } max { x: 0.03 y: 0.01 } }
}
)");
  const std::string stubby_message = refusal_of(stubby, "a 0.03 x 0.01 m box");
  EXPECT_NE(stubby_message.find("not a thin plate"), std::string::npos) << stubby_message;
}

// The spacing is the mid-line's: a 5 mm plate at 0.5 mm, ten spacings across.
TEST(Shell, TakesASlenderPlateAtAnySpacingAlongIt) {
  const ShellSolver solver = solver_of(plate_case("shell_fine", 158));
  EXPECT_NEAR(solver.line().thickness, kT, 1e-12);
  EXPECT_EQ(solver.line().count, 158 + 4 + 1);
}

// At 48 particles along (dx = 1.65 mm) the 5 mm section holds three layers.
constexpr int kAlongForLayers = 48, kLayers = 3;

TEST(Shell, InterfaceFillsTheSectionAndMovesWithIt) {
  ShellSolver solver = solver_of(plate_case("shell_interface", kAlongForLayers));
  ShellParticles& P = solver.particles();
  ASSERT_EQ(ShellInterface::layers(solver.force_parameters().section, solver.parameters().dx),
            kLayers);
  const int i = 8;  // a free particle
  ASSERT_FALSE(P.clamped[i]);
  P.theta[i] = 0.7;
  P.omega[i] = 3.0;
  P.v[i] = Vec2(0.1, -0.2);
  solver.update();
  sph::InterfaceParticles out;
  solver.collect_interface(sph::Region::everything(), out);
  ASSERT_EQ(out.size(), kLayers * P.size());
  const Vec2 d(-std::sin(0.7), std::cos(0.7));  // the director, turned with the section
  double mass = 0.0, volume = 0.0;
  int seen = 0;
  for (std::size_t k = 0; k < out.size(); ++k) {
    if (out.id[k] / kLayers != P.id[i]) continue;
    ++seen;
    const int layer = static_cast<int>(out.id[k] % kLayers);
    // Half a layer inside the faces, a layer apart: -t/3, 0, t/3.
    const Vec2 r = (layer - 1) * (kT / 3.0) * d;
    EXPECT_LT((out.x[k] - (P.x[i] + r)).norm(), 1e-15);
    EXPECT_LT((out.v[k] - (P.v[i] + 3.0 * Vec2(-r.y(), r.x()))).norm(), 1e-14);
    mass += out.m[k];
    volume += out.m[k] / out.rho[k];
  }
  EXPECT_EQ(seen, kLayers);
  // Together the section: the particle's mass and the volume of its length of plate.
  EXPECT_NEAR(mass, P.m[i], 1e-15);
  EXPECT_NEAR(volume, P.V[i] * kT, 1e-15);
}

// Accelerations for a traction (Pa) on the outer layer of the +d side, of
// the -d side, or both.
std::vector<Vec2> tractions(const sph::InterfaceParticles& out, const ShellParticles& P,
                            const Vec2& on_plus, const Vec2& on_minus) {
  std::vector<Vec2> a(out.size(), Vec2::Zero());
  for (std::size_t k = 0; k < out.size(); ++k) {
    const std::size_t i = static_cast<std::size_t>(out.id[k] / kLayers);
    const long layer = out.id[k] % kLayers;
    if (layer == kLayers - 1) a[k] = on_plus * P.V[i] / out.m[k];  // force = traction x length
    if (layer == 0) a[k] = on_minus * P.V[i] / out.m[k];
  }
  return a;
}

TEST(Shell, InterfaceForcesReturnAsForceAndMoment) {
  ShellSolver solver = solver_of(plate_case("shell_interface_forces", kAlongForLayers));
  const ShellParticles& P = solver.particles();
  sph::InterfaceParticles out;
  solver.collect_interface(sph::Region::everything(), out);
  const double p = 250.0, tau = 40.0;  // Pa
  double length = 0.0;                 // of the whole line, clamp included, m
  for (const double V : P.V) length += V;
  const double z_outer = kT / 3.0;  // the outer layers' offset from the mid-line
  auto totals = [&](const std::vector<Vec2>& a) {
    solver.set_interface_accelerations(a);
    Vec2 F = Vec2::Zero();
    double M = 0.0, M_origin = 0.0;
    for (std::size_t i = 0; i < P.size(); ++i) {
      const Vec2 f = P.m[i] * P.external_a[i];
      F += f;
      M += P.J[i] * P.external_alpha[i];
      M_origin += P.J[i] * P.external_alpha[i] + (P.x[i].x() * f.y() - P.x[i].y() * f.x());
    }
    return std::tuple{F, M, M_origin};
  };
  // Pressure p on both sides (pushing in: -p on the +y side, +p on the -y side).
  auto [F, M, M0] = totals(tractions(out, P, Vec2(0, -p), Vec2(0, p)));
  EXPECT_LT(F.norm(), 1e-12);
  EXPECT_NEAR(M, 0.0, 1e-15);
  EXPECT_NEAR(M0, 0.0, 1e-12);
  // On the upper side only: force p L down, no moment about the mid-line, and
  // about the origin the moment of a uniform load on [x0, L].
  std::tie(F, M, M0) = totals(tractions(out, P, Vec2(0, -p), Vec2::Zero()));
  EXPECT_NEAR(F.y(), -p * length, 1e-9 * p * length);
  EXPECT_NEAR(F.x(), 0.0, 1e-12);
  EXPECT_NEAR(M, 0.0, 1e-15);
  const double x0 = kL - length;
  EXPECT_NEAR(M0, -p * 0.5 * (kL * kL - x0 * x0), 1e-9 * p * kL * kL);
  // A shear traction tau along +x on the upper layer turns the section
  // clockwise: moment -tau z per unit length, z the layer's offset.
  std::tie(F, M, M0) = totals(tractions(out, P, Vec2(tau, 0), Vec2::Zero()));
  EXPECT_NEAR(F.x(), tau * length, 1e-9 * tau * length);
  EXPECT_NEAR(M, -tau * z_outer * length, 1e-9 * tau * kT * length);
}

// A zigzag of the deflection, of the rotation or along the line costs strain
// energy (the stress points see it), while a rigid motion costs none.
TEST(Shell, ZigzagsCostEnergyRigidMotionsDoNot) {
  ShellSolver solver = solver_of(plate_case("shell_zigzag", 8));
  ShellParticles& P = solver.particles();
  const ShellParticles rest = P;
  auto energy = [&] {
    solver.update();
    double U = 0.0;
    for (std::size_t k = 0; k < P.stress.size(); ++k)
      U += P.stress.ds[k] * P.stress.strain_energy[k];
    return U;
  };
  const double u = 1e-4, angle = 0.3;  // m, rad
  const double ds = solver.line().ds, EI = solver.force_parameters().section.EI();
  auto zigzag = [&](std::size_t i) { return P.clamped[i] ? 0.0 : (i % 2 == 0 ? 1.0 : -1.0); };
  for (int field = 0; field < 3; ++field) {
    P = rest;
    for (std::size_t i = 0; i < P.size(); ++i) {
      if (field == 0) P.x[i].y() += u * zigzag(i);
      if (field == 1) P.theta[i] += u / ds * zigzag(i);
      if (field == 2) P.x[i].x() += u * zigzag(i);
    }
    // At least most of the bending energy of a curvature 2u/ds^2 over the free
    // length (the rotation's zigzag; the deflection's costs shear, more).
    const double least = 0.8 * 0.5 * EI * std::pow(2.0 * u / (ds * ds), 2) * kL;
    EXPECT_GT(energy(), least) << "zigzag " << field;
  }
  // A rigid rotation of the whole line, clamp included, about the origin.
  P = rest;
  const double c = std::cos(angle), s = std::sin(angle);
  for (std::size_t i = 0; i < P.size(); ++i) {
    P.x[i] = Vec2(c * P.X[i].x() - s * P.X[i].y(), s * P.X[i].x() + c * P.X[i].y());
    P.theta[i] = angle;
  }
  EXPECT_LT(energy(), 1e-20);
  // Round-off only: what an axial strain of 1e-12 would give.
  const ShellSection& section = solver.force_parameters().section;
  const double a_scale = 1e-12 * section.EA() / P.m[8];
  const double alpha_scale = 1e-12 * section.EA() * ds / P.J[8];
  for (std::size_t i = 0; i < P.size(); ++i) {
    EXPECT_LT(P.a[i].norm(), a_scale) << i;
    EXPECT_LT(std::abs(P.alpha[i]), alpha_scale) << i;
  }
}

// The damping (shell_damping.hpp): a zigzag velocity loses energy, a rigid
// motion does not; the shear-rotation mode at the section's cut-off decays
// with it and keeps its energy without; the Hello's report follows.
double total_energy(const ShellParticles& P) {
  double E = 0.0;
  for (std::size_t i = 0; i < P.size(); ++i)
    E += 0.5 * (P.m[i] * P.v[i].squaredNorm() + P.J[i] * P.omega[i] * P.omega[i]);
  for (std::size_t k = 0; k < P.stress.size(); ++k) E += P.stress.ds[k] * P.stress.strain_energy[k];
  return E;
}

double power_of_the_forces(const ShellParticles& P) {
  double power = 0.0;
  for (std::size_t i = 0; i < P.size(); ++i)
    power += P.m[i] * P.a[i].dot(P.v[i]) + P.J[i] * P.alpha[i] * P.omega[i];
  return power;
}

TEST(Shell, DampingTakesEnergyFromZigzagsNotFromRigidMotion) {
  ShellSolver solver = solver_of(plate_case("shell_damped", 8));
  EXPECT_FALSE(solver.undamped_modes());
  EXPECT_TRUE(solver_of(plate_case("shell_undamped", 8, "shell_damping: false")).undamped_modes());
  ShellParticles& P = solver.particles();
  const ShellParticles rest = P;
  const double v = 0.1, omega = 3.0;  // m/s, rad/s
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.clamped[i]) continue;
    P.v[i].y() = (i % 2 == 0 ? v : -v);
    P.omega[i] = (i % 2 == 0 ? omega : -omega);
  }
  solver.update();
  // At rest in shape: only the viscous forces act, and they take power.
  const ShellDamping& damping = solver.force_parameters().damping;
  const double ds = solver.line().ds;
  const double shear_rate = 2.0 * v / ds, curvature_rate = 2.0 * omega / ds;
  const double least_dissipation =  // the shear's and the bending's over the free length, halved
      0.5 * kL *
      (kShearCorrection * damping.eta_shear * kT * shear_rate * shear_rate +
       damping.eta_normal * kT * kT * kT / 12.0 * curvature_rate * curvature_rate);
  EXPECT_LT(power_of_the_forces(P), -least_dissipation);
  // A rigid rotation rate of the whole line (clamp included): no viscous force.
  P = rest;
  for (std::size_t i = 0; i < P.size(); ++i) {
    P.omega[i] = omega;
    P.v[i] = omega * Vec2(-P.x[i].y(), P.x[i].x());
  }
  solver.update();
  // N/m: round-off, of the elastic strains at rest (what an axial strain of
  // 1e-12 would give) and of the rates; a wrong rate of the order of omega
  // would give eta_n t omega, 12 N/m.
  const double scale =
      1e-12 * (solver.force_parameters().section.EA() + damping.eta_normal * kT * omega);
  for (std::size_t i = 0; i < P.size(); ++i) {
    EXPECT_LT(P.m[i] * P.a[i].norm(), scale) << i;
    EXPECT_LT(P.J[i] * std::abs(P.alpha[i]), scale * ds) << i;
  }
}

TEST(Shell, DampingStopsTheShearRotationMode) {
  for (const bool damped : {true, false}) {
    ShellSolver solver = solver_of(plate_case(damped ? "shell_sr_damped" : "shell_sr_undamped", 8,
                                              damped ? "" : "shell_damping: false"));
    ShellParticles& P = solver.particles();
    // The sections turned without the line bending: the rotation against the
    // shear, at the cut-off omega_r (shell_section.hpp).
    for (std::size_t i = 0; i < P.size(); ++i)
      if (!P.clamped[i]) P.theta[i] = 1e-3;
    solver.update();
    const double start = total_energy(P);
    const double period =
        2.0 * std::numbers::pi / solver.force_parameters().section.rotation_frequency();
    while (solver.time() < 10.0 * period) solver.step(solver.step_limits().smallest());
    const double ratio = total_energy(P) / start;
    // Damped: zeta about 0.4 at this spacing (h > t), exp(-2 zeta omega_r t) ~ 1e-21 after ten
    // periods; undamped, the symplectic steps keep it.
    if (damped)
      EXPECT_LT(ratio, 1e-3);
    else
      EXPECT_GT(ratio, 0.9);
  }
}

// The Hello's fastest mode (coupling.proto, fastest_mode_*): the shear-rotation
// cut-off and the damping ratio of the Kelvin-Voigt rule there, whose
// zeta / omega = eta_s / (2 G) is the least of the shell's (the normal
// rates' is eta_n / (2 E')); the coupler's window bound is 2 zeta / omega.
TEST(Shell, StatesItsFastestModeAndItsDamping) {
  const ShellSolver solver = solver_of(plate_case("shell_fastest", 32));
  const ShellSection& section = solver.force_parameters().section;
  const ShellDamping& damping = solver.force_parameters().damping;
  const auto mode = solver.fastest_mode();
  EXPECT_DOUBLE_EQ(mode.angular_frequency, section.rotation_frequency());
  const double per_frequency = mode.damping_ratio / mode.angular_frequency;
  EXPECT_NEAR(per_frequency / (damping.eta_shear / (2.0 * section.G)), 1.0, 1e-12);
  EXPECT_LT(per_frequency, damping.eta_normal / (2.0 * section.E_plane));
  EXPECT_GT(mode.damping_ratio, 0.0);
  const ShellSolver undamped =
      solver_of(plate_case("shell_fastest_undamped", 32, "shell_damping: false"));
  EXPECT_EQ(undamped.fastest_mode().damping_ratio, 0.0);
}

// First-mode period of the Antoci plate at 8 particles along the free length,
// against Euler-Bernoulli in plane strain (T = 0.0678 s): the issue's target
// is 1 % (docs/results/shell.md; the Timoshenko beam the shell converges to is
// 0.4 % longer).
constexpr double kPeriodTolerance = 0.01;

TEST(Shell, AntociPlatePeriodAtEightParticles) {
  ShellSolver solver = solver_of(
      plate_case("shell_period", 8, "initial_velocity { tip_speed: 1.1 root_x: 0 length: 0.079 }"));
  const double T =
      2.0 * std::numbers::pi / cantilever_angular_frequency(12.0e6, 0.4, 1100.0, kT, kL);
  std::vector<double> downward;  // times the tip crosses y = 0 going down
  double t_prev = 0.0, y_prev = 0.0;
  const std::size_t tip = solver.particles().size() - 1;
  while (solver.time() < 2.5 * T) {
    solver.step(solver.step_limits().smallest());
    const double y = solver.particles().x[tip].y();
    if (y_prev > 0.0 && y <= 0.0)
      downward.push_back(t_prev + (solver.time() - t_prev) * y_prev / (y_prev - y));
    t_prev = solver.time();
    y_prev = y;
  }
  ASSERT_GE(downward.size(), 2u);
  const double measured = downward[1] - downward[0];
  EXPECT_NEAR(measured / T - 1.0, 0.0, kPeriodTolerance) << "period " << measured << " s";
}

// The elastica of a cantilever under a dead end load P, L = 1: with psi the
// downward slope, psi'' = -alpha cos psi, psi(0) = 0, psi'(1) = 0 (no moment
// at the free end), alpha = P L^2 / EI. Shooting on psi'(0) in [0, alpha] with
// RK4; returns the tip's deflection / L and rotation (Bisshopp & Drucker 1945
// solve the same problem with elliptic integrals).
std::pair<double, double> elastica_tip(double alpha) {
  constexpr int kSteps = 2000;
  auto shoot = [&](double slope0, double& deflection) {
    // State (psi, psi', y); y' = sin psi.
    std::array<double, 3> y{0.0, slope0, 0.0};
    auto rhs = [&](const std::array<double, 3>& q) {
      return std::array<double, 3>{q[1], -alpha * std::cos(q[0]), std::sin(q[0])};
    };
    const double h = 1.0 / kSteps;
    for (int k = 0; k < kSteps; ++k) {
      auto add = [&](const std::array<double, 3>& a, const std::array<double, 3>& b, double f) {
        return std::array<double, 3>{a[0] + f * b[0], a[1] + f * b[1], a[2] + f * b[2]};
      };
      const auto k1 = rhs(y), k2 = rhs(add(y, k1, h / 2)), k3 = rhs(add(y, k2, h / 2)),
                 k4 = rhs(add(y, k3, h));
      for (int c = 0; c < 3; ++c) y[c] += h / 6 * (k1[c] + 2 * k2[c] + 2 * k3[c] + k4[c]);
    }
    deflection = y[2];
    return std::pair{y[1], y[0]};  // psi'(1), psi(1)
  };
  double low = 0.0, high = alpha, deflection = 0.0, rotation = 0.0;
  for (int k = 0; k < 60; ++k) {
    const double middle = 0.5 * (low + high);
    const auto [end_slope, end_angle] = shoot(middle, deflection);
    rotation = end_angle;
    (end_slope < 0.0 ? low : high) = middle;
  }
  return {deflection, rotation};
}

// The elastica at alpha = 2 (tip rotation 45 degrees), 8 particles along
// (cases/shell_elastica.pbtxt): the issue's target is 2 %.
TEST(Shell, CantileverUnderALargeEndLoadFollowsTheElastica) {
  const double L = 0.15, alpha = 2.0, end = 1.6, average = 0.5;  // m, -, s, s
  const double dx = L / 8;
  const sph::CaseFile case_file =
      sph::load_case(std::string(COSPH_SOURCE_DIR) + "/cases/shell_elastica.pbtxt");
  sph::CaseFile coarse = case_file;
  auto& solid = *coarse.config.mutable_solid();
  solid.set_spacing(dx);
  solid.mutable_body(0)->mutable_min()->set_x(-4 * dx);
  solid.mutable_clamp(0)->mutable_min()->set_x(-4 * dx);
  ShellSolver solver(coarse, read_solid_parameters(coarse));
  const double EI = solver.force_parameters().section.EI();
  solid.mutable_end_load()->mutable_force()->set_y(-alpha * EI / (L * L));
  solver = ShellSolver(coarse, read_solid_parameters(coarse));
  const std::size_t tip = solver.particles().size() - 1;
  double deflection = 0.0, rotation = 0.0, samples = 0.0;
  while (solver.time() < end) {
    const double dt = solver.step_limits().smallest();
    solver.step(dt);
    if (solver.time() < end - average) continue;
    deflection += dt * (solver.particles().X[tip].y() - solver.particles().x[tip].y());
    rotation += dt * -solver.particles().theta[tip];
    samples += dt;
  }
  const auto [exact_deflection, exact_rotation] = elastica_tip(alpha);
  EXPECT_NEAR(deflection / samples / L / exact_deflection, 1.0, 0.02);
  EXPECT_NEAR(rotation / samples / exact_rotation, 1.0, 0.02);
}

// The elastica case with its plate, clamp and end load turned by `angle` about
// the clamp's face, the plate given as a rectangle polygon at that angle and
// the clamp as another; run to `end`. Returns the free end's displacement and
// rotation, turned back by -angle.
std::pair<Vec2, double> turned_cantilever_tip(double angle, double end) {
  const double L = 0.15, dx = L / 8, half = 0.0025;
  sph::CaseFile c = sph::load_case(std::string(COSPH_SOURCE_DIR) + "/cases/shell_elastica.pbtxt");
  auto& solid = *c.config.mutable_solid();
  solid.set_spacing(dx);
  const Eigen::Rotation2Dd turn(angle);
  auto set_rectangle = [&](cosph::config::Region* region, double from, double to) {
    region->Clear();
    for (const Vec2& corner :
         {Vec2(from, -half), Vec2(to, -half), Vec2(to, half), Vec2(from, half)}) {
      const Vec2 turned = turn * corner;
      auto* point = region->mutable_polygon()->add_point();
      point->set_x(turned.x());
      point->set_y(turned.y());
    }
  };
  set_rectangle(solid.mutable_body(0), -4 * dx, L);
  // Past the clamp's face by a quarter spacing: a particle on a turned
  // polygon's edge is inside or not by round-off.
  set_rectangle(solid.mutable_clamp(0), -4 * dx, 0.25 * dx);
  const Vec2 load = turn * Vec2(0.0, -10.18);
  solid.mutable_end_load()->mutable_force()->set_x(load.x());
  solid.mutable_end_load()->mutable_force()->set_y(load.y());
  ShellSolver solver(c, read_solid_parameters(c));
  while (solver.time() < end) solver.step(solver.step_limits().smallest());
  const ShellParticles& P = solver.particles();
  // The free end: the line runs towards +x whichever end the clamp holds.
  const std::size_t tip = P.clamped.front() ? P.size() - 1 : 0;
  return {turn.inverse() * Vec2(P.x[tip] - P.X[tip]), P.theta[tip]};
}

// A plate need not lie along an axis: the same cantilever turned by 30 and
// by 120 degrees (given as rectangles) bends as the axis-aligned one does,
// turned, to round-off.
TEST(Shell, ATurnedPlateBendsAsTheAlignedOne) {
  const double end = 0.4;  // s: the load ramping up, the tip well bent
  const auto [aligned, aligned_theta] = turned_cantilever_tip(0.0, end);
  EXPECT_GT(aligned.norm(), 0.01);  // m: the plate has bent
  for (const double degrees : {30.0, 120.0}) {
    const auto [turned, turned_theta] =
        turned_cantilever_tip(degrees * std::numbers::pi / 180, end);
    EXPECT_LT((turned - aligned).norm(), 1e-6 * aligned.norm()) << degrees << " degrees";
    EXPECT_NEAR(turned_theta, aligned_theta, 1e-6 * std::abs(aligned_theta)) << degrees;
  }
}

// A polygon that is not a rectangle is refused, naming the field.
TEST(Shell, RefusesAPolygonThatIsNotARectangle) {
  const std::string path = testing::write_case("shell_skewed", R"(
run { end_time: 0.1 }
solid {
  model: "shell" spacing: 0.001 density: 1000 youngs_modulus: 1e6 poisson_ratio: 0.3
  body { polygon { point { x: 0 y: 0 } point { x: 0.1 y: 0 } point { x: 0.103 y: 0.005 }
                   point { x: 0 y: 0.005 } } }
}
)");
  const std::string message = refusal_of(path, "a trapezium");
  EXPECT_NE(message.find("solid.body[0].polygon"), std::string::npos) << message;
  EXPECT_NE(message.find("rectangle"), std::string::npos) << message;
}

// A quarter-circle cantilever: the plate runs straight along +x through its
// clamp to (0, 0), then bends up round the centre (0, R) to its free end at
// (R, R), given as a band of 256 chords. Its own resultants vanish at rest.
sph::CaseFile quarter_circle_case(double R, int along, const Vec2& load) {
  sph::CaseFile c = sph::load_case(std::string(COSPH_SOURCE_DIR) + "/cases/shell_elastica.pbtxt");
  auto& solid = *c.config.mutable_solid();
  const double ds = 0.5 * std::numbers::pi * R / along;
  solid.set_spacing(ds);
  auto* band = solid.mutable_body(0);
  band->Clear();
  auto add = [&](const Vec2& p) {
    auto* point = band->mutable_band()->add_point();
    point->set_x(p.x());
    point->set_y(p.y());
  };
  add(Vec2(-4 * ds, 0.0));
  for (int k = 0; k <= 256; ++k) {
    const double psi = 0.5 * std::numbers::pi * k / 256;
    add(Vec2(R * std::sin(psi), R * (1.0 - std::cos(psi))));
  }
  band->mutable_band()->set_thickness(kT);
  auto* clamp = solid.mutable_clamp(0);
  clamp->mutable_min()->set_x(-5 * ds);
  clamp->mutable_max()->set_x(0.25 * ds);
  solid.mutable_end_load()->mutable_force()->set_x(load.x());
  solid.mutable_end_load()->mutable_force()->set_y(load.y());
  return c;
}

// The free end's displacement under an end force F of the quarter circle
// above, clamped at psi = 0, by Castigliano's theorem on the strain energy
// of bending, stretching and shear (M^2 / EI + N^2 / EA + Q^2 / GA) / 2 along
// the arc: at the section psi, t = (cos psi, sin psi), n = (-sin psi, cos psi),
//   M = (R - R sin psi) F_y - R cos psi F_x,  N = F.t,  Q = F.n,
// and u = C F with C_ab = R int_0^(pi/2) (M_a M_b / EI + N_a N_b / EA +
// Q_a Q_b / GA) dpsi, M_a = dM / dF_a and so on:
//   C_xx = R (R^2 pi/4 / EI + pi/4 / EA + pi/4 / GA),
//   C_yy = R (R^2 (3 pi/4 - 2) / EI + pi/4 / EA + pi/4 / GA),
//   C_xy = R (-R^2 / 2 / EI + 1/2 / EA - 1/2 / GA).
// Thin curved-beam theory: its error is of order (t / R)^2.
Vec2 quarter_circle_deflection(double R, const ShellSection& section, const Vec2& F) {
  const double pi = std::numbers::pi, EI = section.EI(), EA = section.EA(), GA = section.GA();
  const double xx = R * (R * R * pi / 4 / EI + pi / 4 / EA + pi / 4 / GA);
  const double yy = R * (R * R * (3 * pi / 4 - 2) / EI + pi / 4 / EA + pi / 4 / GA);
  const double xy = R * (-R * R / 2 / EI + 0.5 / EA - 0.5 / GA);
  return {xx * F.x() + xy * F.y(), xy * F.x() + yy * F.y()};
}

// A curved plate at rest is unstrained: its stress points' reference
// tangents are its chords'.
TEST(Shell, ACurvedPlateAtRestIsUnstrained) {
  sph::CaseFile c = quarter_circle_case(0.1, 16, Vec2::Zero());
  c.config.mutable_solid()->clear_end_load();
  const ShellSolver solver(c, read_solid_parameters(c));
  const ShellParticles& P = solver.particles();
  ASSERT_EQ(P.size(), 16u + 4u + 1u);
  EXPECT_NEAR(P.X.back().x(), 0.1, 1e-6);  // the free end, on the arc
  EXPECT_NEAR(P.X.back().y(), 0.1, 1e-6);
  const ShellSection& section = solver.force_parameters().section;
  for (std::size_t k = 0; k < P.stress.size(); ++k) {
    EXPECT_LT(std::abs(P.stress.N[k]), 1e-9 * section.EA()) << k;
    EXPECT_LT(std::abs(P.stress.Q[k]), 1e-9 * section.GA()) << k;
    EXPECT_LT(std::abs(P.stress.M[k]), 1e-9 * section.EI()) << k;
  }
  // The directors are normal to the arc: at the free end, along -x.
  EXPECT_NEAR(std::cos(P.phi0.back() - std::numbers::pi / 2), 1.0, 1e-5);
}

// The water sees a curved plate's section where it is: on the arc, the
// interface particles lie across the thickness along the arc's normal, from
// R - t/2 + layer/2 to R + t/2 - layer/2 from the centre.
TEST(Shell, ACurvedPlateShowsTheWaterItsSection) {
  const double R = 0.1;
  const sph::CaseFile c = quarter_circle_case(R, 16, Vec2::Zero());
  ShellSolver solver(c, read_solid_parameters(c));
  sph::InterfaceParticles out;
  solver.collect_interface(sph::Region::everything(), out);
  const int layers =
      ShellInterface::layers(solver.force_parameters().section, solver.parameters().dx);
  ASSERT_GE(layers, 1);
  ASSERT_EQ(out.size(), static_cast<std::size_t>(layers) * solver.particles().size());
  const double layer = kT / layers;
  const Vec2 centre(0.0, R);
  int on_arc = 0;
  for (std::size_t k = 0; k < out.size(); ++k) {
    const std::size_t i = static_cast<std::size_t>(out.id[k] / layers);
    if (solver.particles().X[i].x() <= 0.0) continue;  // the straight, clamped part
    ++on_arc;
    const double z = -0.5 * kT + (static_cast<double>(out.id[k] % layers) + 0.5) * layer;
    // The director (-sin phi, cos phi) is the line's left normal: the line
    // runs counter-clockwise round the centre, so it points to the centre.
    // (1e-6 m: the particles sit on the case's 256 chords, 5e-7 m inside.)
    EXPECT_NEAR((out.x[k] - centre).norm(), R - z, 1e-6) << k;
  }
  EXPECT_EQ(on_arc, 16 * layers);
}

// A case gives a curved mid-line as a band: the quarter circle (R = 0.1 m,
// R / t = 20) under a small end force against Castigliano's deflection, at 16
// and 32 particles along the arc (measured 0.22 and 0.10 %). Loaded and run
// as the elastica: the mean over the last 0.5 s of the damped swing about
// rest. The deflection is 0.14 % of R: the change of the load's lever arms
// with it, of order u / R, is then below the discretisation's error (at four
// times the load the error was 0.25 and 0.28 %).
TEST(Shell, ACurvedCantileverBendsAsCastiglianoSays) {
  const double R = 0.1, end = 1.6, average = 0.5;
  const Vec2 F(0.0075, -0.015);  // N/m
  std::vector<double> errors;
  for (const int along : {16, 32}) {
    const sph::CaseFile c = quarter_circle_case(R, along, F);
    ShellSolver solver(c, read_solid_parameters(c));
    const ShellParticles& P = solver.particles();
    Vec2 sum = Vec2::Zero();
    double samples = 0.0;
    while (solver.time() < end) {
      const double dt = solver.step_limits().smallest();
      solver.step(dt);
      if (solver.time() < end - average) continue;
      sum += dt * (P.x.back() - P.X.back());
      samples += dt;
    }
    const Vec2 exact = quarter_circle_deflection(R, solver.force_parameters().section, F);
    const Vec2 measured = sum / samples;
    errors.push_back((measured - exact).norm() / exact.norm());
    std::printf("quarter circle, %d along: (%.4e, %.4e) m, Castigliano (%.4e, %.4e) m, %.2f %%\n",
                along, measured.x(), measured.y(), exact.x(), exact.y(), 100 * errors.back());
    EXPECT_GT(exact.norm(), 0.001 * R);
  }
  EXPECT_LT(errors[0], 0.005);
  EXPECT_LT(errors[1], 0.0025);
}

// The hydrostatic plate's plate alone (cases/hydrostatic_plate.pbtxt: span
// L = 1 m, e = 0.05 m, clamped over 0.0625 m at each end), in vacuum under a
// uniform load, its own weight in a gravity g chosen to make rho_s g e the
// water column's load. Clamped-clamped Timoshenko beam of plane strain:
//   w = q L^4 / (384 E' I) + q L^2 / (8 k G e).
// The load comes on at once and the shell has no dissipation: the mid-span
// swings about its static deflection. The mean over the run (some 25 periods
// of the first mode, T1 = 3.7 ms), weighted by sin^2(pi t / end), takes the
// swing out to far below 0.1 % (a plain mean leaves up to 1 / (2 pi 25)).
double clamped_plate_mean_deflection(int along, double g, double* exact) {
  constexpr double L = 1.0, e = 0.05, E = 67.5e9, nu = 0.34, rho = 2700.0;
  const double dx = L / along;
  const std::string path = testing::write_case("shell_clamped_clamped", R"(
run { end_time: 1 cfl: 0.3 gravity { x: 0 y: )" + std::to_string(-g) + R"( } }
solid {
  model: "shell" spacing: )" + std::to_string(dx) + R"(
  density: 2700 youngs_modulus: 67.5e9 poisson_ratio: 0.34
  body { min { x: -0.0625 y: -0.05 } max { x: 1.0625 y: 0 } }
  clamp { min { x: -0.0625 y: -0.05 } max { x: 0 y: 0 } }
  clamp { min { x: 1 y: -0.05 } max { x: 1.0625 y: 0 } }
}
)");
  ShellSolver solver = solver_of(path);
  const ShellParticles& P = solver.particles();
  std::size_t middle = 0;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (std::abs(P.X[i].x() - 0.5 * L) < std::abs(P.X[middle].x() - 0.5 * L)) middle = i;
  const double q = rho * g * e, E_plane = E / (1.0 - nu * nu), G = E / (2.0 * (1.0 + nu));
  *exact = q * std::pow(L, 4) / (384.0 * E_plane * e * e * e / 12.0) +
           q * L * L / (8.0 * (5.0 / 6.0) * G * e);
  const double end = 0.09;  // s, about 25 first periods
  double sum = 0.0, time = 0.0;
  while (solver.time() < end) {
    const double dt = solver.step_limits().smallest();
    solver.step(dt);
    const double weight = std::pow(std::sin(std::numbers::pi * solver.time() / end), 2);
    sum += dt * weight * (P.X[middle].y() - P.x[middle].y());
    time += dt * weight;
  }
  return sum / time;
}

// The load of the hydrostatic plate, q = rho g H + rho_s g e = 20944 Pa, at
// 16, 32 and 64 particles along the span (64: the finest the thin-box rule
// takes at e = 0.05 m). The two-node Timoshenko element with one-point
// integration converges at second order: each halving divides the error by
// about 4 (measured -1.51, -0.38, -0.09 %).
TEST(Shell, ClampedPlateUnderUniformLoadMatchesTimoshenko) {
  const double g = (1000.0 * 9.81 * 2.0 + 2700.0 * 9.81 * 0.05) / (2700.0 * 0.05);
  std::vector<double> errors;
  for (const int along : {16, 32, 64}) {
    double exact = 0.0;
    const double w = clamped_plate_mean_deflection(along, g, &exact);
    errors.push_back(w / exact - 1.0);
    std::printf("clamped-clamped shell, %d along: %.5e m, Timoshenko %.5e m (%+.2f %%)\n", along, w,
                exact, 100.0 * errors.back());
  }
  EXPECT_LT(std::abs(errors[0]), 0.02);
  EXPECT_LT(std::abs(errors[2]), 0.002);
  for (const std::size_t k : {1u, 2u})
    EXPECT_NEAR(errors[k - 1] / errors[k], 4.0, 1.0) << "halving " << k;
}

}  // namespace
}  // namespace cosph::solid::shell
