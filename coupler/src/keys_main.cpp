// cosph-keys: CURVE key pairs for a coupled run over tcp:// (docs/coupling.md,
// "Two hosts"). The launcher makes a fresh set for every tcp run; by hand:
//   cosph-keys --out DIR coupler fluid solid
// writes DIR/NAME.key (the pair: give it to that process with --keys) and
// DIR/NAME.pub (the public key: --coupler-key for the solvers, --allow-key
// for the coupler), readable by the user alone, in a folder only the user
// can enter.
#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <regex>
#include <string>
#include <vector>

#include "participant/curve_keys.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/solver_cli.hpp"

namespace {

const char* kUsage = "usage: cosph-keys --out DIR NAME [NAME ...]";

int run(int argc, char** argv) {
  std::string folder;
  std::vector<std::string> names;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      std::cout << kUsage
                << "\n\nWrites a CURVE key pair for each NAME: DIR/NAME.key (the pair, for that "
                   "process's --keys)\nand DIR/NAME.pub (its public key: --coupler-key for the "
                   "solvers, --allow-key for\nthe coupler), readable by the user alone; DIR is "
                   "made mode 0700. Earlier keys of\nthe same names are replaced. See "
                   "docs/coupling.md, \"Two hosts\".\n";
      return 0;
    }
    if (arg == "--out") {
      if (++i >= argc) throw sph::ConfigError(std::string("--out needs a value\n") + kUsage);
      folder = argv[i];
    } else if (std::regex_match(arg, std::regex("[A-Za-z0-9_-]+"))) {
      names.push_back(arg);
    } else {
      throw sph::ConfigError("'" + arg + "': a key name is letters, digits, '-' and '_'\n" +
                             kUsage);
    }
  }
  if (folder.empty() || names.empty()) throw sph::ConfigError(kUsage);
  if (!cosph::coupling::curve_available())
    throw sph::ConfigError("this ZeroMQ is built without CURVE (libsodium): no keys, no tcp runs");
  sph::make_output_dir(folder);
  if (::chmod(folder.c_str(), 0700) != 0)
    throw sph::ConfigError(
        folder + ": cannot make it the user's alone (chmod 0700): " + std::strerror(errno));
  for (const std::string& name : names)
    cosph::coupling::write_key_files(folder, name, cosph::coupling::make_key_pair());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return sph::run_guarded("cosph-keys", [&] { return run(argc, argv); });
}
