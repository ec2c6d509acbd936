// A checkpoint: everything one process of a run needs to continue it exactly
// where it stopped (docs/restart.md). One HDF5 file per process per
// checkpoint, DIR/checkpoints/NAME_SSSSSSSSS.h5, S the coupling step (or, for
// a solver run alone, its step count) at which it was taken: the three parts
// of a coupled run's checkpoint share S. HDF5 because the snapshots are HDF5
// already (no new dependency) and a checkpoint can be read with h5dump or
// h5py when a resume goes wrong.
//
// Contents are named arrays of float64, int64 or uint8, and the identity of
// the run that wrote them: the format version, the build, and a hash of the
// case as run (run.end_time left out: a resume may extend it). A checkpoint
// of another format, build or case is refused with a message that says which.
//
// Written whole or not at all: to NAME.partial, closed, fsync'ed, renamed, the
// folder fsync'ed. A process killed while writing leaves a .partial, which is
// never read; the last two complete checkpoints of each process are kept.
#pragma once

#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "sphcore/case_file.hpp"
#include "sphcore/run_parameters.hpp"
#include "sphcore/types.hpp"

namespace sph {

// Raised by a layout change of any checkpoint: older ones are then refused.
inline constexpr std::int64_t kCheckpointFormat = 1;

// Who wrote a checkpoint: refused unless all three match the reader's.
struct RunIdentity {
  std::int64_t format = kCheckpointFormat;
  std::string build;      // compiler and build type: bits may differ between builds
  std::string case_hash;  // of the case with its --set values, run.end_time left out
};

// This build's identity for a case.
RunIdentity run_identity(const CaseFile& case_file);

class Checkpoint {
 public:
  void put(const std::string& name, std::span<const double> values);
  void put(const std::string& name, std::span<const Vec2> values);
  void put(const std::string& name, std::span<const Mat2> values);
  void put(const std::string& name, std::span<const int> values);
  void put(const std::string& name, std::span<const long> values);
  void put(const std::string& name, std::span<const std::uint8_t> values);
  void put_value(const std::string& name, double value) { put(name, std::span(&value, 1)); }
  void put_count(const std::string& name, long value) { put(name, std::span(&value, 1)); }
  void put_flag(const std::string& name, bool value) { put_count(name, value ? 1 : 0); }
  void put_text(const std::string& name, const std::string& text);

  // Each throws std::runtime_error naming the file and the array if it is
  // missing or of the wrong kind.
  void get(const std::string& name, std::vector<double>& values) const;
  void get(const std::string& name, std::vector<Vec2>& values) const;
  void get(const std::string& name, std::vector<Mat2>& values) const;
  void get(const std::string& name, std::vector<int>& values) const;
  void get(const std::string& name, std::vector<long>& values) const;
  void get(const std::string& name, std::vector<std::uint8_t>& values) const;
  double value(const std::string& name) const;
  long count(const std::string& name) const;
  bool flag(const std::string& name) const { return count(name) != 0; }
  std::string text(const std::string& name) const;
  bool has(const std::string& name) const;

  // Writes DIR/checkpoints/NAME_SSSSSSSSS.h5 whole, then deletes all but the
  // last two of NAME and any NAME .partial left by a process that was
  // killed. Returns the path.
  std::string write(const std::string& out_dir, const std::string& name, long sequence,
                    const RunIdentity& identity) const;

  // Reads a checkpoint and refuses it (ConfigError naming the file and what
  // differs) unless `expected` wrote it.
  static Checkpoint read(const std::string& path, const RunIdentity& expected);

  long sequence() const { return count("sequence"); }
  const std::string& path() const { return path_; }

 private:
  const std::vector<double>& reals(const std::string& name) const;
  const std::vector<std::int64_t>& integers(const std::string& name) const;
  const std::vector<std::uint8_t>& bytes(const std::string& name) const;

  std::map<std::string, std::vector<double>> reals_;
  std::map<std::string, std::vector<std::int64_t>> integers_;
  std::map<std::string, std::vector<std::uint8_t>> bytes_;
  std::string path_ = "(checkpoint in memory)";
};

// The checkpoint file of process `name` at `sequence` in an output folder.
std::string checkpoint_path(const std::string& out_dir, const std::string& name, long sequence);

}  // namespace sph

namespace sph {

// A solver whose state a checkpoint can hold: save() puts every array and
// counter the next step reads; restore() takes them back into a solver built
// from the same case, and rebuilds what it derives from them (the neighbour
// search) as the uninterrupted run has it.
template <class Solver>
concept Checkpointable = requires(Solver& solver, const Solver& done, Checkpoint& out,
                                  const Checkpoint& in) {
  done.save(out);
  solver.restore(in);
};

// A solver lists its state arrays once, as visit(name, array) calls, and
// the list serves both directions: save() visits with CheckpointPut, restore()
// with CheckpointGet (the solvers' *_checkpoint.cpp).
struct CheckpointPut {
  Checkpoint& checkpoint;
  template <class T>
  void operator()(const char* name, const std::vector<T>& values) const {
    checkpoint.put(name, std::span<const T>(values));
  }
};
struct CheckpointGet {
  const Checkpoint& checkpoint;
  template <class T>
  void operator()(const char* name, std::vector<T>& values) const {
    checkpoint.get(name, values);
  }
};

// A solver's simulated time and step count.
inline void put_clock(Checkpoint& checkpoint, double time, long steps) {
  checkpoint.put_value("time", time);
  checkpoint.put_count("steps", steps);
}
inline void take_clock(const Checkpoint& checkpoint, double& time, long& steps) {
  time = checkpoint.value("time");
  steps = checkpoint.count("steps");
}

// The output, snapshot and checkpoint intervals of a run: a resume keeps
// those of the first run, even where their defaults follow a longer end time.
inline void put_intervals(Checkpoint& checkpoint, const RunParameters& run) {
  checkpoint.put("intervals", std::vector<double>{run.output_interval, run.snapshot_interval,
                                                  run.checkpoint_interval});
}
inline void take_intervals(const Checkpoint& checkpoint, RunParameters& run) {
  std::vector<double> intervals;
  checkpoint.get("intervals", intervals);
  run.output_interval = intervals.at(0);
  run.snapshot_interval = intervals.at(1);
  run.checkpoint_interval = intervals.at(2);
}

// How a run checkpoints: who it is, and where it resumes from.
struct CheckpointSettings {
  RunIdentity identity;
  std::string resume_from;  // a checkpoint file; empty: from the start
};

}  // namespace sph
