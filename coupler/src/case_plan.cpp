// cosph-case: checks a case file before anything runs, and tells the launcher
// which processes the case needs.
//   cosph-case plan CASE [--set FIELD=VALUE ...]
// prints the executables in start order, one per line: "cosph-fluid" for
// water alone, the solid's program for a solid alone, "cosph-coupler",
// "cosph-fluid" and the solid's program for a coupled case. The solid's
// program is "cosph-solid-jaumann" or "cosph-solid-tl" after solid.model, or the
// absolute path of the program solid.executable names (solid_executable.hpp).
// A multi-rate coupled case (coupling.max_substeps > 1, or 0 and multi-rate
// chosen by substep_choice.hpp; the solid at its own step) ends with a line
// "separate-cores": the launcher then gives each solver cores of its own
// (docs/coupling.md, "Multi-rate coupling").
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "coupler_settings.hpp"
#include "fluid_parameters.hpp"
#include "fluid_scene.hpp"
#include "solid_executable.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/particle_budget.hpp"
#include "sphcore/region_reader.hpp"
#include "sphcore/run_parameters.hpp"
#include "sphcore/solver_cli.hpp"

namespace {

const char* kUsage = "usage: cosph-case plan CASE [--set FIELD=VALUE ...]";

// Where a bare solid.executable is looked up: the launcher's executable folder
// (COSPH_BIN; unset, the folder of this program, which the launcher started
// from there), then the case's folder, then PATH.
cosph::coupler::ExecutableSearch executable_search() {
  cosph::coupler::ExecutableSearch search;
  const char* bin = std::getenv("COSPH_BIN");
  std::error_code error;
  if (bin != nullptr && *bin != '\0')
    search.bin_dir = bin;
  else
    search.bin_dir = std::filesystem::read_symlink("/proc/self/exe", error).parent_path().string();
  const char* path = std::getenv("PATH");
  search.path_dirs = cosph::coupler::split_search_path(path != nullptr ? path : "");
  return search;
}

int plan(int argc, char** argv) {
  if (argc >= 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h")) {
    std::cout << kUsage
              << "\n\nValidates the case and prints the executables it needs, one per line.\n";
    return 0;
  }
  if (argc < 3 || std::string(argv[1]) != "plan") throw sph::ConfigError(kUsage);
  std::vector<std::string> overrides;
  for (int i = 3; i < argc; ++i) {
    if (std::string(argv[i]) != "--set" || i + 1 >= argc) throw sph::ConfigError(kUsage);
    overrides.push_back(argv[++i]);
  }
  const sph::CaseFile case_file = sph::load_case(argv[2], overrides);
  sph::read_run_parameters(case_file);
  const bool fluid = case_file.config.has_fluid(), solid = case_file.config.has_solid();
  sph::require(fluid || solid, case_file, "fluid, solid", "the case has neither");
  sph::check_regions(case_file);
  sph::check_particle_budget(case_file);
  if (fluid) {
    const auto parameters = cosph::fluid::read_fluid_parameters(case_file);
    cosph::fluid::check_walls_close(case_file, parameters);
  }
  // The coupler's own fields too, so that a bad one stops the run before
  // any process starts.
  const bool separate_cores = fluid && solid && [&] {
    const auto settings = cosph::coupler::read_coupler_settings(case_file);
    return settings.stepping.max_substeps > 1 && !settings.solid_at_fluid_step;
  }();
  std::vector<std::string> programs;
  if (fluid && solid) programs = {"cosph-coupler", "cosph-fluid"};
  if (fluid && !solid) programs = {"cosph-fluid"};
  if (solid) programs.push_back(cosph::coupler::solid_program(case_file, executable_search()));
  for (const std::string& program : programs) std::cout << program << "\n";
  if (separate_cores) std::cout << "separate-cores\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return sph::run_guarded("cosph-case", [&] { return plan(argc, argv); });
}
