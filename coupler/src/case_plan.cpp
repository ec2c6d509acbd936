// cosph-case: checks a case file before anything runs, and tells the launcher
// which processes the case needs.
//   cosph-case plan CASE [--set FIELD=VALUE ...]
// prints one line, the executables in start order: "cosph-fluid" for water
// alone, "cosph-solid" for a solid alone, "cosph-coupler cosph-fluid
// cosph-solid" for a coupled case ("cosph-solid-tl" instead of "cosph-solid"
// when solid.model is "total_lagrangian").
#include <iostream>
#include <string>
#include <vector>

#include "fluid_parameters.hpp"
#include "fluid_scene.hpp"
#include "solid_parameters.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/run_parameters.hpp"
#include "sphcore/solver_cli.hpp"

namespace {

const char* kUsage = "usage: cosph-case plan CASE [--set FIELD=VALUE ...]";

int plan(int argc, char** argv) {
  if (argc >= 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h")) {
    std::cout << kUsage << "\n\nValidates the case and prints the executables it needs.\n";
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
  if (fluid) {
    const auto parameters = cosph::fluid::read_fluid_parameters(case_file);
    cosph::fluid::check_walls_close(case_file, parameters);
  }
  // The solid's executable follows its model (solid.model).
  const std::string solid_exe =
      solid ? cosph::solid::model_executable(cosph::solid::read_solid_parameters(case_file).model)
            : "";
  if (fluid && solid) {
    std::cout << "cosph-coupler cosph-fluid " << solid_exe << "\n";
  } else {
    std::cout << (fluid ? std::string("cosph-fluid") : solid_exe) << "\n";
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return sph::run_guarded("cosph-case", [&] { return plan(argc, argv); });
}
