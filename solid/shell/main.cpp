// cosph-solid-shell: the reduced-dimension SPH shell (one line of particles
// on a thin plate's mid-line, Reissner-Mindlin in plane strain), for cases
// with solid.model: "shell". Runs a case alone when the case has no fluid;
// coupled runs come through the coupler, as for cosph-solid.
#include <sstream>

#include "shell_solver.hpp"
#include "solid_program.hpp"

int main(int argc, char** argv) {
  using cosph::solid::SolidParameters;
  using cosph::solid::shell::ShellSolver;
  const cosph::solid::SolidProgram<ShellSolver> program{
      .name = "cosph-solid-shell",
      .about = "Reduced-dimension SPH shell solver (solid.model: \"shell\").",
      .model = cosph::solid::SolidModel::shell,
      .protocol_name = "cosph-solid-shell (shell)",
      .summary =
          [](const ShellSolver& solver, const SolidParameters&) {
            const auto& section = solver.force_parameters().section;
            std::ostringstream summary;
            summary << "shell: thickness " << section.thickness << " m, " << solver.line().count
                    << " particles along at ds = " << solver.line().ds
                    << " m, axial c = " << section.sound_speed() << " m/s";
            return summary.str();
          },
      .unused_settings =
          [](const sph::CaseFile& case_file, const SolidParameters& parameters) {
            std::vector<std::string> notes;
            const auto& solid = case_file.config.solid();
            if (parameters.artificial_stress.enabled)
              notes.push_back("solid.artificial_stress is not used by the shell");
            if (!solid.velocity_gradient().empty())
              notes.push_back("solid.velocity_gradient is not used by the shell");
            if (solid.artificial_viscosity() > 0.0 || solid.artificial_viscosity_quadratic() > 0.0)
              notes.push_back(
                  "solid.artificial_viscosity is not used: the shell damps by its own rule "
                  "(solid.shell_damping, docs/shell.md)");
            if (!solid.walls().empty()) notes.push_back("solid.walls are not met by the shell");
            if (solid.has_hourglass_control())
              notes.push_back(
                  "solid.hourglass_control is not used: the shell's stress points leave no "
                  "zero-energy mode");
            return notes;
          }};
  return cosph::solid::run_solid_program(argc, argv, program);
}
