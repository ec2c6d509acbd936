// A solver's coupled loop (participant/coupled_run.hpp) against a coupler that
// the test plays on a thread of its own: which state goes out, and when.
#include <gtest/gtest.h>

#include <unistd.h>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <future>
#include <limits>
#include <set>
#include <thread>
#include <zmq.hpp>

#include "participant/bound_ipc_file.hpp"
#include "participant/coupled_run.hpp"
#include "participant/protocol.hpp"
#include "sphcore/gauge.hpp"
#include "sphcore/region.hpp"
#include "sphcore/time_step.hpp"

namespace {

namespace cp = cosph::coupling;
using sph::Mat2;
using sph::Vec2;

constexpr double kDt = 1e-3;                           // s, every step
constexpr double kSpeed = 2.0;                         // m/s, of the solver's one particle
constexpr long kWindows = 5;                           // exchanges after the first
constexpr std::chrono::milliseconds kAnswerDelay{20};  // the coupler's "work" per step

// What the coupler saw, for the test to check afterwards.
struct CouplerLog {
  std::atomic<long> states{0};  // received so far, the first (before any step) included
  std::vector<double> time, x;  // of each state, and of its particle
  std::vector<double> waiting;  // s, the solver's wait for answers, as each state reports it
  // The gauges of each state: none, or the force passes the solver had done.
  std::vector<std::vector<double>> gauges;
  // The coupler's script: after which states it asks for gauges with the next.
  std::set<long> asks_for_gauges_after;
};

// One particle moving at kSpeed. With kSplits, it splits its step as the
// cosph solvers do. Its force pass waits for the coupler to hold this step's
// state: at most two seconds when it splits, and 50 ms when it does not (the
// state must then never come during the pass, and a state sent too early
// would reach the coupler within that time). It counts the passes that found
// the state not yet out.
template <bool kSplits>
class MovingParticle {
 public:
  explicit MovingParticle(const CouplerLog& coupler,
                          std::chrono::milliseconds patience = std::chrono::milliseconds(2000))
      : coupler_(coupler), patience_(patience) {}

  void begin_step(double dt) {
    advance(dt);
    force_pass();
  }
  void advance_state(double dt) requires kSplits { advance(dt); }
  void compute_forces() requires kSplits { force_pass(); }
  void end_step(double dt) {
    time_ += dt;
    ++steps_;
  }

  sph::StepLimits step_limits() const {
    const double inf = std::numeric_limits<double>::infinity();
    return {kDt, inf, inf};
  }
  void collect_interface(const sph::Region&, sph::InterfaceParticles& out) const {
    out.clear();
    out.add(0, x_, Vec2(kSpeed, 0.0), Mat2::Zero(), 1.0, 1000.0, 1e-3, 10.0);
  }
  void set_interface_accelerations(const std::vector<Vec2>&) {}
  sph::Region interaction_bounds() const { return sph::bounds_of(std::vector<Vec2>{x_}); }
  double max_smoothing_length() const { return 1e-3; }
  std::vector<sph::Gauge> gauge_values() const {
    return {{"force_passes", "1", static_cast<double>(force_passes_)}};
  }
  double time() const { return time_; }
  long steps() const { return steps_; }
  sph::Snapshot snapshot() const { return sph::Snapshot(std::vector<Vec2>{x_}); }
  std::vector<Vec2> particles() const { return {x_}; }

  long force_passes_before_the_state_was_out() const { return late_; }

 private:
  void advance(double dt) { x_.x() += kSpeed * dt; }
  void force_pass() {
    ++force_passes_;
    const long wanted = steps_ + 2;  // the first state, and this step's
    const auto give_up =
        std::chrono::steady_clock::now() + (kSplits ? patience_ : std::chrono::milliseconds(50));
    while (coupler_.states.load() < wanted && std::chrono::steady_clock::now() < give_up)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    if (coupler_.states.load() < wanted) ++late_;
  }

