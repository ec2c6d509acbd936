// The file of an ipc:// endpoint a process bound, removed when this object
// is destroyed. ZeroMQ removes the file only when it chose the name itself,
// so every coupled run left its coupler.sock in the output folder (and every
// benchmark its socket in /tmp). Declare it before the zmq::context_t, so that
// it is destroyed after the socket and the context are closed.
#pragma once

#include <filesystem>
#include <string_view>
#include <system_error>

namespace cosph::coupling {

class BoundIpcFile {
 public:
  BoundIpcFile() = default;
  BoundIpcFile(const BoundIpcFile&) = delete;
  BoundIpcFile& operator=(const BoundIpcFile&) = delete;
  ~BoundIpcFile() {
    std::error_code ignored;  // already gone, or never made: nothing to do
    if (!path_.empty()) std::filesystem::remove(path_, ignored);
  }

  // Call once the bind has succeeded; other transports have no file.
  void bound(std::string_view endpoint) {
    constexpr std::string_view kIpc = "ipc://";
    if (!endpoint.starts_with(kIpc)) return;
    endpoint.remove_prefix(kIpc.size());
    if (!endpoint.starts_with('@')) path_ = endpoint;  // '@': Linux's abstract names, no file
  }

 private:
  std::filesystem::path path_;
};

}  // namespace cosph::coupling
