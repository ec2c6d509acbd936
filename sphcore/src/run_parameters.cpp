#include "sphcore/run_parameters.hpp"

#include <cmath>

namespace sph {

RunParameters read_run_parameters(const CaseFile& case_file) {
  const auto& run = case_file.config.run();
  require(case_file.config.has_run(), case_file, "run",
          "missing (it sets end_time and the outputs)");
  require(run.end_time() > 0.0, case_file, "run.end_time",
          "must be positive, got " + format_number(run.end_time()) + " s");
  require(run.output_interval() >= 0.0, case_file, "run.output_interval", "must not be negative");
  require(run.snapshot_interval() >= 0.0, case_file, "run.snapshot_interval",
          "must not be negative");
  // Up to 8 so that scripts/stability_map.py can find where the step breaks;
  // the usual range is 0.2 to 0.3 (docs/physics.md, "Time step").
  require(run.cfl() >= 0.0 && run.cfl() <= 8.0, case_file, "run.cfl",
          "must lie in (0, 8], got " + format_number(run.cfl()));
  require(run.threads() >= 0, case_file, "run.threads", "must not be negative");
  RunParameters p;
  p.end_time = run.end_time();
  p.output_interval = run.output_interval() > 0.0 ? run.output_interval() : p.end_time / 500.0;
  p.snapshot_interval = run.snapshot_interval() > 0.0 ? run.snapshot_interval() : p.end_time / 20.0;
  p.cfl = run.cfl() > 0.0 ? run.cfl() : 0.25;
  p.gravity = Vec2(run.gravity().x(), run.gravity().y());
  p.threads = run.threads();
  require(std::isfinite(run.checkpoint_interval()), case_file, "run.checkpoint_interval",
          "must be a number (negative: no checkpoints)");
  // About ten checkpoints per run: a stopped run loses a tenth of it at most,
  // for ten writes of the state.
  p.checkpoint_interval = run.checkpoint_interval() > 0.0    ? run.checkpoint_interval()
                          : run.checkpoint_interval() == 0.0 ? p.end_time / 10.0
                                                             : INFINITY;
  return p;
}

Resolution read_resolution(const CaseFile& case_file, const std::string& block, double spacing,
                           double h_factor) {
  require(spacing > 0.0, case_file, block + ".spacing",
          "must be positive, got " + format_number(spacing) + " m");
  const double factor = h_factor > 0.0 ? h_factor : 1.3;
  require(factor >= 1.0 && factor <= 2.0, case_file, block + ".h_factor",
          "must lie in [1, 2] (the shipped cases use 1.3 to 2), got " + format_number(h_factor));
  return {spacing, factor * spacing};
}

double read_density(const CaseFile& case_file, const std::string& block, double density) {
  require(density > 0.0, case_file, block + ".density",
          "must be positive, got " + format_number(density) + " kg/m^3");
  return density;
}

ArtificialViscosityCoefficients read_artificial_viscosity(
    const CaseFile& case_file, const std::string& block, double A, double B,
    const ArtificialViscosityCoefficients& defaults) {
  require(A >= 0.0, case_file, block + ".artificial_viscosity", "must not be negative");
  require(B >= 0.0, case_file, block + ".artificial_viscosity_quadratic", "must not be negative");
  return {A > 0.0 ? A : defaults.A, B > 0.0 ? B : defaults.B};
}

}  // namespace sph
