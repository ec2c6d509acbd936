// Peers that are not one of a run's solvers: each kind of bad message, sent
// on a raw DEALER socket before the solvers join and again while they run,
// must be refused, answered with the reason and logged by the coupler, and
// the run of two cosph-dummy solvers must go on to its end. A registered
// solver's garbage, on the other hand, stops the run (test_coupler_with_dummies).
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "coupled_processes.hpp"

namespace {

namespace cp = cosph::coupling;
using cosph::testing::Clock;
using cosph::testing::CoupledProcesses;
using cosph::testing::hello_of;
using namespace std::chrono_literals;

struct RogueMessage {
  std::string kind;
  std::function<void(zmq::socket_t&)> send;
  std::string reason;  // part of the refusal the coupler logs and answers with
};

void send_bytes(zmq::socket_t& socket, const std::string& bytes) {
  socket.send(zmq::buffer(bytes), zmq::send_flags::none);
}

std::vector<RogueMessage> rogue_messages(bool solvers_joined) {
  std::vector<RogueMessage> messages{
      {"garbage", [](zmq::socket_t& s) { send_bytes(s, "\xff\xff\xff not a cosph message"); },
       "bytes that are not a cosph coupling message"},
      {"empty", [](zmq::socket_t& s) { send_bytes(s, ""); },
       "0 bytes that are not a cosph coupling message"},
      {"multi-frame",
       [](zmq::socket_t& s) {
         const std::string hello = cp::serialise(hello_of(cp::FLUID, "rogue"));
         s.send(zmq::buffer(hello), zmq::send_flags::sndmore);
         s.send(zmq::buffer(hello), zmq::send_flags::none);
       },
       "a message of 2 frames"},
      {"oversized",
       [](zmq::socket_t& s) {
         cp::send(s, hello_of(cp::FLUID, std::string(std::size_t{1} << 20, 'x')));
       },
       "over the limit of 65536 bytes"},
      {"wrong version", [](zmq::socket_t& s) { cp::send(s, hello_of(cp::FLUID, "rogue", 99)); },
       "protocol version 99 of 'rogue'"},
      {"state before Hello",
       [](zmq::socket_t& s) {
         cp::Envelope state;
         state.mutable_state()->set_time(0.0);
         state.mutable_state()->set_proposed_dt(1e-3);
         cp::send(s, state);
       },
       "a state from a peer that has not said Hello"}};
  // Before the solvers join, a well-formed solid Hello would be the run's solid.
  if (solvers_joined)
    messages.push_back({"a second solid",
                        [](zmq::socket_t& s) { cp::send(s, hello_of(cp::SOLID, "rogue")); },
                        "a second solid solver, 'rogue'"});
  return messages;
}

// Sends each message from a socket of its own and expects the coupler's
// refusal back, naming the reason.
void send_rogues(const std::string& endpoint, bool solvers_joined) {
  zmq::context_t context;
  for (const RogueMessage& message : rogue_messages(solvers_joined)) {
    zmq::socket_t rogue(context, zmq::socket_type::dealer);
    rogue.set(zmq::sockopt::linger, 0);
    rogue.connect(endpoint);
    message.send(rogue);
    const std::optional<cp::Envelope> reply = cp::receive(rogue, 5000ms, "the coupler");
    ASSERT_TRUE(reply.has_value()) << message.kind << ": no answer";
    ASSERT_TRUE(reply->has_error()) << message.kind;
    EXPECT_NE(reply->error().message().find(message.reason), std::string::npos)
        << message.kind << ": " << reply->error().message();
  }
}

TEST(RoguePeers, AreRefusedAndLoggedWhileTheRunGoesOn) {
  CoupledProcesses run("rogues");
  run.write_case(5.0);
  const std::string endpoint = run.ipc_endpoint();
  auto coupler = run.start_coupler(endpoint);
  ASSERT_NO_FATAL_FAILURE(send_rogues(endpoint, false));
  // Slowed to 2 s for its 20 steps, so that the rogues come while the run goes on.
  auto fluid = run.start_dummy("fluid", endpoint, {"--busy-ms", "100"});
  auto solid = run.start_dummy("solid", endpoint);
  ASSERT_TRUE(cosph::testing::wait_for_output(*coupler, "coupling '", Clock::now() + 10s))
      << coupler->err();
  ASSERT_NO_FATAL_FAILURE(send_rogues(endpoint, true));
  ASSERT_EQ(fluid->wait_until(Clock::now()), cosph::testing::ChildProcess::kStillRunning)
      << "the run ended before the rogues came: slow the fluid down";

  const auto deadline = Clock::now() + 20s;
  EXPECT_EQ(coupler->wait_until(deadline), 0) << coupler->err();
  EXPECT_EQ(fluid->wait_until(deadline), 0) << fluid->err();
  EXPECT_EQ(solid->wait_until(deadline), 0) << solid->err();
  const std::string log = coupler->err();
  for (bool joined : {false, true})
    for (const RogueMessage& message : rogue_messages(joined))
      EXPECT_NE(log.find(message.reason), std::string::npos) << message.kind << "\n" << log;
  std::size_t refusals = 0;
  for (auto at = log.find("refused a peer"); at != std::string::npos;
       at = log.find("refused a peer", at + 1))
    ++refusals;
  EXPECT_EQ(refusals, rogue_messages(false).size() + rogue_messages(true).size()) << log;
}

}  // namespace

namespace {

// A registered solver is held to the size of its own Hello: a state of more
// particles than it announced stops the run, naming it.
TEST(RoguePeers, ARegisteredSolversOversizedStateStopsTheRunNamingIt) {
  CoupledProcesses run("oversized_state");
  run.write_case(5.0);
  const std::string endpoint = run.ipc_endpoint();
  auto coupler = run.start_coupler(endpoint);
  zmq::context_t context;
  std::vector<zmq::socket_t> solvers;
  for (const cp::Phase phase : {cp::FLUID, cp::SOLID}) {
    zmq::socket_t& socket = solvers.emplace_back(context, zmq::socket_type::dealer);
    socket.set(zmq::sockopt::linger, 0);
    socket.connect(endpoint);
    cp::send(socket, hello_of(phase, "the test's " + std::string(cp::phase_name(phase))));
  }
  for (zmq::socket_t& socket : solvers)  // once both Hellos are in
    ASSERT_TRUE(cp::receive(socket, 5000ms, "the coupler").value().has_welcome());
  // hello_of announces 10 particles; this state carries 10000.
  cp::Envelope state;
  state.mutable_state()->set_proposed_dt(1e-3);
  state.mutable_state()->set_max_smoothing_length(1e-3);
  state.mutable_state()->mutable_position()->Resize(20000, 0.0);
  cp::send(solvers[0], state);
  EXPECT_EQ(coupler->wait_until(Clock::now() + 10s), 1) << coupler->err();
  EXPECT_NE(coupler->err().find("the fluid ('the test's fluid') sent a message of"),
            std::string::npos)
      << coupler->err();
  EXPECT_NE(coupler->err().find("for the 10 particles of its Hello"), std::string::npos)
      << coupler->err();
  // The other solver hears why.
  const std::optional<cp::Envelope> error = cp::receive(solvers[1], 5000ms, "the coupler");
  ASSERT_TRUE(error && error->has_error());
  EXPECT_NE(error->error().message().find("the fluid ('the test's fluid')"), std::string::npos);
}

}  // namespace
