// cosph-dummy: a coupled "solver" without physics (STYLE.md: "a dummy
// participant exercises the protocol without physics"). It runs the real
// participant loop (participant/coupled_run.hpp) with a block of particles
// that carries a prescribed stress sigma = -P I and moves with a prescribed
// velocity (V, 0), proposes a fixed step, and records in DIR/dummy_PHASE.csv
// every step the coupler gave it and the total cross-phase force sum m a it
// received. As a solid it sends an acceleration (--acceleration A: (A, 0) for
// every particle) with its state, as the solid models do, unless
// --send-acceleration 0 (a solid that does not send it). The fluid block lies left of x = 0, the
// solid block right of it, so the two meet across x = 0.
//
// --busy-ms W makes each step take W ms of "work" before the state goes out,
// on every step or, with --busy-parity 0 or 1, on the even or odd ones only.
//
// Failure modes for the tests: --die-at-step K exits abruptly (no goodbye),
// --hang-at-step K stops answering, --garbage-at-step K sends bytes that are
// not a message, --version V announces another protocol version. The last two
// need a raw DEALER socket: the Participant never misbehaves.
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <thread>

#include "participant/coupled_run.hpp"
#include "participant/coupling_timeout.hpp"
#include "participant/protocol.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/gauge.hpp"
#include "sphcore/output_lock.hpp"
#include "sphcore/region.hpp"
#include "sphcore/solver_cli.hpp"
#include "sphcore/time_step.hpp"

namespace {

namespace cp = cosph::coupling;
using sph::Mat2;
using sph::Vec2;

struct DummyOptions {
  std::string phase, endpoint, out_dir;
  std::string keys, coupler_key;  // CURVE key files, over tcp://
  long particles = 200;
  double dt = 0.0;   // 0: 1e-3 s for the fluid, 1.5e-3 s for the solid
  double end = 1.0;  // s, for progress and snapshots only: the coupler ends the run
  double spacing = 1e-3;
  double motion = 0.0;        // m/s, x velocity
  double stress = -1;         // Pa, pressure P; negative: 1000 Pa for the fluid, 0 for the solid
  double acceleration = 0.0;  // m/s^2, x acceleration a solid sends
  long send_acceleration = 1;
  double timeout = cosph::coupling::kDefaultTimeoutSeconds;
  double busy_ms = 0.0;
  long busy_parity = -1;  // negative: busy on every step
  long die_at = -1, hang_at = -1, garbage_at = -1;
  long version = -1;  // negative: the right one
};

const char* kUsage =
    "usage: cosph-dummy --phase fluid|solid --endpoint E --out DIR [--particles N] [--dt DT]\n"
    "       [--end T] [--spacing DX] [--motion V] [--stress P] [--timeout S]\n"
    "       [--acceleration A] [--send-acceleration 0|1] [--keys FILE --coupler-key FILE]\n"
    "       [--busy-ms W] [--busy-parity 0|1]\n"
    "       [--die-at-step K] [--hang-at-step K] [--garbage-at-step K] [--version V]";

DummyOptions parse_options(int argc, char** argv) {
  DummyOptions o;
  const std::map<std::string, std::string*> texts{{"--phase", &o.phase},
                                                  {"--endpoint", &o.endpoint},
                                                  {"--out", &o.out_dir},
                                                  {"--keys", &o.keys},
                                                  {"--coupler-key", &o.coupler_key}};
  const std::map<std::string, double*> numbers{
      {"--dt", &o.dt},           {"--end", &o.end},
      {"--spacing", &o.spacing}, {"--motion", &o.motion},
      {"--stress", &o.stress},   {"--timeout", &o.timeout},
      {"--busy-ms", &o.busy_ms}, {"--acceleration", &o.acceleration}};
  const std::map<std::string, long*> integers{{"--particles", &o.particles},
                                              {"--die-at-step", &o.die_at},
                                              {"--hang-at-step", &o.hang_at},
                                              {"--garbage-at-step", &o.garbage_at},
                                              {"--version", &o.version},
                                              {"--busy-parity", &o.busy_parity},
                                              {"--send-acceleration", &o.send_acceleration}};
  for (int i = 1; i < argc; i += 2) {
    const std::string option = argv[i];
    if (i + 1 >= argc) throw sph::ConfigError(option + " needs a value\n" + kUsage);
    const std::string value = argv[i + 1];
    try {
      if (texts.count(option))
        *texts.at(option) = value;
      else if (numbers.count(option))
        *numbers.at(option) = std::stod(value);
      else if (integers.count(option))
        *integers.at(option) = std::stol(value);
      else
        throw sph::ConfigError("unknown option " + option + "\n" + kUsage);
    } catch (const std::logic_error&) {  // from std::stod, std::stol
      throw sph::ConfigError(option + ": not a number: " + value);
    }
  }
  if ((o.phase != "fluid" && o.phase != "solid") || o.endpoint.empty() || o.out_dir.empty())
    throw sph::ConfigError(std::string("--phase fluid|solid, --endpoint and --out are required\n") +
                           kUsage);
  if (!(o.particles > 0 && o.spacing > 0.0 && o.timeout > 0.0))
    throw sph::ConfigError("--particles, --spacing and --timeout must be positive");
  if (o.dt <= 0.0) o.dt = o.phase == "fluid" ? 1e-3 : 1.5e-3;
  if (o.stress < 0.0) o.stress = o.phase == "fluid" ? 1000.0 : 0.0;
  return o;
}

// The Solver of CoupledRun (see its header for the list of duties).
class DummySolver {
 public:
  explicit DummySolver(const DummyOptions& o)
      : o_(o), h_(1.3 * o.spacing), csv_(o.out_dir + "/dummy_" + o.phase + ".csv") {
    const bool fluid = o.phase == "fluid";
    const long rows = std::lround(std::ceil(std::sqrt(static_cast<double>(o.particles))));
    for (long k = 0; k < o.particles; ++k) {
      const double column = static_cast<double>(k / rows) + 0.5;
      x_.emplace_back(fluid ? -column * o.spacing : column * o.spacing,
                      (static_cast<double>(k % rows) + 0.5) * o.spacing);
    }
    rho_ = fluid ? 1000.0 : 1100.0;
    if (!csv_) throw std::runtime_error(o.out_dir + "/dummy_" + o.phase + ".csv: cannot create");
    csv_ << "step,t,dt,sum_max,sum_may\n";
    csv_.precision(17);
  }

