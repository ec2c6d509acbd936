// cosph-bench-messaging: the time of one coupling round trip, as a solver and
// the coupler pay it every step: the solver serialises its interface state and
// sends it, the coupler receives and parses it and answers with one
// acceleration per particle, which the solver receives and parses. Two
// processes over ZeroMQ ipc, as the launcher runs them. Not a test: run
//   build/bin/cosph-bench-messaging [--round-trips N]
// It prints a table; scripts/benchmark.py turns it into docs/results/messaging.md.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>
#include <zmq.hpp>

#include "participant/bound_ipc_file.hpp"
#include "participant/protocol.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/solver_cli.hpp"

namespace {

namespace cp = cosph::coupling;
using Clock = std::chrono::steady_clock;

constexpr std::chrono::milliseconds kTimeout{10000};
const std::vector<int> kSizes{0, 100, 1000, 5000};  // interface particles per message

sph::InterfaceParticles interface_of(int size) {
  sph::InterfaceParticles particles;
  for (int k = 0; k < size; ++k) {
    const double s = 1e-3 * k;
    particles.add(k, sph::Vec2(s, 2 * s), sph::Vec2(-s, s), sph::Mat2::Constant(1e3 * s), 1e-3,
                  1000.0 + s, 1.3e-3, 20.0);
  }
  return particles;
}

// The coupler's side: answer every state with one acceleration per particle.
void serve(const std::string& endpoint, int round_trips) {
  cp::BoundIpcFile socket_file;
  zmq::context_t context;
  zmq::socket_t socket(context, zmq::socket_type::router);
  // Until the last answer is out: closing drops what is still queued.
  socket.set(zmq::sockopt::linger, static_cast<int>(kTimeout.count()));
  socket.bind(endpoint);
  socket_file.bound(endpoint);
  for (std::size_t s = 0; s < kSizes.size(); ++s)
    for (int r = 0; r <= round_trips; ++r) {  // the first is a warm-up
      const std::optional<cp::Routed> message = cp::receive_routed(socket, kTimeout);
      if (!message) throw cp::CouplingError("the solver's side went quiet");
      const sph::InterfaceParticles particles = cp::from_proto(message->envelope.state());
      cp::Envelope reply;
      cp::CouplingStep& step = *reply.mutable_step();
      step.set_step(static_cast<std::uint64_t>(r));
      step.set_dt(1e-5);
      step.mutable_acceleration()->Resize(2 * static_cast<int>(particles.size()), 1.0);
      cp::send_to(socket, message->identity, reply);
    }
}

// The solver's side: returns the median round trip in seconds for each size.
std::vector<double> time_round_trips(const std::string& endpoint, int round_trips) {
  zmq::context_t context;
  zmq::socket_t socket(context, zmq::socket_type::dealer);
  socket.set(zmq::sockopt::linger, 0);
  socket.connect(endpoint);
  std::vector<double> medians;
  for (const int size : kSizes) {
    const sph::InterfaceParticles particles = interface_of(size);
    std::vector<double> seconds;
    for (int r = 0; r <= round_trips; ++r) {
      const auto start = Clock::now();
      cp::Envelope envelope;
      cp::InterfaceState& state = *envelope.mutable_state();
      state.set_step(static_cast<std::uint64_t>(r));
      cp::to_proto(particles, state);
      cp::send(socket, envelope);
      const std::optional<cp::Envelope> reply = cp::receive(socket, kTimeout, "the coupler");
      if (!reply)
        throw cp::CouplingError(
            "no answer from the coupler's side within " + std::to_string(kTimeout.count()) +
            " ms, at " + std::to_string(size) + " particles, round trip " + std::to_string(r));
      if (reply->step().acceleration_size() != 2 * size)
        throw cp::CouplingError("the coupler's side answered with " +
                                std::to_string(reply->step().acceleration_size()) +
                                " accelerations for " + std::to_string(size) + " particles");
      if (r > 0) seconds.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    }
    std::nth_element(seconds.begin(), seconds.begin() + seconds.size() / 2, seconds.end());
    medians.push_back(seconds[seconds.size() / 2]);
  }
  return medians;
}

int bench(int argc, char** argv) {
  // Both processes keep freed memory, as the coupler does and as a solver's
  // large heap does by itself: a fresh process with a small heap would hand
  // every message's pages back to the system and fault them in again, which
  // on this VM made the round trip at 1000 particles five times as long.
  cp::keep_freed_memory();  // before the fork: both processes
  int round_trips = 2000;
  for (int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    if (option == "--round-trips" && i + 1 < argc) {
      round_trips = std::max(1, std::stoi(argv[++i]));
    } else if (option == "--help" || option == "-h") {
      std::printf(
          "usage: cosph-bench-messaging [--round-trips N]\n\n"
          "The median time of one coupling round trip (a solver's interface state to the\n"
          "coupler and one acceleration per particle back, serialised, sent over ZeroMQ ipc\n"
          "between two processes and parsed) at 0, 100, 1000 and 5000 interface particles.\n"
          "Not a test.\n");
      return 0;
    } else {
      throw sph::ConfigError("usage: cosph-bench-messaging [--round-trips N]");
    }
  }
  const std::string endpoint = "ipc:///tmp/cosph-bench-messaging-" + std::to_string(getpid());
  const pid_t coupler = fork();
  if (coupler < 0) throw sph::ConfigError("cannot start the coupler's process");
  if (coupler == 0) {
    // The child never returns into the parent's code: it exits here.
    int status = 0;
    try {
      serve(endpoint, round_trips);
    } catch (const std::exception& error) {
      std::fprintf(stderr, "cosph-bench-messaging: coupler's side: %s\n", error.what());
      status = 1;
    }
    std::_Exit(status);
  }
  std::vector<double> medians;
  try {
    medians = time_round_trips(endpoint, round_trips);
  } catch (...) {
    kill(coupler, SIGKILL);
    waitpid(coupler, nullptr, 0);
    throw;
  }
  int status = 0;
  waitpid(coupler, &status, 0);
  std::printf("%-22s %18s\n", "interface particles", "round trip (ms)");
  for (std::size_t s = 0; s < kSizes.size(); ++s)
    std::printf("%-22d %18.4f\n", kSizes[s], 1e3 * medians[s]);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  return sph::run_guarded("cosph-bench-messaging", [&] { return bench(argc, argv); });
}
