// The command line every cosph executable shares:
//   EXE --case FILE --out DIR [--set FIELD=VALUE ...] [--endpoint E] [--resume FILE]
//       [--keys FILE] [--coupler-key FILE] [--allow-key FILE ...] [--bind-any] [--help]
// and the outermost error handling: bad input exits 2, a failed run exits 1,
// each with one line "EXE: error: ..." on stderr.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace sph {

struct SolverArgs {
  std::string case_path;
  std::string out_dir;
  std::vector<std::string> overrides;
  std::string endpoint;     // empty: run alone
  std::string resume_from;  // a checkpoint (docs/restart.md); empty: from the start
  bool bind_any = false;    // the coupler may listen on a wildcard tcp address
  // CURVE key files for tcp:// (participant/curve_keys.hpp): this process's
  // pair; a solver's: the coupler's public key; the coupler's: its solvers'.
  std::string key_file, coupler_key_file;
  std::vector<std::string> allowed_key_files;
};

// Throws ConfigError on a malformed command line. Prints help and exits 0 on --help.
SolverArgs parse_solver_args(int argc, char** argv, const std::string& program,
                             const std::string& summary);

// Runs body, mapping ConfigError to exit code 2 and any other exception to 1.
int run_guarded(const std::string& program, const std::function<int()>& body);

// Creates DIR (and its parents); throws ConfigError naming it if that fails.
void make_output_dir(const std::string& dir);

}  // namespace sph
