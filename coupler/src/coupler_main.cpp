// cosph-coupler: the process between the fluid and the solid solver. It fixes
// the common step and computes the cross-phase momentum terms once per pair.
// Started by the launcher: coupler/cosph run CASE --out DIR.

#include <iostream>

#include "coupler_session.hpp"
#include "coupler_settings.hpp"
#include "endpoint_safety.hpp"
#include "participant/protocol.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/output_lock.hpp"
#include "sphcore/run_control.hpp"
#include "sphcore/solver_cli.hpp"
#include "substep_choice.hpp"

namespace {

int run(int argc, char** argv) {
  const sph::SolverArgs args = sph::parse_solver_args(
      argc, argv, "cosph-coupler",
      "Couples cosph-fluid and a solid solver over ZeroMQ (docs/physics.md, \"Coupling\").");
  const sph::CaseFile case_file = sph::load_case(args.case_path, args.overrides);
  cosph::coupler::CouplerSettings settings = cosph::coupler::read_coupler_settings(case_file);
  sph::require(!args.endpoint.empty(), case_file, "--endpoint",
               "the coupler needs an endpoint to bind (ipc://PATH or tcp://HOST:PORT)");
  cosph::coupler::check_bind_address(args.endpoint, args.bind_any);
  settings.endpoint = args.endpoint;
  settings.keys = {args.key_file, args.coupler_key_file, args.allowed_key_files};
  cosph::coupling::check_key_files(args.endpoint, settings.keys, /*coupler=*/true);
  settings.out_dir = args.out_dir;
  settings.checkpoints = {sph::run_identity(case_file), args.resume_from};
  std::cout << "cosph-coupler: sub-stepping: " << settings.stepping.reason << std::endl;
  std::cout << "cosph-coupler: the wall's acceleration in its pressure: "
            << settings.wall_acceleration.reason << std::endl;
  sph::make_output_dir(args.out_dir);
  sph::lock_output_dir(args.out_dir, args.endpoint, sph::command_line(argc, argv));
  sph::install_stop_handlers();
  return cosph::coupler::run_coupler(settings);
}

}  // namespace

int main(int argc, char** argv) {
  cosph::coupling::keep_freed_memory();  // messages and pair lists of some 100 kB every step
  return sph::run_guarded("cosph-coupler", [&] { return run(argc, argv); });
}