  const CouplerLog& coupler_;
  std::chrono::milliseconds patience_;
  long force_passes_ = 0;
  Vec2 x_ = Vec2::Zero();
  double time_ = 0.0;
  long steps_ = 0;
  long late_ = 0;
};

// Answers every state with the step kDt, kAnswerDelay after it arrives,
// until kWindows exchanges are done.
void play_coupler(zmq::socket_t& socket, CouplerLog& log) {
  const std::chrono::milliseconds timeout(10000);
  const auto hello = cp::receive_routed(socket, timeout);
  ASSERT_TRUE(hello && hello->envelope.has_hello());
  cp::Envelope welcome;
  *welcome.mutable_welcome()->mutable_send_region() =
      cp::to_proto(sph::Region{Vec2(-1e3, -1e3), Vec2(1e3, 1e3)});
  welcome.mutable_welcome()->set_protocol_version(cp::kProtocolVersion);
  cp::send_to(socket, hello->identity, welcome);
  for (long window = 0; window <= kWindows; ++window) {
    const auto message = cp::receive_routed(socket, timeout);
    ASSERT_TRUE(message && message->envelope.has_state()) << "window " << window;
    const cp::InterfaceState& state = message->envelope.state();
    log.time.push_back(state.time());
    log.x.push_back(state.position(0));
    log.waiting.push_back(state.waiting());
    log.gauges.emplace_back();
    for (const auto& gauge : state.gauges()) log.gauges.back().push_back(gauge.value());
    log.states.fetch_add(1);
    std::this_thread::sleep_for(kAnswerDelay);
    cp::Envelope reply;
    cp::CouplingStep& step = *reply.mutable_step();
    step.set_dt(kDt);
    step.add_acceleration(0.0);
    step.add_acceleration(0.0);
    *step.mutable_send_region() = welcome.welcome().send_region();
    step.set_stop(window == kWindows);
    step.set_report_gauges(log.asks_for_gauges_after.count(window) > 0);
    cp::send_to(socket, message->identity, reply);
  }
}

template <class Solver>
void run_against_the_coupler(Solver& solver, CouplerLog& log) {
  const std::filesystem::path out =
      std::filesystem::temp_directory_path() / ("cosph_coupled_run_" + std::to_string(getpid()));
  std::filesystem::create_directories(out);
  const std::string endpoint = "ipc://" + (out / "coupler.sock").string();
  {
    cp::BoundIpcFile socket_file;
    zmq::context_t context;
    zmq::socket_t socket(context, zmq::socket_type::router);
    socket.set(zmq::sockopt::linger, 1000);
    socket.bind(endpoint);
    socket_file.bound(endpoint);
    auto coupler = std::async(std::launch::async, [&] { play_coupler(socket, log); });
    const sph::RunParameters run{1.0, 1.0, 1.0, 0.25, Vec2::Zero(), 1};
    cp::CoupledRun<Solver> coupled(
        solver, run, {out.string(), "particle", cp::PhaseKind::solid, "test", endpoint, 10.0});
    EXPECT_EQ(coupled.run(), 0);
    coupler.get();
  }
  std::filesystem::remove_all(out);
}

// The state each exchange carries is the one at the end of the step: time and
// position advanced, with the own forces or without them.
void expect_advanced_states(const CouplerLog& log) {
  ASSERT_EQ(log.time.size(), static_cast<std::size_t>(kWindows + 1));
  for (std::size_t n = 0; n < log.time.size(); ++n) {
    const double steps = static_cast<double>(n);
    EXPECT_NEAR(log.time[n], steps * kDt, 1e-15) << "state " << n;
    EXPECT_NEAR(log.x[n], steps * kSpeed * kDt, 1e-15) << "state " << n;
  }
}

TEST(CoupledRun, ASolverThatSplitsItsStepSendsItsStateBeforeItsForcePass) {
  CouplerLog log;
  MovingParticle<true> solver(log);
  run_against_the_coupler(solver, log);
  expect_advanced_states(log);
  // Sent only after the force pass, every state would arrive too late.
  EXPECT_EQ(solver.force_passes_before_the_state_was_out(), 0);
  EXPECT_EQ(solver.steps(), kWindows);
}

TEST(CoupledRun, ASolverThatDoesNotSplitItsStepSendsItAfterTheWholeBeginStep) {
  static_assert(!cp::SplitsItsStep<MovingParticle<false>>);
  CouplerLog log;
  MovingParticle<false> solver(log);
  run_against_the_coupler(solver, log);
  expect_advanced_states(log);
  EXPECT_EQ(solver.force_passes_before_the_state_was_out(), kWindows);
}

// Each state reports how long the solver has waited for answers so far: at
// least the coupler's delay for every answer before it (a solver that splits
// its step hides part of that delay behind its force pass).
TEST(CoupledRun, EachStateReportsTheSolversWaitForTheAnswersSoFar) {
  CouplerLog log;
  MovingParticle<false> solver(log);
  run_against_the_coupler(solver, log);
  ASSERT_EQ(log.waiting.size(), static_cast<std::size_t>(kWindows + 1));
  EXPECT_EQ(log.waiting[0], 0.0);
  // Each answer comes kAnswerDelay after the state arrives, and the solver
  // starts its clock a little after sending: on a loaded machine it may lose
  // a few ms of each wait there (seen once under ctest -j2). Half the delay a
  // step still tells a sum from the last wait alone (n >= 3).
  const double delay = std::chrono::duration<double>(kAnswerDelay).count();
  for (std::size_t n = 1; n < log.waiting.size(); ++n) {
    EXPECT_GT(log.waiting[n], log.waiting[n - 1]) << "state " << n;
    EXPECT_GE(log.waiting[n], 0.5 * static_cast<double>(n) * delay) << "state " << n;
  }
}

// Gauges go out with the first state and with each state the coupler asked
// for, as the next timeseries row; a solver that splits its step sends such a
// state after its force pass, so that gauges may read the forces (the water's
// wall forces do). Other states carry none.
TEST(CoupledRun, GaugesGoOutOnlyWithTheStatesAskedForAndAfterTheForcePass) {
  CouplerLog log;
  log.asks_for_gauges_after = {1, 3};
  // No patience: the force pass before a state due in the timeseries would
  // wait for it in vain.
  MovingParticle<true> solver(log, std::chrono::milliseconds(0));
  run_against_the_coupler(solver, log);
  expect_advanced_states(log);
  ASSERT_EQ(log.gauges.size(), static_cast<std::size_t>(kWindows + 1));
  for (std::size_t n = 0; n < log.gauges.size(); ++n) {
    const bool asked = n == 0 || log.asks_for_gauges_after.count(static_cast<long>(n) - 1) > 0;
    ASSERT_EQ(log.gauges[n].size(), asked ? 1u : 0u) << "state " << n;
    // State n follows n steps; its own force pass done, or none at the start.
    if (asked) {
      EXPECT_EQ(log.gauges[n][0], static_cast<double>(n)) << "state " << n;
    }
  }
}

}  // namespace
