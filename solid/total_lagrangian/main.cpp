// cosph-solid-tl: the total-Lagrangian SPH solid solver (St Venant-Kirchhoff,
// corrected reference kernel gradients, hourglass control), for cases with
// solid.model: "total_lagrangian". Runs a case alone when the case has no
// fluid; coupled runs come through the coupler, as for cosph-solid.
#include <omp.h>

#include <iostream>

#include "participant/run_solver.hpp"
#include "solid_parameters.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/solver_cli.hpp"
#include "tl_solver.hpp"

namespace {

using cosph::solid::tl::TLSolver;

int run_solid_tl(int argc, char** argv) {
  const sph::SolverArgs args =
      sph::parse_solver_args(argc, argv, "cosph-solid-tl",
                             "Total-Lagrangian SPH elastic solid solver (solid.model: "
                             "\"total_lagrangian\").");
  const sph::CaseFile case_file = sph::load_case(args.case_path, args.overrides);
  const auto parameters = cosph::solid::read_solid_parameters(case_file);
  cosph::solid::require_model(case_file, parameters, cosph::solid::SolidModel::total_lagrangian);
  const bool coupled = !args.endpoint.empty();
  sph::require(coupled || !case_file.config.has_fluid(), case_file, "fluid",
               "this case is coupled: run it with coupler/cosph, which starts the coupler");
  sph::make_output_dir(args.out_dir);
  sph::install_stop_handlers();

  sph::RunThreads threads(parameters.run.threads);
  TLSolver solver(case_file, parameters);
  threads.settle(solver.particles().size());
  long clamped = 0;
  for (auto c : solver.particles().clamped) clamped += c;
  std::cout << "cosph-solid-tl: " << solver.particles().size() << " solid particles (" << clamped
            << " clamped), dx = " << parameters.dx << " m, h = " << parameters.h
            << " m, c = " << parameters.c0 << " m/s, hourglass alpha "
            << solver.force_parameters().hourglass_alpha << ", " << omp_get_max_threads()
            << " threads" << std::endl;
  if (parameters.artificial_stress.enabled)
    std::cout << "cosph-solid-tl: note: solid.artificial_stress is not used: the fixed "
                 "reference neighbours of the total-Lagrangian solid have no tensile instability"
              << std::endl;
  if (!case_file.config.solid().velocity_gradient().empty())
    std::cout << "cosph-solid-tl: note: solid.velocity_gradient is not used: the "
                 "total-Lagrangian solid takes its deformation gradient against the initial "
                 "configuration"
              << std::endl;
  return cosph::coupling::run_solver(solver, parameters.run, case_file, args, "solid",
                                     cosph::coupling::PhaseKind::solid,
                                     "cosph-solid-tl (total_lagrangian)");
}

}  // namespace

int main(int argc, char** argv) {
  return sph::run_guarded("cosph-solid-tl", [&] { return run_solid_tl(argc, argv); });
}
