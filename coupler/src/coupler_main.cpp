// cosph-coupler: the process between the fluid and the solid solver. It fixes
// the common step and computes the cross-phase momentum terms once per pair.
// Started by the launcher: coupler/cosph run CASE --out DIR.

#include <iostream>

#include "coupler_session.hpp"
#include "participant/protocol.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/run_control.hpp"
#include "sphcore/solver_cli.hpp"
#include "substep_choice.hpp"

namespace {

using cosph::coupler::CrossPhaseParameters;
using cosph::coupler::InterfaceModel;

// A coefficient of the case if given, else `fallback`'s if given, else `otherwise`.
double first_positive(double given, double fallback, double otherwise) {
  return given > 0.0 ? given : fallback > 0.0 ? fallback : otherwise;
}

CrossPhaseParameters read_cross_phase_parameters(const sph::CaseFile& case_file) {
  const auto& coupling = case_file.config.coupling();
  const std::string& name = coupling.interface();
  sph::require(name.empty() || name == "moving_wall" || name == "stress_sum", case_file,
               "coupling.interface",
               "unknown interface model '" + name + "' (known: moving_wall, stress_sum)");
  CrossPhaseParameters par;
  par.model = name == "stress_sum" ? InterfaceModel::stress_sum : InterfaceModel::moving_wall;
  par.gravity = sph::read_run_parameters(case_file).gravity;
  if (par.model == InterfaceModel::stress_sum) {
    // Damped as solid pairs are (SPEC.md: A ~ 1 for a solid): c_ij there is
    // mostly the solid's sound speed. Damped as water (A = 0.02), the
    // interface let water at negative pressure clump into the bending plate
    // within 5 ms; with the mean of the two phases' coefficients the elastic
    // plate still blew up at t = 0.086 s.
    const auto& solid = case_file.config.solid();
    par.A = first_positive(coupling.artificial_viscosity(), solid.artificial_viscosity(), 1.0);
    par.B = first_positive(coupling.artificial_viscosity_quadratic(),
                           solid.artificial_viscosity_quadratic(), 1.0);
  } else {
    // Water against a wall: the water's coefficients (and its sound speed).
    const auto& fluid = case_file.config.fluid();
    par.A = first_positive(coupling.artificial_viscosity(), fluid.artificial_viscosity(), 0.02);
    par.B = first_positive(coupling.artificial_viscosity_quadratic(),
                           fluid.artificial_viscosity_quadratic(), 0.0);
  }
  return par;
}

int run(int argc, char** argv) {
  const sph::SolverArgs args = sph::parse_solver_args(
      argc, argv, "cosph-coupler",
      "Couples cosph-fluid and a solid solver over ZeroMQ (SPEC.md \"the coupling rule\").");
  const sph::CaseFile case_file = sph::load_case(args.case_path, args.overrides);
  sph::require(case_file.config.has_fluid() && case_file.config.has_solid(), case_file,
               "fluid, solid", "a coupled case needs both");
  sph::require(!args.endpoint.empty(), case_file, "--endpoint",
               "the coupler needs an endpoint to bind (ipc://PATH or tcp://HOST:PORT)");
  const auto& coupling = case_file.config.coupling();
  sph::require(coupling.timeout() >= 0.0, case_file, "coupling.timeout", "must not be negative");
  sph::require(coupling.artificial_viscosity() >= 0.0, case_file, "coupling.artificial_viscosity",
               "must not be negative");

  cosph::coupler::CouplerSettings settings;
  settings.endpoint = args.endpoint;
  settings.out_dir = args.out_dir;
  settings.run = sph::read_run_parameters(case_file);
  settings.timeout_seconds = coupling.timeout() > 0.0 ? coupling.timeout() : 10.0;
  settings.cross_phase = read_cross_phase_parameters(case_file);
  const cosph::coupler::SubstepChoice substeps = cosph::coupler::read_substep_choice(case_file);
  settings.max_substeps = substeps.max_substeps;
  sph::require(coupling.solid_step().empty() || coupling.solid_step() == "own" ||
                   coupling.solid_step() == "fluid",
               case_file, "coupling.solid_step",
               "must be \"own\" (default) or \"fluid\", not \"" + coupling.solid_step() + "\"");
  settings.solid_at_fluid_step = coupling.solid_step() == "fluid";
  std::cout << "cosph-coupler: sub-stepping: "
            << (settings.solid_at_fluid_step ? "the fluid's step, taken whole by the solid "
                                               "(coupling.solid_step \"fluid\")"
                                             : substeps.reason)
            << std::endl;
  sph::make_output_dir(args.out_dir);
  sph::install_stop_handlers();
  return cosph::coupler::run_coupler(settings);
}

}  // namespace

int main(int argc, char** argv) {
  cosph::coupling::keep_freed_memory();  // messages and pair lists of some 100 kB every step
  return sph::run_guarded("cosph-coupler", [&] { return run(argc, argv); });
}
