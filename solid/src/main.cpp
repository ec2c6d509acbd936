// cosph-solid: the SPH linear elastic solid solver (Gray, Monaghan & Swift
// 2001). Runs a case alone when the case has no fluid; coupled runs come
// through the coupler.
#include "solid_program.hpp"
#include "solid_solver.hpp"

int main(int argc, char** argv) {
  using cosph::solid::SolidParameters;
  using cosph::solid::SolidSolver;
  const cosph::solid::SolidProgram<SolidSolver> program{
      .name = "cosph-solid",
      .about = "SPH linear elastic solid solver (SPEC.md \"Solid\").",
      .model = cosph::solid::SolidModel::jaumann,
      .protocol_name = "cosph-solid (jaumann)",
      .summary = [](const SolidSolver&, const SolidParameters& parameters) -> std::string {
        return parameters.artificial_stress.enabled ? "artificial stress on"
                                                    : "artificial stress off";
      }};
  return cosph::solid::run_solid_program(argc, argv, program);
}
