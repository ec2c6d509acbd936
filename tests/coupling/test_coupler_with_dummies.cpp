// The three processes together: cosph-coupler and two cosph-dummy solvers over
// ipc:// in a scratch folder. A run that ends well (the common step is the
// smaller proposal, momentum is conserved across the wire, both sides' gauges
// are recorded), the answer naming the solver whose state came last, and runs
// that fail: a solver that dies, hangs, sends garbage,
// never connects, or speaks another protocol version. Each must end every
// process with a message that names the reason, within the coupling timeout;
// SIGTERM ends a coupler's wait for a silent solver within two seconds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <sstream>
#include <thread>
#include <utility>

#include "child_process.hpp"
#include "participant/protocol.hpp"
#include "test_support.hpp"

namespace {

using cosph::testing::ChildProcess;
using cosph::testing::Clock;
using cosph::testing::ScratchDir;
using namespace std::chrono_literals;

const std::string kBin = COSPH_BIN_DIR;
constexpr double kFluidDt = 1e-3, kSolidDt = 1.5e-3, kEndTime = 0.02;

// A CSV file with a header row; columns found by name without the " [unit]".
struct Table {
  std::vector<std::string> names;
  std::vector<std::vector<double>> rows;

  explicit Table(const std::string& path) {
    std::istringstream text(cosph::testing::read_text(path));
    std::string line, cell;
    std::getline(text, line);
    std::istringstream header(line);
    while (std::getline(header, cell, ',')) names.push_back(cell.substr(0, cell.find(" [")));
    while (std::getline(text, line)) {
      std::istringstream row_text(line);
      std::vector<double>& row = rows.emplace_back();
      while (std::getline(row_text, cell, ',')) row.push_back(std::stod(cell));
    }
  }
  bool has(const std::string& name) const {
    return std::find(names.begin(), names.end(), name) != names.end();
  }
  double at(std::size_t row, const std::string& name) const {
    const auto column = std::find(names.begin(), names.end(), name);
    if (column == names.end()) throw std::runtime_error("no column " + name);
    return rows.at(row).at(static_cast<std::size_t>(column - names.begin()));
  }
};

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

class CouplerWithDummies : public ::testing::Test {
 protected:
  void write_case(double timeout, int max_substeps = 0, double output_interval = 0.0005,
                  bool wall_acceleration = false) {
    std::ostringstream text;
    text << "run { end_time: " << kEndTime << " output_interval: " << output_interval
         << " snapshot_interval: 0.02 }\n"
         << "fluid { spacing: 0.001 density: 1000 }\nsolid { spacing: 0.001 }\n"
         << "coupling { timeout: " << timeout << " max_substeps: " << max_substeps
         << " wall_acceleration: " << (wall_acceleration ? "true" : "false") << " }\n";
    cosph::testing::write_text(dir_.file("case.pbtxt"), text.str());
    timeout_ = timeout;
  }
  std::string endpoint() const { return "ipc://" + dir_.file("coupler.sock"); }
  std::string out(const std::string& name) const { return dir_.file("out/" + name); }

  std::unique_ptr<ChildProcess> start_coupler() {
    return std::make_unique<ChildProcess>(
        std::vector<std::string>{kBin + "/cosph-coupler", "--case", dir_.file("case.pbtxt"),
                                 "--out", dir_.file("out"), "--endpoint", endpoint()},
        dir_.file("coupler"));
  }
  std::unique_ptr<ChildProcess> start_dummy(const std::string& phase,
                                            std::vector<std::string> extra = {}) {
    std::vector<std::string> argv{kBin + "/cosph-dummy",
                                  "--phase",
                                  phase,
                                  "--endpoint",
                                  endpoint(),
                                  "--out",
                                  dir_.file("out"),
                                  "--timeout",
                                  std::to_string(timeout_),
                                  "--dt",
                                  phase == "fluid" ? "0.001" : "0.0015"};
    argv.insert(argv.end(), extra.begin(), extra.end());
    return std::make_unique<ChildProcess>(argv, dir_.file(phase));
  }

