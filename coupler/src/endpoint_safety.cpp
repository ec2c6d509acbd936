#include "endpoint_safety.hpp"

#include <array>
#include <string_view>

#include "sphcore/case_file.hpp"

namespace cosph::coupler {

bool binds_every_interface(const std::string& endpoint) {
  constexpr std::string_view kTcp = "tcp://";
  std::string_view address(endpoint);
  if (!address.starts_with(kTcp)) return false;
  address.remove_prefix(kTcp.size());
  const auto port = address.rfind(':');
  if (port == std::string_view::npos) return false;
  address = address.substr(0, port);
  constexpr std::array<std::string_view, 5> kWildcards{"*", "0.0.0.0", "[::]", "::", "[*]"};
  for (std::string_view wildcard : kWildcards)
    if (address == wildcard) return true;
  return false;
}

void check_bind_address(const std::string& endpoint, bool bind_any) {
  if (bind_any || !binds_every_interface(endpoint)) return;
  throw sph::ConfigError(
      "--endpoint " + endpoint +
      ": listens on every network interface, where any host that reaches the port can try to "
      "join the run; give the address of one interface (e.g. tcp://192.168.1.10:5555), or add "
      "--bind-any if every interface is meant");
}

}  // namespace cosph::coupler
