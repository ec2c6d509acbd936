// cosph-solid-jaumann: the SPH linear elastic solid solver with the Jaumann
// stress rate (Gray, Monaghan & Swift 2001), for cases with solid.model
// "jaumann" (the default). Runs a case alone when the case has no fluid; coupled runs come
// through the coupler.
#include "jaumann_solver.hpp"
#include "solid_program.hpp"

int main(int argc, char** argv) {
  using cosph::solid::SolidParameters;
  using cosph::solid::jaumann::JaumannSolver;
  const cosph::solid::SolidProgram<JaumannSolver> program{
      .name = "cosph-solid-jaumann",
      .about = "SPH linear elastic solid solver, Jaumann stress rate (solid.model: \"jaumann\").",
      .model = cosph::solid::SolidModel::jaumann,
      .protocol_name = "cosph-solid-jaumann (jaumann)",
      .summary = [](const JaumannSolver&, const SolidParameters& parameters) -> std::string {
        return parameters.artificial_stress.enabled ? "artificial stress on"
                                                    : "artificial stress off";
      }};
  return cosph::solid::run_solid_program(argc, argv, program);
}
