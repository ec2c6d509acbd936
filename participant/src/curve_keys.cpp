#include "participant/curve_keys.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <zmq.hpp>

#include "sphcore/case_file.hpp"

namespace cosph::coupling {

namespace {

constexpr std::size_t kZ85KeyLength = 40;

bool is_z85_key(const std::string& key) {
  std::array<std::uint8_t, 32> binary{};
  return key.size() == kZ85KeyLength && zmq_z85_decode(binary.data(), key.c_str()) != nullptr;
}

// The value of the line "NAME = VALUE", or empty.
std::string field(const std::string& path, const std::string& name) {
  std::ifstream in(path);
  if (!in) throw sph::ConfigError(path + ": cannot read key file: " + std::strerror(errno));
  for (std::string line; std::getline(in, line);) {
    const auto equals = line.find('=');
    if (equals == std::string::npos) continue;
    auto trim = [](std::string text) {
      const auto first = text.find_first_not_of(" \t\r\"");
      const auto last = text.find_last_not_of(" \t\r\"");
      return first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
    };
    if (trim(line.substr(0, equals)) == name) return trim(line.substr(equals + 1));
  }
  return {};
}

std::string key_field(const std::string& path, const std::string& name) {
  const std::string key = field(path, name);
  if (key.empty())
    throw sph::ConfigError(path + ": " + name + ": missing (cosph-keys writes key files)");
  if (!is_z85_key(key))
    throw sph::ConfigError(path + ": " + name + ": not a CURVE key (40 Z85 characters), got '" +
                           key + "'");
  return key;
}

void write_private(const std::string& path, const std::string& text) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  if (fd < 0) throw sph::ConfigError(path + ": cannot write key file: " + std::strerror(errno));
  // An older file keeps its mode through O_TRUNC: make it the user's alone.
  bool written = ::fchmod(fd, 0600) == 0 &&
                 ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
  const int error = errno;
  written = ::close(fd) == 0 && written;
  if (!written) throw sph::ConfigError(path + ": cannot write key file: " + std::strerror(error));
}

// Z85 text with its terminating NUL: the form ZeroMQ takes as text.
void set_key(zmq::socket_t& socket, int option, const std::string& key) {
  if (zmq_setsockopt(socket.handle(), option, key.c_str(), key.size() + 1) != 0)
    throw zmq::error_t();
}

}  // namespace

bool curve_available() {
  return zmq_has("curve") != 0;
}

KeyPair make_key_pair() {
  std::array<char, kZ85KeyLength + 1> public_key{}, secret_key{};
  if (zmq_curve_keypair(public_key.data(), secret_key.data()) != 0)
    throw sph::ConfigError(std::string("cannot make a CURVE key pair: ") +
                           zmq_strerror(zmq_errno()) + " (is ZeroMQ built with libsodium?)");
  return {public_key.data(), secret_key.data()};
}

void write_key_files(const std::string& folder, const std::string& name, const KeyPair& keys) {
  const std::string base = folder + "/" + name;
  write_private(base + ".pub", "public-key = " + keys.public_key + "\n");
  write_private(base + ".key",
                "public-key = " + keys.public_key + "\nsecret-key = " + keys.secret_key + "\n");
}

KeyPair read_key_pair(const std::string& path) {
  KeyPair keys{key_field(path, "public-key"), key_field(path, "secret-key")};
  std::array<char, kZ85KeyLength + 1> derived{};
  if (zmq_curve_public(derived.data(), keys.secret_key.c_str()) != 0 ||
      keys.public_key != derived.data())
    throw sph::ConfigError(path + ": public-key is not the public key of its secret-key");
  return keys;
}

std::string read_public_key(const std::string& path) {
  return key_field(path, "public-key");
}

void check_key_files(const std::string& endpoint, const CurveKeyFiles& files, bool coupler) {
  const std::string needed = coupler ? "--keys FILE (the coupler's key pair) and --allow-key FILE "
                                       "(each solver's public key)"
                                     : "--keys FILE (this solver's key pair) and --coupler-key "
                                       "FILE (the coupler's public key)";
  const bool tcp = endpoint.rfind("tcp://", 0) == 0;
  const bool complete =
      files.given() && (coupler ? !files.allowed.empty() : !files.coupler.empty());
  if (complete || (!tcp && files.own.empty() && files.coupler.empty() && files.allowed.empty()))
    return;
  throw sph::ConfigError(
      "--endpoint " + endpoint + ": " +
      (tcp ? "a run over tcp is encrypted, and joined only by processes with the run's keys: "
           : "incomplete keys: ") +
      "give " + needed + "; cosph-keys makes them (docs/coupling.md, \"Two hosts\")");
}

}  // namespace cosph::coupling

namespace cosph::coupling {

void use_client_keys(zmq::socket_t& socket, const CurveKeyFiles& files) {
  if (!files.given()) return;
  const KeyPair own = read_key_pair(files.own);
  set_key(socket, ZMQ_CURVE_SERVERKEY, read_public_key(files.coupler));
  set_key(socket, ZMQ_CURVE_PUBLICKEY, own.public_key);
  set_key(socket, ZMQ_CURVE_SECRETKEY, own.secret_key);
}

void use_server_keys(zmq::socket_t& socket, const CurveKeyFiles& files) {
  if (!files.given()) return;
  const KeyPair own = read_key_pair(files.own);
  socket.set(zmq::sockopt::curve_server, true);
  set_key(socket, ZMQ_CURVE_SECRETKEY, own.secret_key);
  socket.set(zmq::sockopt::zap_domain, "cosph");
}

}  // namespace cosph::coupling
