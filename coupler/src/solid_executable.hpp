// Which program the launcher starts for a case's solid, so that a solid
// model of your own runs without editing cosph. The case names it in
// solid.executable; without that field the built-in solver of solid.model
// runs (cosph::solid::model_executable).
#pragma once

#include <string>
#include <vector>

#include "sphcore/case_file.hpp"

namespace cosph::coupler {

// Where a bare program name (no "/") is looked up, in this order.
struct ExecutableSearch {
  std::string bin_dir;                 // the launcher's executable folder (COSPH_BIN)
  std::vector<std::string> path_dirs;  // the folders of PATH
};

// The folders of a PATH-like list ("a:b:c"); empty entries are skipped.
std::vector<std::string> split_search_path(const std::string& path);

// The program for the case's solid: a built-in name ("cosph-solid-jaumann",
// "cosph-solid-tl", found in the executable folder by the launcher) when
// solid.executable is absent, else the absolute path of the program it names:
//   - with a "/": that path, relative to the case file's folder;
//   - else the first executable file of that name in search.bin_dir, the case
//     file's folder, then search.path_dirs.
// Throws sph::ConfigError naming the file, solid.executable and the reason
// when there is no such program or it is not executable.
std::string solid_program(const sph::CaseFile& case_file, const ExecutableSearch& search);

}  // namespace cosph::coupler