  void begin_step(double dt) {
    if (steps_ == o_.die_at) {
      std::cerr << "cosph-dummy: " << o_.phase << " dies at step " << steps_ << std::endl;
      std::_Exit(3);
    }
    if (steps_ == o_.hang_at) hang();
    csv_ << steps_ << ',' << time_ << ',' << dt << ',' << force_.x() << ',' << force_.y()
         << std::endl;
    for (Vec2& x : x_) x.x() += o_.motion * dt;
    if (o_.busy_ms > 0.0 && (o_.busy_parity < 0 || steps_ % 2 == o_.busy_parity))
      std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(o_.busy_ms));
  }
  void end_step(double dt) {
    time_ += dt;
    ++steps_;
  }

  sph::StepLimits step_limits() const {
    const double inf = std::numeric_limits<double>::infinity();
    return {o_.dt, inf, inf};
  }
  void collect_interface(const sph::Region& region, sph::InterfaceParticles& out) {
    out.clear();
    const bool sends_acceleration = o_.phase == "solid" && o_.send_acceleration != 0;
    for (std::size_t i = 0; i < x_.size(); ++i) {
      if (!region.contains(x_[i])) continue;
      const Vec2 v(o_.motion, 0.0), a(o_.acceleration, 0.0);
      const Mat2 sigma = -o_.stress * Mat2::Identity();
      if (sends_acceleration)
        out.add(static_cast<long>(i), x_[i], v, a, sigma, mass(), rho_, h_, 10.0);
      else
        out.add(static_cast<long>(i), x_[i], v, sigma, mass(), rho_, h_, 10.0);
    }
  }
  void set_interface_accelerations(const std::vector<Vec2>& a) {
    force_ = Vec2::Zero();
    for (const Vec2& a_i : a) force_ += mass() * a_i;
  }

  sph::Region interaction_bounds() const { return sph::bounds_of(x_); }
  double max_smoothing_length() const { return h_; }
  std::vector<sph::Gauge> gauge_values() const {
    std::vector<sph::Gauge> gauges{{o_.phase + "_force_x", "N/m", force_.x()},
                                   {o_.phase + "_steps", "1", static_cast<double>(steps_)}};
    if (o_.phase == "fluid") gauges.push_back({"height", "m", interaction_bounds().max.y()});
    return gauges;
  }
  double time() const { return time_; }
  long steps() const { return steps_; }
  sph::Snapshot snapshot() const { return sph::Snapshot(x_); }
  const std::vector<Vec2>& particles() const { return x_; }

