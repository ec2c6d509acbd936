// Where the coupler may listen. A wildcard tcp address listens on every
// network interface, so any host that reaches the port can try to join: it
// needs an explicit --bind-any. An ipc:// socket is made under umask 077, so
// that only the user can connect to it, whatever the user's umask.
#pragma once

#include <sys/stat.h>

#include <string>

namespace cosph::coupler {

// Whether `endpoint` is tcp:// on every interface (*, 0.0.0.0, [::], ::).
bool binds_every_interface(const std::string& endpoint);

// Throws sph::ConfigError for a wildcard tcp endpoint without --bind-any.
void check_bind_address(const std::string& endpoint, bool bind_any);

// umask 077 for as long as it lives: files made meanwhile are the user's alone.
class PrivateUmask {
 public:
  PrivateUmask() : previous_(::umask(077)) {}
  ~PrivateUmask() { ::umask(previous_); }
  PrivateUmask(const PrivateUmask&) = delete;
  PrivateUmask& operator=(const PrivateUmask&) = delete;

 private:
  mode_t previous_;
};

}  // namespace cosph::coupler
