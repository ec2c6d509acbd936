// cosph-coupler and cosph-dummy solvers as real processes in a scratch
// folder, for the tests of who may join a run: a short coupled case, the
// coupler on an endpoint, and raw DEALER sockets that play rogue peers.
#pragma once

#include <chrono>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>
#include <zmq.hpp>

#include "child_process.hpp"
#include "participant/protocol.hpp"
#include "test_support.hpp"

namespace cosph::testing {

class CoupledProcesses {
 public:
  explicit CoupledProcesses(const std::string& label) : dir_(label) {}

  void write_case(double timeout) {
    std::ostringstream text;
    text << "run { end_time: 0.02 output_interval: 0.0005 snapshot_interval: 0.02 }\n"
         << "fluid { spacing: 0.001 density: 1000 }\nsolid { spacing: 0.001 }\n"
         << "coupling { timeout: " << timeout << " }\n";
    write_text(dir_.file("case.pbtxt"), text.str());
    timeout_ = timeout;
  }

  std::string ipc_endpoint() const { return "ipc://" + dir_.file("coupler.sock"); }
  const ScratchDir& dir() const { return dir_; }

  std::unique_ptr<ChildProcess> start_coupler(const std::string& endpoint,
                                              std::vector<std::string> extra = {}) {
    std::vector<std::string> argv{COSPH_BIN_DIR "/cosph-coupler",
                                  "--case",
                                  dir_.file("case.pbtxt"),
                                  "--out",
                                  dir_.file("out"),
                                  "--endpoint",
                                  endpoint};
    argv.insert(argv.end(), extra.begin(), extra.end());
    return std::make_unique<ChildProcess>(argv, dir_.file("coupler"));
  }

  // A dummy solver; `extra` may slow it (--busy-ms) or give it keys.
  std::unique_ptr<ChildProcess> start_dummy(const std::string& phase, const std::string& endpoint,
                                            std::vector<std::string> extra = {}) {
    std::vector<std::string> argv{COSPH_BIN_DIR "/cosph-dummy",
                                  "--phase",
                                  phase,
                                  "--endpoint",
                                  endpoint,
                                  "--out",
                                  dir_.file("out"),
                                  "--timeout",
                                  std::to_string(timeout_)};
    argv.insert(argv.end(), extra.begin(), extra.end());
    return std::make_unique<ChildProcess>(argv, dir_.file(phase + std::to_string(started_++)));
  }

 private:
  ScratchDir dir_;
  double timeout_ = 10.0;
  int started_ = 0;
};

// Waits until `text` appears in what `process` wrote to stdout (or stderr),
// or the deadline passes.
inline bool wait_for_output(const ChildProcess& process, const std::string& text,
                            Clock::time_point deadline, bool on_stderr = false) {
  while (Clock::now() < deadline) {
    if ((on_stderr ? process.err() : process.out()).find(text) != std::string::npos) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

// A Hello as a solver sends it.
inline coupling::Envelope hello_of(coupling::Phase phase, const std::string& solver,
                                   unsigned version = coupling::kProtocolVersion) {
  coupling::Envelope hello;
  hello.mutable_hello()->set_protocol_version(version);
  hello.mutable_hello()->set_phase(phase);
  hello.mutable_hello()->set_solver(solver);
  hello.mutable_hello()->set_particle_count(10);
  hello.mutable_hello()->set_max_smoothing_length(1e-3);
  return hello;
}

}  // namespace cosph::testing