 private:
  double mass() const { return rho_ * o_.spacing * o_.spacing; }
  // Stops answering, as a stalled solver would, until SIGTERM or a minute passes.
  void hang() const {
    std::cerr << "cosph-dummy: " << o_.phase << " hangs at step " << steps_ << std::endl;
    const auto until = std::chrono::steady_clock::now() + std::chrono::minutes(1);
    while (!sph::stop_requested() && std::chrono::steady_clock::now() < until)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    throw std::runtime_error("stopped while hanging at step " + std::to_string(steps_));
  }

  DummyOptions o_;
  double h_, rho_;
  std::vector<Vec2> x_;
  Vec2 force_ = Vec2::Zero();  // sum m a of the last accelerations received
  double time_ = 0.0;
  long steps_ = 0;
  std::ofstream csv_;
};

// The misbehaviours the Participant cannot produce, on a raw DEALER socket:
// a Hello with another protocol version, garbage bytes at step garbage_at.
int run_misbehaving(const DummyOptions& o, DummySolver& solver) {
  zmq::context_t context(1);
  zmq::socket_t socket(context, zmq::socket_type::dealer);
  socket.set(zmq::sockopt::linger, 1000);
  socket.connect(o.endpoint);
  const std::chrono::milliseconds timeout(std::lround(1000.0 * o.timeout));
  auto await = [&] {
    const auto reply = cp::receive(socket, timeout, "the coupler");
    if (!reply) throw cp::CouplingError("the coupler did not answer");
    if (reply->has_error()) throw cp::CouplingError("coupler: " + reply->error().message());
    return *reply;
  };

  cp::Envelope hello;
  cp::Hello& h = *hello.mutable_hello();
  h.set_protocol_version(o.version >= 0 ? static_cast<unsigned>(o.version) : cp::kProtocolVersion);
  h.set_phase(o.phase == "fluid" ? cp::FLUID : cp::SOLID);
  h.set_solver("cosph-dummy (" + o.phase + ")");
  h.set_particle_count(solver.particles().size());
  h.set_max_smoothing_length(solver.max_smoothing_length());
  *h.mutable_bounds() = cp::to_proto(solver.interaction_bounds());
  cp::send(socket, hello);
  sph::Region region = cp::from_proto(await().welcome().send_region());
  sph::InterfaceParticles particles;
  for (long step = 0;; ++step) {
    if (step == o.garbage_at) {
      std::cerr << "cosph-dummy: " << o.phase << " sends garbage at step " << step << std::endl;
      const std::string garbage = "\xff\xff\xff not a cosph message";
      socket.send(zmq::buffer(garbage), zmq::send_flags::none);
      await();
      throw cp::CouplingError("the coupler accepted garbage");
    }
    cp::Envelope message;
    cp::InterfaceState& state = *message.mutable_state();
    state.set_step(static_cast<std::uint64_t>(step));
    state.set_time(solver.time());
    state.set_proposed_dt(solver.step_limits().smallest());
    *state.mutable_bounds() = cp::to_proto(solver.interaction_bounds());
    state.set_max_smoothing_length(solver.max_smoothing_length());
    solver.collect_interface(region, particles);
    cp::to_proto(particles, state);
    cp::send(socket, message);
    const cp::Envelope reply = await();
    if (reply.step().stop()) return 0;
    region = cp::from_proto(reply.step().send_region());
    solver.begin_step(reply.step().dt());
    solver.end_step(reply.step().dt());
  }
}

int run(int argc, char** argv) {
  const DummyOptions o = parse_options(argc, argv);
  sph::make_output_dir(o.out_dir);
  sph::lock_output_dir(o.out_dir, o.endpoint, sph::command_line(argc, argv));
  sph::install_stop_handlers();
  DummySolver solver(o);
  if (o.version >= 0 || o.garbage_at >= 0) return run_misbehaving(o, solver);
  const sph::RunParameters run{o.end, o.end, o.end, 0.25, Vec2::Zero(), 1};
  const cp::PhaseKind phase = o.phase == "fluid" ? cp::PhaseKind::fluid : cp::PhaseKind::solid;
  cp::CoupledRun<DummySolver> coupled(
      solver, run,
      {o.out_dir, "dummy_" + o.phase, phase, "cosph-dummy (" + o.phase + ")", o.endpoint, o.timeout,
       cp::CurveKeyFiles{o.keys, o.coupler_key, {}}});
  return coupled.run();
}

}  // namespace

int main(int argc, char** argv) {
  return sph::run_guarded("cosph-dummy", [&] { return run(argc, argv); });
}
