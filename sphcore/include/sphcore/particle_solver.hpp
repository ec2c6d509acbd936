// What every solver keeps alike: its parameters and particles, the time and
// the step count, and a step that is begin_step then end_step (the split a
// coupled run needs; participant/coupled_solver.hpp). A solver derives from
// ParticleSolver<itself, its particles, its parameters> and writes only what
// its model does differently.
#pragma once

#include <utility>

namespace sph {

template <class Derived, class Particles, class Parameters>
class ParticleSolver {
 public:
  // Advances by dt. Throws sph::RunawayError if the new state is not physical;
  // the particles then hold that bad state.
  void step(double dt) {
    Derived& solver = static_cast<Derived&>(*this);
    solver.begin_step(dt);
    solver.end_step(dt);
  }

  double time() const { return time_; }
  long steps() const { return steps_; }
  const Particles& particles() const { return particles_; }
  // For tests that set up a state the case cannot describe; the next step
  // recomputes everything derived from it.
  Particles& particles() { return particles_; }
  const Parameters& parameters() const { return parameters_; }
  double max_smoothing_length() const { return parameters_.h; }

 protected:
  ParticleSolver(const Parameters& parameters, Particles particles)
      : parameters_(parameters), particles_(std::move(particles)) {}

  Parameters parameters_;
  Particles particles_;
  double time_ = 0.0;
  long steps_ = 0;
};

}  // namespace sph
