// The coupling messages (proto/coupling.proto) built, serialised, parsed and
// checked without a network: participant/protocol.hpp as pure functions.
#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "participant/protocol.hpp"
#include "sphcore/gauge.hpp"
#include "sphcore/region.hpp"

namespace {

namespace cp = cosph::coupling;
using sph::Mat2;
using sph::Vec2;

// Particles whose every field differs, with a stress whose xy and yx differ,
// so that a swapped or dropped component shows.
sph::InterfaceParticles random_particles(int n) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  sph::InterfaceParticles P;
  for (int i = 0; i < n; ++i) {
    Mat2 sigma;
    sigma << 1e4 * u(random), 1e3 * u(random), 2e3 * u(random), 1e4 * u(random);
    P.add(1000 + 3 * i, Vec2(u(random), u(random)), Vec2(u(random), u(random)), sigma,
          1.0 + u(random) * 0.1, 1000.0 + u(random), 1.3e-3 * (1.5 + u(random)), 20.0 + u(random));
  }
  return P;
}

std::string error_of(const std::function<void()>& body) {
  try {
    body();
  } catch (const cp::CouplingError& error) {
    return error.what();
  }
  return "";
}

TEST(Protocol, InterfaceStateRoundTripsThroughBytes) {
  const sph::InterfaceParticles original = random_particles(17);
  cp::Envelope envelope;
  cp::to_proto(original, *envelope.mutable_state());
  const cp::Envelope parsed = cp::parse(cp::serialise(envelope), "the test");
  ASSERT_TRUE(parsed.has_state());
  const sph::InterfaceParticles P = cp::from_proto(parsed.state());

  ASSERT_EQ(P.size(), original.size());
  for (std::size_t i = 0; i < P.size(); ++i) {
    EXPECT_EQ(P.id[i], original.id[i]);
    EXPECT_EQ(P.x[i], original.x[i]);
    EXPECT_EQ(P.v[i], original.v[i]);
    EXPECT_EQ(P.sigma[i], original.sigma[i]) << "particle " << i << " stress";
    EXPECT_EQ(P.m[i], original.m[i]);
    EXPECT_EQ(P.rho[i], original.rho[i]);
    EXPECT_EQ(P.h[i], original.h[i]);
    EXPECT_EQ(P.c[i], original.c[i]);
  }
}

// Protocol version 3: a solid's acceleration travels with its state, one per
// particle; a state without it (a fluid, a version-2 solid) parses with none,
// and a partial array is refused naming the field.
TEST(Protocol, AccelerationRoundTripsOrIsAbsent) {
  sph::InterfaceParticles solid;
  for (int i = 0; i < 4; ++i)
    solid.add(i, Vec2(i, 0.0), Vec2::Zero(), Vec2(0.5 * i, -9.81 - i), Mat2::Zero(), 1.0, 1.0, 1.0,
              1.0);
  cp::Envelope envelope;
  cp::to_proto(solid, *envelope.mutable_state());
  ASSERT_EQ(envelope.state().acceleration_size(), 8);
  const sph::InterfaceParticles parsed =
      cp::from_proto(cp::parse(cp::serialise(envelope), "the test").state());
  ASSERT_TRUE(parsed.has_acceleration());
  for (std::size_t i = 0; i < solid.size(); ++i) EXPECT_EQ(parsed.a[i], solid.a[i]);

  cp::InterfaceState without;
  cp::to_proto(random_particles(5), without);
  EXPECT_EQ(without.acceleration_size(), 0);
  const sph::InterfaceParticles none = cp::from_proto(without);
  EXPECT_EQ(none.size(), 5u);
  EXPECT_FALSE(none.has_acceleration());

  envelope.mutable_state()->mutable_acceleration()->RemoveLast();
  const std::string message = error_of([&] { cp::from_proto(envelope.state()); });
  EXPECT_NE(message.find("acceleration"), std::string::npos) << message;
}

TEST(Protocol, StressTravelsAsXxXyYxYy) {
  sph::InterfaceParticles P;
  Mat2 sigma;
  sigma << 1.0, 2.0, 3.0, 4.0;  // row-major: xx, xy / yx, yy
  P.add(0, Vec2::Zero(), Vec2::Zero(), sigma, 1.0, 1.0, 1.0, 1.0);
  cp::InterfaceState state;
  cp::to_proto(P, state);
  ASSERT_EQ(state.stress_size(), 4);
  EXPECT_EQ(state.stress(0), 1.0);
  EXPECT_EQ(state.stress(1), 2.0);
  EXPECT_EQ(state.stress(2), 3.0);
  EXPECT_EQ(state.stress(3), 4.0);
}

TEST(Protocol, RegionsRoundTripIncludingUnbounded) {
  const sph::Region region{Vec2(-1.0, 0.5), Vec2(2.0, 3.5)};
  const sph::Region back = cp::from_proto(cp::to_proto(region));
  EXPECT_EQ(back.min, region.min);
  EXPECT_EQ(back.max, region.max);
  EXPECT_TRUE(
      cp::from_proto(cp::to_proto(sph::Region::everything())).contains(Vec2(1e300, -1e300)));
  EXPECT_TRUE(cp::from_proto(cp::to_proto(sph::Region{})).empty());
}

