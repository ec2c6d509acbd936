// receive() over a real ZeroMQ socket pair: a spinning receive still returns
// as soon as the message is in, still sleeps on when the spin is over, and
// never waits past its timeout, however long the spin.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>
#include <zmq.hpp>

#include "participant/protocol.hpp"

namespace {

namespace cp = cosph::coupling;
using Clock = std::chrono::steady_clock;
using std::chrono::microseconds;
using std::chrono::milliseconds;

struct SocketPair {
  zmq::context_t context;
  zmq::socket_t receiver{context, zmq::socket_type::pair};
  zmq::socket_t sender{context, zmq::socket_type::pair};
  SocketPair() {
    receiver.bind("inproc://receive-test");
    sender.connect("inproc://receive-test");
  }
  // Sends a step message from a thread of its own after `delay`.
  std::thread send_after(milliseconds delay) {
    return std::thread([this, delay] {
      std::this_thread::sleep_for(delay);
      cp::Envelope message;
      message.mutable_step()->set_step(7);
      cp::send(sender, message);
    });
  }
};

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

TEST(Receive, ASpinningReceiveReturnsAsSoonAsTheMessageIsIn) {
  SocketPair sockets;
  std::thread sender = sockets.send_after(milliseconds(5));
  const auto start = Clock::now();
  const auto message =
      cp::receive(sockets.receiver, milliseconds(5000), "the test", milliseconds(2000));
  const double waited = seconds_since(start);
  sender.join();
  ASSERT_TRUE(message.has_value());
  EXPECT_EQ(message->step().step(), 7u);
  EXPECT_LT(waited, 1.0) << "the receive spun on after the message came";
}

TEST(Receive, AMessageThatComesAfterTheSpinIsStillReceived) {
  SocketPair sockets;
  std::thread sender = sockets.send_after(milliseconds(50));
  const auto message =
      cp::receive(sockets.receiver, milliseconds(5000), "the test", microseconds(100));
  sender.join();
  ASSERT_TRUE(message.has_value());
  EXPECT_EQ(message->step().step(), 7u);
}

TEST(Receive, TheSpinNeverOutlastsTheTimeout) {
  SocketPair sockets;
  const auto start = Clock::now();
  const auto message =
      cp::receive(sockets.receiver, milliseconds(20), "the test", milliseconds(3000));
  const double waited = seconds_since(start);
  EXPECT_FALSE(message.has_value());
  EXPECT_GE(waited, 0.019);
  EXPECT_LT(waited, 1.5) << "the receive spun past its timeout";
}

}  // namespace
