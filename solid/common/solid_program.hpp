// What a solid executable does from its command line to the end of its run:
// read the case, refuse a case of another solid model, build the solver, say
// what it built, and run it alone or coupled (participant/run_solver.hpp).
// cosph-solid-jaumann and cosph-solid-tl differ only in the fields of SolidProgram.
#pragma once

#include <omp.h>

#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "clamp_reach.hpp"
#include "participant/run_solver.hpp"
#include "solid_parameters.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/output_lock.hpp"
#include "sphcore/particle_budget.hpp"
#include "sphcore/run_threads.hpp"
#include "sphcore/solver_cli.hpp"

namespace cosph::solid {

template <class Solver>
struct SolidProgram {
  const char* name;           // of the executable, "cosph-solid-jaumann"
  const char* about;          // one line for --help
  SolidModel model;           // the case's solid.model this program runs
  const char* protocol_name;  // how it introduces itself to the coupler
  // The model's own part of the start-up line ("artificial stress on").
  std::function<std::string(const Solver&, const SolidParameters&)> summary;
  // One note for each setting of the case that this model does not use.
  std::function<std::vector<std::string>(const sph::CaseFile&, const SolidParameters&)>
      unused_settings =
          [](const sph::CaseFile&, const SolidParameters&) { return std::vector<std::string>{}; };
};

template <class Solver>
int run_solid_program(int argc, char** argv, const SolidProgram<Solver>& program) {
  return sph::run_guarded(program.name, [&] {
    const sph::SolverArgs args = sph::parse_solver_args(argc, argv, program.name, program.about);
    const sph::CaseFile case_file = sph::load_case(args.case_path, args.overrides);
    const SolidParameters parameters = read_solid_parameters(case_file);
    require_model(case_file, parameters, program.model);
    sph::check_particle_budget(case_file);
    const bool coupled = !args.endpoint.empty();
    sph::require(coupled || !case_file.config.has_fluid(), case_file, "fluid",
                 "this case is coupled: run it with coupler/cosph, which starts the coupler");
    sph::make_output_dir(args.out_dir);
    sph::lock_output_dir(args.out_dir, args.endpoint, sph::command_line(argc, argv));
    sph::install_stop_handlers();

    sph::RunThreads threads(parameters.run.threads);
    Solver solver(case_file, parameters);
    threads.settle(solver.particles().size());
    long clamped = 0;
    for (auto c : solver.particles().clamped) clamped += c;
    // The continuum solids' clamp out of reach (clamp_reach.hpp): particles
    // past the last one in reach are never visited.
    std::string out_of_reach;
    if constexpr (requires { solver.particles().reach_end; })
      out_of_reach = ", " +
                     std::to_string(solver.particles().size() - in_reach(solver.particles())) +
                     " of them never visited, out of every free particle's reach";
    std::cout << program.name << ": " << solver.particles().size() << " solid particles ("
              << clamped << " clamped" << out_of_reach << "), dx = " << parameters.dx
              << " m, h = " << parameters.h << " m, c = " << parameters.c0 << " m/s, "
              << program.summary(solver, parameters) << ", " << omp_get_max_threads() << " threads"
              << std::endl;
    for (const std::string& note : program.unused_settings(case_file, parameters))
      std::cout << program.name << ": note: " << note << std::endl;
    return coupling::run_solver(solver, parameters.run, case_file, args, "solid",
                                coupling::PhaseKind::solid, program.protocol_name, threads);
  });
}

}  // namespace cosph::solid
