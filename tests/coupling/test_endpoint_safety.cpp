// Where the coupler listens: a wildcard tcp address only with --bind-any,
// and an ipc:// socket that only the user can connect to, whatever the umask.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>

#include "coupled_processes.hpp"
#include "endpoint_safety.hpp"

namespace {

using cosph::coupler::binds_every_interface;
using cosph::testing::ChildProcess;
using cosph::testing::Clock;
using cosph::testing::CoupledProcesses;
using namespace std::chrono_literals;

TEST(EndpointSafety, WildcardAddressesAreKnown) {
  for (const char* wildcard :
       {"tcp://*:5555", "tcp://0.0.0.0:5555", "tcp://[::]:5555", "tcp://:::5555"})
    EXPECT_TRUE(binds_every_interface(wildcard)) << wildcard;
  for (const char* one : {"tcp://127.0.0.1:5555", "tcp://192.168.1.10:5555", "tcp://[::1]:5555",
                          "tcp://eth0:5555", "ipc:///tmp/x.sock"})
    EXPECT_FALSE(binds_every_interface(one)) << one;
}

TEST(EndpointSafety, AWildcardBindNeedsBindAny) {
  CoupledProcesses run("wildcard");
  run.write_case(1.0);
  auto refused = run.start_coupler("tcp://0.0.0.0:0");
  EXPECT_EQ(refused->wait_until(Clock::now() + 5s), 2) << refused->err();
  EXPECT_NE(refused->err().find("--bind-any"), std::string::npos) << refused->err();
  EXPECT_NE(refused->err().find("every network interface"), std::string::npos) << refused->err();
}

TEST(EndpointSafety, TheIpcSocketIsTheUsersAloneWhateverTheUmask) {
  CoupledProcesses run("ipc_mode");
  run.write_case(3.0);
  const mode_t previous = ::umask(002);  // group-writable files: the coupler must not follow it
  auto coupler = run.start_coupler(run.ipc_endpoint());
  ::umask(previous);
  const std::string socket = run.dir().file("coupler.sock");
  const auto deadline = Clock::now() + 5s;
  while (!std::filesystem::exists(socket) && Clock::now() < deadline)
    std::this_thread::sleep_for(10ms);
  struct stat status {};
  ASSERT_EQ(::stat(socket.c_str(), &status), 0) << coupler->err();
  EXPECT_EQ(status.st_mode & 077, 0u) << "mode " << std::oct << (status.st_mode & 0777);
  coupler->signal(SIGTERM);
  EXPECT_NE(coupler->wait_until(Clock::now() + 5s), ChildProcess::kStillRunning);
}

}  // namespace
