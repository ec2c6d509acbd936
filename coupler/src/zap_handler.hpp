// Who may join a run over CURVE: ZeroMQ asks a ZAP handler (ZeroMQ RFC 27)
// about every peer that completed the CURVE handshake, which proves it holds
// the secret key of the public key it shows. This handler admits the run's
// solvers' public keys alone, and logs every peer it refuses; the run goes
// on. (A peer with a wrong key for the coupler fails the handshake itself,
// before any ZAP request.)
#pragma once

#include <atomic>
#include <set>
#include <string>
#include <thread>
#include <zmq.hpp>

namespace cosph::coupler {

class ZapHandler {
 public:
  // Serves `context`'s ZAP requests from a thread of its own until destroyed.
  // Create it before the socket it guards binds. allowed: Z85 public keys.
  ZapHandler(zmq::context_t& context, std::set<std::string> allowed);
  ~ZapHandler();
  ZapHandler(const ZapHandler&) = delete;
  ZapHandler& operator=(const ZapHandler&) = delete;

 private:
  void serve();
  void answer();

  std::set<std::string> allowed_;
  zmq::socket_t socket_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace cosph::coupler