  // The coupler and two dummies with these arguments, each of the three
  // ending cleanly within 15 s.
  void run_to_the_end(std::vector<std::string> fluid_args = {},
                      std::vector<std::string> solid_args = {}) {
    auto coupler = start_coupler();
    auto fluid = start_dummy("fluid", std::move(fluid_args));
    auto solid = start_dummy("solid", std::move(solid_args));
    const auto deadline = Clock::now() + 15s;
    ASSERT_EQ(coupler->wait_until(deadline), 0) << coupler->err();
    ASSERT_EQ(fluid->wait_until(deadline), 0) << fluid->err();
    ASSERT_EQ(solid->wait_until(deadline), 0) << solid->err();
  }

  ScratchDir dir_{"coupling"};
  double timeout_ = 10.0;
};

TEST_F(CouplerWithDummies, RunToTheEndWithTheSmallerStepAndBalancedForces) {
  write_case(5.0);
  ASSERT_NO_FATAL_FAILURE(
      run_to_the_end({"--stress", "1000"}, {"--stress", "0", "--motion", "-0.01"}));

  // Every step either side was given is the smaller proposal (the last one
  // may be cut to land on end_time), and the run ends at end_time.
  const Table fluid_steps(out("dummy_fluid.csv")), solid_steps(out("dummy_solid.csv"));
  const std::size_t steps = fluid_steps.rows.size();
  ASSERT_EQ(steps, static_cast<std::size_t>(std::lround(kEndTime / kFluidDt)));
  ASSERT_EQ(solid_steps.rows.size(), steps);
  for (std::size_t k = 0; k < steps; ++k)
    for (const Table* side : {&fluid_steps, &solid_steps}) {
      EXPECT_NEAR(side->at(k, "dt"), std::min(kFluidDt, kSolidDt), 1e-12) << "step " << k;
      EXPECT_EQ(side->at(k, "step"), static_cast<double>(k));
    }
  EXPECT_NEAR(fluid_steps.at(steps - 1, "t") + fluid_steps.at(steps - 1, "dt"), kEndTime, 1e-12);

  // What each side received balances, step by step; the fluid pushes the solid away.
  for (std::size_t k = 0; k < steps; ++k) {
    const double on_fluid = fluid_steps.at(k, "sum_max"), on_solid = solid_steps.at(k, "sum_max");
    EXPECT_LT(on_fluid, 0.0) << "step " << k;
    EXPECT_NEAR(on_fluid + on_solid, 0.0, 1e-12 * std::abs(on_fluid)) << "step " << k;
    EXPECT_NEAR(fluid_steps.at(k, "sum_may") + solid_steps.at(k, "sum_may"), 0.0,
                1e-12 * std::abs(on_fluid));
  }

  // The coupler's own record agrees (9 significant digits in the file).
  const Table coupling(out("coupling.csv"));
  ASSERT_GE(coupling.rows.size(), steps);
  for (std::size_t r = 0; r < coupling.rows.size(); ++r) {
    const double fx = coupling.at(r, "force_on_fluid_x");
    EXPECT_LT(fx, 0.0) << "row " << r;
    EXPECT_NEAR(fx + coupling.at(r, "force_on_solid_x"), 0.0, 1e-8 * std::abs(fx)) << "row " << r;
    EXPECT_NEAR(coupling.at(r, "force_on_fluid_y") + coupling.at(r, "force_on_solid_y"), 0.0,
                1e-8 * std::abs(fx));
    EXPECT_GT(coupling.at(r, "pairs"), 0.0) << "row " << r;
  }
  // Each solver's wait for the coupler's answers, as it reported it, grows.
  for (const char* waiting : {"fluid_waiting", "solid_waiting"}) {
    for (std::size_t r = 1; r < coupling.rows.size(); ++r)
      EXPECT_GE(coupling.at(r, waiting), coupling.at(r - 1, waiting)) << waiting << ", row " << r;
    EXPECT_GT(coupling.at(coupling.rows.size() - 1, waiting), 0.0) << waiting;
  }

  const Table timeseries(out("timeseries.csv"));
  for (const char* gauge : {"fluid_force_x", "fluid_steps", "solid_force_x", "solid_steps"})
    EXPECT_TRUE(timeseries.has(gauge)) << gauge;
  ASSERT_GE(timeseries.rows.size(), steps);
  const std::size_t last = timeseries.rows.size() - 1;
  EXPECT_EQ(timeseries.at(last, "fluid_steps"), timeseries.at(last, "solid_steps"));
  EXPECT_GT(timeseries.at(last, "solid_force_x"), 0.0);

  // The coupler's socket file is not left behind.
  EXPECT_FALSE(std::filesystem::exists(dir_.file("coupler.sock")));
}

// The solvers take turns being slow: each waits for the other on every
// second step, which is their imbalance, not the coupling's cost. The waits
// of the one whose state came last, step by step, are the coupling's alone:
// the messages and the pair forces, a small part of either solver's waits.
TEST_F(CouplerWithDummies, PaceSetterWaitsCountTheCouplingAloneWhenTheSolversTakeTurns) {
  write_case(5.0);
  ASSERT_NO_FATAL_FAILURE(run_to_the_end({"--busy-ms", "20", "--busy-parity", "0"},
                                         {"--busy-ms", "20", "--busy-parity", "1"}));
  const Table coupling(out("coupling.csv"));
  const std::size_t last = coupling.rows.size() - 1;
  const double fluid = coupling.at(last, "fluid_waiting"),
               solid = coupling.at(last, "solid_waiting");
  const double pace_setter = coupling.at(last, "pace_setter_waiting");
  // Each waited about 20 ms on every second of the run's 20 steps.
  EXPECT_GT(std::min(fluid, solid), 0.15) << "fluid " << fluid << " s, solid " << solid << " s";
  EXPECT_GT(pace_setter, 0.0);
  EXPECT_LT(pace_setter, 0.3 * std::min(fluid, solid))
      << "fluid " << fluid << " s, solid " << solid << " s";
  for (std::size_t r = 1; r < coupling.rows.size(); ++r)
    EXPECT_GE(coupling.at(r, "pace_setter_waiting"), coupling.at(r - 1, "pace_setter_waiting"));
}

// The solvers send gauges only with the states the coupler asks them for,
// those due in timeseries.csv: each row must hold the gauges of its own
// state (the dummies count their steps), not those of an earlier one.
TEST_F(CouplerWithDummies, EachTimeseriesRowHoldsTheGaugesOfItsOwnState) {
  constexpr double kOutputInterval = 0.0025;  // 2.5 steps
  write_case(5.0, 0, kOutputInterval);
  ASSERT_NO_FATAL_FAILURE(run_to_the_end());

  const Table timeseries(out("timeseries.csv"));
  const std::size_t rows = timeseries.rows.size();
  // t = 0, the first step at or past each multiple of the interval, the end.
  ASSERT_EQ(rows, 9u);
  EXPECT_EQ(timeseries.at(0, "t"), 0.0);
  EXPECT_NEAR(timeseries.at(rows - 1, "t"), kEndTime, 1e-12);
  for (std::size_t r = 0; r < rows; ++r) {
    const double t = timeseries.at(r, "t");
    // A dummy counts a step at its end_step, after the step's exchange.
    const double steps_done = std::max(0.0, std::round(t / kFluidDt) - 1.0);
    EXPECT_EQ(timeseries.at(r, "fluid_steps"), steps_done) << "row " << r;
    EXPECT_EQ(timeseries.at(r, "solid_steps"), steps_done) << "row " << r;
    EXPECT_GE(t, static_cast<double>(r) * kOutputInterval - 1e-12) << "row " << r;
  }
}

// Multi-rate: the window is the larger proposal (the solid's 1.5 ms, within 4
// times the fluid's 1 ms); the fluid covers it in two sub-steps of 0.75 ms
// with the forces of the window's start held, and both meet at its end.
TEST_F(CouplerWithDummies, MultiRateWindowIsTheLargerStepAndTheOtherSideSubsteps) {
  write_case(5.0, 4);
  ASSERT_NO_FATAL_FAILURE(
      run_to_the_end({"--stress", "1000"}, {"--stress", "0", "--motion", "-0.01"}));

  const Table fluid_steps(out("dummy_fluid.csv")), solid_steps(out("dummy_solid.csv"));
  const std::size_t windows = solid_steps.rows.size();
  ASSERT_EQ(windows, static_cast<std::size_t>(std::ceil(kEndTime / kSolidDt)));
  for (std::size_t w = 0; w + 1 < windows; ++w) {
    EXPECT_NEAR(solid_steps.at(w, "dt"), kSolidDt, 1e-12) << "window " << w;
    for (std::size_t k : {2 * w, 2 * w + 1}) {
      EXPECT_NEAR(fluid_steps.at(k, "dt"), 0.5 * kSolidDt, 1e-12) << "sub-step " << k;
      // Held over the window: what the solid received, opposite.
      EXPECT_NEAR(fluid_steps.at(k, "sum_max"), -solid_steps.at(w, "sum_max"),
                  1e-12 * std::abs(solid_steps.at(w, "sum_max")))
          << "sub-step " << k;
    }
  }
  // The last window is cut to land on end_time, where both sides end.
  const std::size_t last_solid = windows - 1, last_fluid = fluid_steps.rows.size() - 1;
  EXPECT_NEAR(solid_steps.at(last_solid, "t") + solid_steps.at(last_solid, "dt"), kEndTime, 1e-12);
  EXPECT_NEAR(fluid_steps.at(last_fluid, "t") + fluid_steps.at(last_fluid, "dt"), kEndTime, 1e-12);
}

// The coupler tells the solver whose state came last that it did (the
// solver that sets the pace polls for its next answer): both orders, played
// on raw sockets so that the order is the test's.
TEST_F(CouplerWithDummies, TheAnswerTellsTheSolverWhoseStateCameLast) {
  namespace cp = cosph::coupling;
  write_case(5.0);
  auto coupler = start_coupler();
  zmq::context_t context;
  std::map<cp::Phase, zmq::socket_t> peers;
  const std::chrono::milliseconds timeout(5000);
  for (const cp::Phase phase : {cp::FLUID, cp::SOLID}) {
    zmq::socket_t& socket =
        peers.emplace(phase, zmq::socket_t(context, zmq::socket_type::dealer)).first->second;
    socket.set(zmq::sockopt::linger, 0);
    socket.connect(endpoint());
    cp::Envelope hello;
    hello.mutable_hello()->set_protocol_version(cp::kProtocolVersion);
    hello.mutable_hello()->set_phase(phase);
    hello.mutable_hello()->set_solver("the test");
    hello.mutable_hello()->set_max_smoothing_length(1e-3);
    cp::send(socket, hello);
  }
  for (auto& [phase, socket] : peers)
    ASSERT_TRUE(cp::receive(socket, timeout, "the coupler").value().has_welcome());

  auto send_state = [&](cp::Phase phase, long step) {
    cp::Envelope message;
    message.mutable_state()->set_step(static_cast<std::uint64_t>(step));
    message.mutable_state()->set_time(1e-3 * static_cast<double>(step));
    message.mutable_state()->set_proposed_dt(1e-3);
    message.mutable_state()->set_max_smoothing_length(1e-3);
    cp::send(peers.at(phase), message);
  };
  auto came_last = [&](cp::Phase phase) {
    const std::optional<cp::Envelope> reply = cp::receive(peers.at(phase), timeout, "the coupler");
    EXPECT_TRUE(reply && reply->has_step()) << "no step for " << cp::phase_name(phase);
    return reply && reply->step().came_last();
  };
  long step = 0;
  for (const auto& [first, last] :
       {std::pair{cp::FLUID, cp::SOLID}, std::pair{cp::SOLID, cp::FLUID}}) {
    send_state(first, step);
    std::this_thread::sleep_for(100ms);  // the coupler has the first state well before the last
    send_state(last, step);
    EXPECT_TRUE(came_last(last)) << cp::phase_name(last) << " sent last at step " << step;
    EXPECT_FALSE(came_last(first)) << cp::phase_name(first) << " sent first at step " << step;
    ++step;
  }
}

// Expects every process to have ended by itself before the deadline and been reaped.
void expect_all_gone(std::initializer_list<ChildProcess*> processes) {
  for (ChildProcess* process : processes) {
    EXPECT_TRUE(process->reaped());
    EXPECT_FALSE(process->exists());
  }
}

// SIGTERM (what the launcher sends when another process failed) stops a
// coupler that is waiting for a solver that went quiet within two
// seconds, not at the end of the coupling timeout: otherwise the launcher
// would have to kill it, and its socket file would stay behind.
TEST_F(CouplerWithDummies, SigtermEndsACouplersWaitForASilentSolverAtOnce) {
  write_case(30.0);
  auto coupler = start_coupler();
  auto fluid = start_dummy("fluid");
  auto solid = start_dummy("solid", {"--hang-at-step", "4"});
  // Step 4's exchange: the fluid has sent its state, the solid never will.
  std::this_thread::sleep_for(1s);
  ASSERT_EQ(coupler->wait_until(Clock::now()), ChildProcess::kStillRunning) << coupler->err();
  const auto sent = Clock::now();
  coupler->signal(SIGTERM);
  const int coupler_code = coupler->wait_until(sent + 5s);
  EXPECT_NE(coupler_code, ChildProcess::kStillRunning) << "the coupler waited on after SIGTERM";
  EXPECT_NE(coupler_code, 0);
  EXPECT_TRUE(contains(coupler->err(), "interrupted")) << coupler->err();
  EXPECT_FALSE(std::filesystem::exists(dir_.file("coupler.sock")));
  // The coupler's error reaches the fluid, which stops too.
  EXPECT_NE(fluid->wait_until(sent + 5s), ChildProcess::kStillRunning);
  solid->signal(SIGTERM);
  EXPECT_NE(solid->wait_until(Clock::now() + 3s), ChildProcess::kStillRunning);
  expect_all_gone({coupler.get(), fluid.get(), solid.get()});
}

TEST_F(CouplerWithDummies, ASolverThatDiesEndsTheRunWithItsReason) {
  write_case(3.0);
  const auto start = Clock::now();
  auto coupler = start_coupler();
  auto fluid = start_dummy("fluid", {"--die-at-step", "5"});
  auto solid = start_dummy("solid");
  const auto deadline = start + 10s;
  const int coupler_code = coupler->wait_until(deadline);
  const int solid_code = solid->wait_until(deadline);
  const int fluid_code = fluid->wait_until(deadline);
  EXPECT_LT(Clock::now() - start, 10s);
  EXPECT_EQ(fluid_code, 3) << fluid->err();  // the dummy's abrupt exit
  EXPECT_NE(coupler_code, ChildProcess::kStillRunning);
  EXPECT_NE(coupler_code, 0);
  EXPECT_TRUE(contains(coupler->err(), "waiting for the fluid")) << coupler->err();
  EXPECT_TRUE(contains(coupler->err(), "died")) << coupler->err();
  EXPECT_NE(solid_code, ChildProcess::kStillRunning);
  EXPECT_NE(solid_code, 0);
  // The solid reports the coupler's diagnosis, not a timeout of its own.
  EXPECT_TRUE(contains(solid->err(), "coupler: step")) << solid->err();
  EXPECT_TRUE(contains(solid->err(), "waiting for the fluid")) << solid->err();
  expect_all_gone({coupler.get(), fluid.get(), solid.get()});
  EXPECT_FALSE(std::filesystem::exists(dir_.file("coupler.sock")));
}

TEST_F(CouplerWithDummies, ASolverThatHangsIsTimedOutAndStopsOnSigterm) {
  write_case(2.0);
  const auto start = Clock::now();
  auto coupler = start_coupler();
  auto fluid = start_dummy("fluid");
  auto solid = start_dummy("solid", {"--hang-at-step", "4"});
  const int coupler_code = coupler->wait_until(start + 8s);
  EXPECT_NE(coupler_code, ChildProcess::kStillRunning);
  EXPECT_NE(coupler_code, 0);
  EXPECT_TRUE(contains(coupler->err(), "waiting for the solid")) << coupler->err();
  const int fluid_code = fluid->wait_until(start + 8s);
  EXPECT_NE(fluid_code, ChildProcess::kStillRunning);
  EXPECT_NE(fluid_code, 0);
  EXPECT_TRUE(contains(fluid->err(), "waiting for the solid")) << fluid->err();
  // The hung solver is still there; SIGTERM (what the launcher sends) ends it.
  EXPECT_EQ(solid->wait_until(Clock::now()), ChildProcess::kStillRunning);
  solid->signal(SIGTERM);
  const int solid_code = solid->wait_until(Clock::now() + 3s);
  EXPECT_NE(solid_code, ChildProcess::kStillRunning);
  EXPECT_NE(solid_code, 0);
  expect_all_gone({coupler.get(), fluid.get(), solid.get()});
}

TEST_F(CouplerWithDummies, GarbageFromASolverEndsTheRun) {
  write_case(3.0);
  auto coupler = start_coupler();
  auto fluid = start_dummy("fluid");
  auto solid = start_dummy("solid", {"--garbage-at-step", "3"});
  const auto deadline = Clock::now() + 8s;
  EXPECT_EQ(coupler->wait_until(deadline), 1) << coupler->err();
  // The run stops, naming the solver whose message it was.
  EXPECT_TRUE(contains(coupler->err(), "garbage from the solid ('cosph-dummy (solid)')"))
      << coupler->err();
  EXPECT_EQ(fluid->wait_until(deadline), 1) << fluid->err();
  EXPECT_TRUE(contains(fluid->err(), "garbage")) << fluid->err();
  EXPECT_EQ(solid->wait_until(deadline), 1) << solid->err();
  EXPECT_TRUE(contains(solid->err(), "coupler: garbage")) << solid->err();
  expect_all_gone({coupler.get(), fluid.get(), solid.get()});
}

TEST_F(CouplerWithDummies, ACouplerWhoseSolversNeverConnectGivesUp) {
  write_case(2.0);
  const auto start = Clock::now();
  auto coupler = start_coupler();
  const int code = coupler->wait_until(start + 6s);
  EXPECT_LT(Clock::now() - start, 5s);
  EXPECT_NE(code, ChildProcess::kStillRunning);
  EXPECT_NE(code, 0);
  EXPECT_TRUE(contains(coupler->err(), "waiting for the solvers")) << coupler->err();
  expect_all_gone({coupler.get()});
}

// A solid that sends no acceleration with its state still couples to the end;
// the coupler says once that the moving wall's pressure leaves its term out.
// The net force on the solid is in timeseries.csv, row by row the one in
// coupling.csv.
TEST_F(CouplerWithDummies, ASolidWithoutAccelerationCouplesWithOneWarning) {
  const std::string warning = "sends no acceleration";
  for (const bool sends : {true, false}) {
    write_case(10.0, 0, 0.0005, /*wall_acceleration=*/true);
    auto coupler = start_coupler();
    auto fluid = start_dummy("fluid");
    auto solid = start_dummy("solid", {"--send-acceleration", sends ? "1" : "0"});
    const auto deadline = Clock::now() + 15s;
    ASSERT_EQ(coupler->wait_until(deadline), 0) << coupler->err();
    ASSERT_EQ(fluid->wait_until(deadline), 0) << fluid->err();
    ASSERT_EQ(solid->wait_until(deadline), 0) << solid->err();
    const std::string log = coupler->err();
    const auto first = log.find(warning);
    if (sends) {
      EXPECT_EQ(first, std::string::npos) << log;
    } else {
      ASSERT_NE(first, std::string::npos) << log;
      EXPECT_EQ(log.find(warning, first + 1), std::string::npos) << "warned twice: " << log;
    }
    const Table series(out("timeseries.csv")), coupling(out("coupling.csv"));
    ASSERT_TRUE(series.has("plate_force_x") && series.has("plate_force_y"));
    ASSERT_EQ(series.rows.size(), coupling.rows.size());
    double largest = 0.0;
    for (std::size_t r = 0; r < series.rows.size(); ++r) {
      EXPECT_EQ(series.at(r, "plate_force_x"), coupling.at(r, "force_on_solid_x")) << "row " << r;
      EXPECT_EQ(series.at(r, "plate_force_y"), coupling.at(r, "force_on_solid_y")) << "row " << r;
      largest = std::max(largest, std::abs(series.at(r, "plate_force_x")));
    }
    EXPECT_GT(largest, 0.0);  // the fluid's 1000 Pa pushes the solid
  }
}

// The coupler refuses the solver, tells it why and logs it, but waits on for
// a solver it can take (test_rogue_peers): here none comes, and it gives up.
TEST_F(CouplerWithDummies, AnotherProtocolVersionIsRefused) {
  write_case(3.0);
  auto coupler = start_coupler();
  auto fluid = start_dummy("fluid", {"--version", "99"});
  const auto deadline = Clock::now() + 6s;
  const int fluid_code = fluid->wait_until(deadline);
  EXPECT_NE(fluid_code, ChildProcess::kStillRunning);
  EXPECT_NE(fluid_code, 0);
  // The dummy reports the coupler's refusal, which names both versions.
  EXPECT_TRUE(contains(fluid->err(), "coupler: protocol version 99")) << fluid->err();
  EXPECT_TRUE(contains(fluid->err(),
                       "coupler's version " + std::to_string(cosph::coupling::kProtocolVersion)))
      << fluid->err();
  const int coupler_code = coupler->wait_until(deadline);
  EXPECT_NE(coupler_code, ChildProcess::kStillRunning);
  EXPECT_NE(coupler_code, 0);
  EXPECT_TRUE(contains(coupler->err(), "refused")) << coupler->err();
  expect_all_gone({coupler.get(), fluid.get()});
}

}  // namespace
