#include "zap_handler.hpp"

#include <array>
#include <chrono>
#include <iostream>
#include <vector>

namespace cosph::coupler {

ZapHandler::ZapHandler(zmq::context_t& context, std::set<std::string> allowed)
    : allowed_(std::move(allowed)), socket_(context, zmq::socket_type::rep) {
  socket_.set(zmq::sockopt::linger, 0);
  socket_.bind("inproc://zeromq.zap.01");
  thread_ = std::thread([this] { serve(); });
}

ZapHandler::~ZapHandler() {
  stop_ = true;
  thread_.join();
}

void ZapHandler::serve() {
  // Polls in slices, so that the destructor's stop is seen within one.
  while (!stop_) {
    zmq::pollitem_t item{socket_.handle(), 0, ZMQ_POLLIN, 0};
    try {
      if (zmq::poll(&item, 1, std::chrono::milliseconds(100)) > 0) answer();
    } catch (const zmq::error_t& error) {
      if (error.num() != EINTR) {
        std::cerr << "cosph-coupler: the key check stopped: " << error.what() << std::endl;
        return;
      }
    }
  }
}

// A request: version, request id, domain, address, routing id, mechanism,
// then the credentials (for CURVE: the peer's 32-byte public key).
void ZapHandler::answer() {
  std::vector<zmq::message_t> request;
  do {
    (void)socket_.recv(request.emplace_back(), zmq::recv_flags::none);
  } while (request.back().more());
  std::string key = "(none)";
  if (request.size() >= 7 && request[6].size() == 32) {
    std::array<char, 41> z85{};
    zmq_z85_encode(z85.data(), static_cast<const std::uint8_t*>(request[6].data()), 32);
    key = z85.data();
  }
  const std::string address = request.size() > 3 ? request[3].to_string() : "?";
  const bool admitted =
      request.size() >= 7 && request[5].to_string() == "CURVE" && allowed_.count(key) != 0;
  if (!admitted)
    std::cerr << "cosph-coupler: refused a peer at " << address << ": its CURVE key " << key
              << " is not one of this run's solvers' (--allow-key); the run goes on" << std::endl;
  const std::array<std::string, 6> reply{"1.0",
                                         request.size() > 1 ? request[1].to_string() : "",
                                         admitted ? "200" : "400",
                                         admitted ? "OK" : "not one of this run's keys",
                                         admitted ? key : "",
                                         ""};
  for (std::size_t i = 0; i < reply.size(); ++i)
    socket_.send(zmq::buffer(reply[i]),
                 i + 1 < reply.size() ? zmq::send_flags::sndmore : zmq::send_flags::none);
}

}  // namespace cosph::coupler
