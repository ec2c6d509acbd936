// Coupled runs over tcp:// with CURVE keys: cosph-keys writes key files only
// the user can read; a run needs them; the coupler admits the run's solvers'
// keys alone, logs a peer with other keys as refused, and the run goes on;
// a solver given the wrong coupler key never gets in.
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>

#include "coupled_processes.hpp"
#include "participant/curve_keys.hpp"
#include "sphcore/case_file.hpp"

namespace {

namespace cp = cosph::coupling;
using cosph::testing::ChildProcess;
using cosph::testing::Clock;
using cosph::testing::CoupledProcesses;
using namespace std::chrono_literals;

// A tcp port on the loopback interface that nothing listens on now.
int free_tcp_port() {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t length = sizeof(address);
  if (::bind(fd, reinterpret_cast<sockaddr*>(&address), length) != 0 ||
      ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) != 0)
    throw std::runtime_error("no free tcp port");
  ::close(fd);
  return ntohs(address.sin_port);
}

mode_t mode_of(const std::string& path) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) throw std::runtime_error(path + ": missing");
  return status.st_mode & 0777;
}

class CurveRun : public ::testing::Test {
 protected:
  void SetUp() override {
    run_.write_case(5.0);
    ChildProcess keys({COSPH_BIN_DIR "/cosph-keys", "--out", key("").substr(0, key("").size() - 1),
                       "coupler", "fluid", "solid", "rogue"},
                      run_.dir().file("keys_log"));
    ASSERT_EQ(keys.wait_until(Clock::now() + 10s), 0) << keys.err();
  }
  std::string key(const std::string& file) const { return run_.dir().file("keys/" + file); }
  std::vector<std::string> coupler_keys() const {
    return {"--keys",         key("coupler.key"), "--allow-key",
            key("fluid.pub"), "--allow-key",      key("solid.pub")};
  }
  std::vector<std::string> solver_keys(const std::string& name,
                                       const std::string& coupler = "coupler") const {
    return {"--keys", key(name + ".key"), "--coupler-key", key(coupler + ".pub")};
  }

  CoupledProcesses run_{"curve"};
  const std::string endpoint_ = "tcp://127.0.0.1:" + std::to_string(free_tcp_port());
};

TEST_F(CurveRun, KeyFilesAreTheUsersAloneAndReadBack) {
  EXPECT_EQ(mode_of(run_.dir().file("keys")), 0700u);
  for (const char* name : {"coupler", "fluid", "solid"}) {
    const std::string pair = key(std::string(name) + ".key"), pub = key(std::string(name) + ".pub");
    EXPECT_EQ(mode_of(pair), 0600u) << pair;
    EXPECT_EQ(mode_of(pub), 0600u) << pub;
    const cp::KeyPair keys = cp::read_key_pair(pair);
    EXPECT_EQ(keys.public_key, cp::read_public_key(pub));
    EXPECT_NE(keys.public_key, keys.secret_key);
  }
  EXPECT_NE(cp::read_public_key(key("fluid.pub")), cp::read_public_key(key("solid.pub")));
  // A pair whose public key is another's is refused, naming the file.
  std::ofstream(key("mixed.key")) << "public-key = " << cp::read_public_key(key("fluid.pub"))
                                  << "\nsecret-key = "
                                  << cp::read_key_pair(key("solid.key")).secret_key << "\n";
  try {
    cp::read_key_pair(key("mixed.key"));
    FAIL() << "a mixed pair was taken";
  } catch (const sph::ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find(key("mixed.key") + ": public-key is not"),
              std::string::npos)
        << error.what();
  }
}

TEST_F(CurveRun, TcpWithoutKeysIsRefused) {
  auto coupler = run_.start_coupler(endpoint_);
  EXPECT_EQ(coupler->wait_until(Clock::now() + 5s), 2) << coupler->err();
  EXPECT_NE(coupler->err().find("--allow-key"), std::string::npos) << coupler->err();
  auto fluid = run_.start_dummy("fluid", endpoint_);
  EXPECT_EQ(fluid->wait_until(Clock::now() + 5s), 2) << fluid->err();
  EXPECT_NE(fluid->err().find("--coupler-key"), std::string::npos) << fluid->err();
}

TEST_F(CurveRun, OnlyTheRunsKeysJoinAndARefusedPeerIsLoggedWhileTheRunGoesOn) {
  auto coupler = run_.start_coupler(endpoint_, coupler_keys());
  // With keys of its own but not the run's: refused by the coupler.
  auto stranger = run_.start_dummy("solid", endpoint_, solver_keys("rogue"));
  // With the right keys but the wrong coupler's: its handshake fails.
  auto misled = run_.start_dummy("solid", endpoint_, solver_keys("solid", "rogue"));
  // No keys at all: a plain ZeroMQ peer, which the CURVE socket does not hear.
  zmq::context_t context;
  zmq::socket_t plain(context, zmq::socket_type::dealer);
  plain.set(zmq::sockopt::linger, 0);
  plain.connect(endpoint_);
  cp::send(plain, cosph::testing::hello_of(cp::SOLID, "plain rogue"));

  const std::string stranger_key = cp::read_public_key(key("rogue.pub"));
  const std::string refusal = "refused a peer at 127.0.0.1: its CURVE key " + stranger_key +
                              " is not one of this run's solvers'";
  ASSERT_TRUE(cosph::testing::wait_for_output(*coupler, refusal, Clock::now() + 10s, true))
      << coupler->err();

  auto fluid = run_.start_dummy("fluid", endpoint_, solver_keys("fluid"));
  auto solid = run_.start_dummy("solid", endpoint_, solver_keys("solid"));
  const auto deadline = Clock::now() + 20s;
  EXPECT_EQ(coupler->wait_until(deadline), 0) << coupler->err();
  EXPECT_EQ(fluid->wait_until(deadline), 0) << fluid->err();
  EXPECT_EQ(solid->wait_until(deadline), 0) << solid->err();
  // Refused once, not at every reconnection.
  const std::string log = coupler->err();
  EXPECT_EQ(log.find(refusal, log.find(refusal) + 1), std::string::npos) << log;
  EXPECT_NE(coupler->out().find("coupling 'cosph-dummy (fluid)' and 'cosph-dummy (solid)'"),
            std::string::npos)
      << coupler->out();
  EXPECT_FALSE(cp::receive(plain, 100ms, "the coupler").has_value());
  for (ChildProcess* rogue : {stranger.get(), misled.get()}) {
    rogue->signal(SIGTERM);
    EXPECT_NE(rogue->wait_until(Clock::now() + 5s), 0) << rogue->err();
  }
}

}  // namespace
