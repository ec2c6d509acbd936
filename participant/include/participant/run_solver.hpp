// What every solver's main() does once its solver is built: run it alone
// (sph::StandaloneRun, its gauges as the columns of timeseries.csv) or, given
// an endpoint, in a coupled run (CoupledRun).
#pragma once

#include <string>
#include <vector>

#include "participant/coupled_run.hpp"
#include "participant/coupling_timeout.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/checkpoint.hpp"
#include "sphcore/gauge.hpp"
#include "sphcore/solver_cli.hpp"
#include "sphcore/standalone_run.hpp"

namespace cosph::coupling {

template <class Solver>
int run_solver(Solver& solver, const sph::RunParameters& run, const sph::CaseFile& case_file,
               const sph::SolverArgs& args, const std::string& name, PhaseKind phase,
               const std::string& description, sph::RunThreads& threads) {
  if (!args.endpoint.empty()) {
    const double timeout = coupling_timeout_seconds(case_file);
    CoupledRun<Solver> coupled(
        solver, run,
        {args.out_dir, name, phase, description, args.endpoint, timeout,
         CurveKeyFiles{args.key_file, args.coupler_key_file, args.allowed_key_files}});
    coupled.revise_threads_with(threads);
    coupled.checkpoint_with({sph::run_identity(case_file), args.resume_from});
    return coupled.run();
  }
  std::vector<sph::Column> columns;
  for (const sph::Gauge& gauge : solver.gauge_values()) columns.push_back({gauge.name, gauge.unit});
  sph::StandaloneRun<Solver> alone(solver, run, args.out_dir, name, columns, [](const Solver& s) {
    std::vector<double> values;
    for (const sph::Gauge& gauge : s.gauge_values()) values.push_back(gauge.value);
    return values;
  });
  alone.revise_threads_with(threads);
  alone.checkpoint_with({sph::run_identity(case_file), args.resume_from});
  return alone.run();
}

}  // namespace cosph::coupling
