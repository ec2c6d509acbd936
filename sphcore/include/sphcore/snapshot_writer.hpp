// HDF5 particle snapshots with an XDMF index, so that ParaView opens a run as
// a time series (File > Open > NAME.xdmf; docs/paraview.md).
//
// Each snapshot is one file DIR/NAME_NNNNNN.h5 holding /position (N x 3, z = 0),
// /connectivity (N x 1 int32, 0..N-1) and one dataset per field: float64 for
// real fields, int32 for integer ones (ids, kind codes, flags). The index
// gives every snapshot a Polyvertex topology of N one-node elements read from
// /connectivity: the Xdmf3 readers (ParaView's default) and meshio make one
// vertex cell per particle from it, and none without it. Each file is written
// to a temporary name and renamed, and the XDMF index is rewritten after each,
// so a run that dies keeps a readable record of every snapshot it finished.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "sphcore/types.hpp"

namespace sph {

class Checkpoint;

// The particle data of one snapshot, gathered by a solver.
class Snapshot {
 public:
  explicit Snapshot(std::span<const Vec2> positions);
  void add_scalar(const std::string& name, std::span<const double> values);
  void add_scalar(const std::string& name, std::span<const int> values);
  void add_vector(const std::string& name, std::span<const Vec2> values);

  struct Field {
    std::string name;
    int components;  // 1 or 3
    // Size N * components; integer fields are scalars.
    std::variant<std::vector<double>, std::vector<std::int32_t>> data;
    bool is_integer() const { return data.index() == 1; }
  };
  std::size_t size() const { return size_; }
  const std::vector<double>& positions() const { return positions_; }
  const std::vector<Field>& fields() const { return fields_; }

 private:
  std::size_t size_;
  std::vector<double> positions_;
  std::vector<Field> fields_;
};

class SnapshotWriter {
 public:
  SnapshotWriter(std::string out_dir, std::string name);

  // Writes DIR/NAME_NNNNNN.h5 and rewrites DIR/NAME.xdmf. Returns the .h5 path.
  std::string write(const Snapshot& snapshot, double time);

  // Writes DIR/NAME_<label>.h5 outside the time series (for example the last
  // good state of a run that blew up). Returns its path.
  std::string write_extra(const Snapshot& snapshot, double time, const std::string& label);

  // The snapshots listed so far, for a checkpoint; restore() lists those of
  // a checkpoint again, so that a resumed run's index lists each once.
  void save(Checkpoint& checkpoint) const;
  void restore(const Checkpoint& checkpoint);

 private:
  struct FieldLayout {
    std::string name;
    int components;
    bool is_integer;
  };
  struct Entry {
    std::string file;
    double time;
    std::size_t size;
    std::vector<FieldLayout> fields;
  };
  void write_file(const Snapshot& snapshot, double time, const std::string& path) const;
  void write_index() const;

  std::string out_dir_, name_;
  std::vector<Entry> entries_;
};

}  // namespace sph