TEST(Protocol, GaugesAndStepSurviveSerialisation) {
  cp::Envelope envelope;
  cp::InterfaceState& state = *envelope.mutable_state();
  state.set_step(12);
  state.set_time(0.25);
  state.set_proposed_dt(1e-5);
  cp::Gauge& gauge = *state.add_gauges();
  gauge.set_name("tip_dx");
  gauge.set_unit("m");
  gauge.set_value(-3e-4);
  const cp::Envelope parsed = cp::parse(cp::serialise(envelope), "the test");
  EXPECT_EQ(parsed.state().step(), 12u);
  EXPECT_EQ(parsed.state().time(), 0.25);
  EXPECT_EQ(parsed.state().proposed_dt(), 1e-5);
  ASSERT_EQ(parsed.state().gauges_size(), 1);
  EXPECT_EQ(parsed.state().gauges(0).name(), "tip_dx");
  EXPECT_EQ(parsed.state().gauges(0).value(), -3e-4);
}

// Each malformed array is refused with a message that names it.
TEST(Protocol, MalformedArraysAreRefusedNamingTheField) {
  using Corruption = std::function<void(cp::InterfaceState&)>;
  const std::vector<std::pair<std::string, Corruption>> cases{
      {"position", [](cp::InterfaceState& s) { s.add_position(0.0); }},
      {"velocity", [](cp::InterfaceState& s) { s.mutable_velocity()->RemoveLast(); }},
      {"stress", [](cp::InterfaceState& s) { s.mutable_stress()->RemoveLast(); }},
      {"mass", [](cp::InterfaceState& s) { s.add_mass(1.0); }},
      {"density", [](cp::InterfaceState& s) { s.clear_density(); }},
      {"smoothing_length",
       [](cp::InterfaceState& s) { s.mutable_smoothing_length()->RemoveLast(); }},
      {"sound_speed", [](cp::InterfaceState& s) { s.add_sound_speed(1.0); }},
  };
  for (const auto& [field, corrupt] : cases) {
    cp::InterfaceState state;
    cp::to_proto(random_particles(5), state);
    corrupt(state);
    const std::string message = error_of([&] { cp::from_proto(state); });
    EXPECT_NE(message.find(field), std::string::npos) << field << ": '" << message << "'";
  }
}

TEST(Protocol, NonPositiveMassIsRefused) {
  cp::InterfaceState state;
  cp::to_proto(random_particles(3), state);
  state.set_mass(1, 0.0);
  EXPECT_NE(error_of([&] { cp::from_proto(state); }).find("not positive"), std::string::npos);
}

TEST(Protocol, GarbageBytesAreRefusedNamingTheSender) {
  const std::string garbage = "\xff\xff\xff not a message";
  const std::string message = error_of([&] { cp::parse(garbage, "the fluid"); });
  EXPECT_NE(message.find("garbage from the fluid"), std::string::npos) << message;
  // Zero bytes parse as an empty Envelope: no body, refused too.
  EXPECT_NE(error_of([] { cp::parse("", "the solid"); }).find("the solid"), std::string::npos);
}

cp::Hello good_hello(cp::Phase phase) {
  cp::Hello hello;
  hello.set_protocol_version(cp::kProtocolVersion);
  hello.set_phase(phase);
  hello.set_solver("test solver");
  hello.set_max_smoothing_length(1e-3);
  return hello;
}

TEST(Protocol, CheckHelloAcceptsTheRightVersionAndPhase) {
  EXPECT_EQ(cp::check_hello(good_hello(cp::FLUID), cp::FLUID), "");
  EXPECT_EQ(cp::check_hello(good_hello(cp::SOLID), cp::SOLID), "");
}

// Version 2 lacks only the acceleration, which the coupler can do without.
TEST(Protocol, CheckHelloAcceptsTheOldestVersionAndNoOlder) {
  cp::Hello hello = good_hello(cp::SOLID);
  hello.set_protocol_version(cp::kOldestProtocolVersion);
  EXPECT_EQ(cp::check_hello(hello, cp::SOLID), "");
  hello.set_protocol_version(cp::kOldestProtocolVersion - 1);
  EXPECT_NE(cp::check_hello(hello, cp::SOLID), "");
  hello.set_protocol_version(cp::kProtocolVersion + 1);
  EXPECT_NE(cp::check_hello(hello, cp::SOLID), "");
}

TEST(Protocol, CheckHelloRefusesAnotherVersionNamingBoth) {
  cp::Hello hello = good_hello(cp::FLUID);
  hello.set_protocol_version(42);
  const std::string message = cp::check_hello(hello, cp::FLUID);
  EXPECT_NE(message.find("version 42"), std::string::npos) << message;
  EXPECT_NE(message.find("version " + std::to_string(cp::kProtocolVersion)), std::string::npos)
      << message;
}

TEST(Protocol, CheckHelloRefusesTheWrongPhase) {
  const std::string message = cp::check_hello(good_hello(cp::SOLID), cp::FLUID);
  EXPECT_NE(message.find("solid"), std::string::npos) << message;
  EXPECT_NE(message.find("fluid"), std::string::npos) << message;
  EXPECT_NE(cp::check_hello(good_hello(cp::PHASE_UNSPECIFIED), cp::SOLID), "");
}

TEST(Protocol, CheckHelloRefusesANonPositiveSmoothingLength) {
  cp::Hello hello = good_hello(cp::FLUID);
  hello.set_max_smoothing_length(0.0);
  EXPECT_NE(cp::check_hello(hello, cp::FLUID), "");
}

}  // namespace
