// CURVE keys (ZeroMQ's elliptic-curve encryption and authentication,
// CurveZMQ) for coupled runs over tcp://. Each process has a key pair; the
// coupler takes only the public keys it was given (--allow-key), and each
// solver checks that it speaks to the coupler whose public key it was given
// (--coupler-key). Keys are Z85 text, 40 characters.
//
// Files: NAME.key holds a pair, NAME.pub the public key alone, one line each
// "public-key = KEY", "secret-key = KEY", written readable by the user alone.
#pragma once

#include <string>
#include <vector>

namespace zmq {
class socket_t;
}

namespace cosph::coupling {

struct KeyPair {
  std::string public_key, secret_key;
};

// Whether this ZeroMQ was built with CURVE (libsodium).
bool curve_available();

KeyPair make_key_pair();

// Writes FOLDER/NAME.key and FOLDER/NAME.pub, mode 0600, replacing earlier ones.
// Throws sph::ConfigError naming the file if it cannot.
void write_key_files(const std::string& folder, const std::string& name, const KeyPair& keys);

// Throw sph::ConfigError naming the file and the reason: unreadable, a key
// missing or not 40 Z85 characters, a public key that is not the secret's.
KeyPair read_key_pair(const std::string& path);
std::string read_public_key(const std::string& path);

// What a process was given on its command line.
struct CurveKeyFiles {
  std::string own;                   // --keys: this process's pair
  std::string coupler;               // --coupler-key: a solver's, the coupler's public key
  std::vector<std::string> allowed;  // --allow-key: the coupler's, its solvers' public keys
  bool given() const { return !own.empty(); }
};

// Throws sph::ConfigError if a tcp:// endpoint comes without keys, or the
// keys a process of this role (`coupler`, else a solver) needs are missing.
void check_key_files(const std::string& endpoint, const CurveKeyFiles& files, bool coupler);

// Before connect: a solver's socket speaks CURVE with `files`' keys, and
// only to the coupler of files.coupler. Nothing without keys.
void use_client_keys(zmq::socket_t& socket, const CurveKeyFiles& files);
// Before bind: the coupler's socket speaks CURVE with its pair `files.own`;
// who may join is the ZAP handler's decision (coupler/src/zap_handler.hpp).
void use_server_keys(zmq::socket_t& socket, const CurveKeyFiles& files);

}  // namespace cosph::coupling
