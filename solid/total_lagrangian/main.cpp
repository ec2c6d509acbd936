// cosph-solid-tl: the total-Lagrangian SPH solid solver (St Venant-Kirchhoff,
// corrected reference kernel gradients, hourglass control), for cases with
// solid.model: "total_lagrangian". Runs a case alone when the case has no
// fluid; coupled runs come through the coupler, as for cosph-solid-jaumann.
#include <sstream>

#include "solid_program.hpp"
#include "tl_solver.hpp"

int main(int argc, char** argv) {
  using cosph::solid::SolidParameters;
  using cosph::solid::tl::TLSolver;
  const cosph::solid::SolidProgram<TLSolver> program{
      .name = "cosph-solid-tl",
      .about = "Total-Lagrangian SPH elastic solid solver (solid.model: \"total_lagrangian\").",
      .model = cosph::solid::SolidModel::total_lagrangian,
      .protocol_name = "cosph-solid-tl (total_lagrangian)",
      .summary =
          [](const TLSolver& solver, const SolidParameters&) {
            std::ostringstream summary;
            summary << "hourglass alpha " << solver.force_parameters().hourglass_alpha;
            return summary.str();
          },
      .unused_settings =
          [](const sph::CaseFile& case_file, const SolidParameters& parameters) {
            std::vector<std::string> notes;
            if (parameters.artificial_stress.enabled)
              notes.push_back(
                  "solid.artificial_stress is not used: the fixed reference neighbours of the "
                  "total-Lagrangian solid have no tensile instability");
            if (!case_file.config.solid().velocity_gradient().empty())
              notes.push_back(
                  "solid.velocity_gradient is not used: the total-Lagrangian solid takes its "
                  "deformation gradient against the initial configuration");
            return notes;
          }};
  return cosph::solid::run_solid_program(argc, argv, program);
}
