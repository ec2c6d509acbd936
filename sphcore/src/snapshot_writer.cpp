#include "sphcore/snapshot_writer.hpp"

#include <hdf5.h>

#include <cstdio>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "hdf5_in_memory.hpp"
#include "sphcore/checkpoint.hpp"
#include "sphcore/whole_file.hpp"

namespace sph {

Snapshot::Snapshot(std::span<const Vec2> positions) : size_(positions.size()) {
  positions_.reserve(3 * size_);
  for (const Vec2& p : positions) positions_.insert(positions_.end(), {p.x(), p.y(), 0.0});
}

void Snapshot::add_scalar(const std::string& name, std::span<const double> values) {
  fields_.push_back({name, 1, std::vector<double>(values.begin(), values.end())});
}

void Snapshot::add_scalar(const std::string& name, std::span<const int> values) {
  fields_.push_back({name, 1, std::vector<std::int32_t>(values.begin(), values.end())});
}

void Snapshot::add_vector(const std::string& name, std::span<const Vec2> values) {
  std::vector<double> data;
  data.reserve(3 * values.size());
  for (const Vec2& v : values) data.insert(data.end(), {v.x(), v.y(), 0.0});
  fields_.push_back({name, 3, std::move(data)});
}

SnapshotWriter::SnapshotWriter(std::string out_dir, std::string name)
    : out_dir_(std::move(out_dir)), name_(std::move(name)) {}

std::string SnapshotWriter::write(const Snapshot& snapshot, double time) {
  char number[16];
  std::snprintf(number, sizeof number, "%06zu", entries_.size());
  const std::string file = name_ + "_" + number + ".h5";
  write_file(snapshot, time, out_dir_ + "/" + file);
  Entry entry{file, time, snapshot.size(), {}};
  for (const auto& field : snapshot.fields())
    entry.fields.push_back({field.name, field.components, field.is_integer()});
  entries_.push_back(std::move(entry));
  write_index();
  return out_dir_ + "/" + file;
}

std::string SnapshotWriter::write_extra(const Snapshot& snapshot, double time,
                                        const std::string& label) {
  const std::string path = out_dir_ + "/" + name_ + "_" + label + ".h5";
  write_file(snapshot, time, path);
  return path;
}

void SnapshotWriter::save(Checkpoint& checkpoint) const {
  std::vector<double> times;
  std::vector<long> sizes;
  std::string layouts;  // one line per snapshot: NAME COMPONENTS INTEGER ...
  for (const Entry& e : entries_) {
    times.push_back(e.time);
    sizes.push_back(static_cast<long>(e.size));
    for (const FieldLayout& field : e.fields)
      layouts += field.name + " " + std::to_string(field.components) + " " +
                 (field.is_integer ? "1 " : "0 ");
    layouts += "\n";
  }
  checkpoint.put("snapshot_times", times);
  checkpoint.put("snapshot_sizes", sizes);
  checkpoint.put_text("snapshot_fields", layouts);
}

void SnapshotWriter::restore(const Checkpoint& checkpoint) {
  std::vector<double> times;
  std::vector<long> sizes;
  checkpoint.get("snapshot_times", times);
  checkpoint.get("snapshot_sizes", sizes);
  std::istringstream layouts(checkpoint.text("snapshot_fields"));
  entries_.clear();
  for (std::size_t k = 0; k < times.size(); ++k) {
    char number[24];
    std::snprintf(number, sizeof number, "%06zu", k);
    Entry entry{name_ + "_" + number + ".h5", times[k], static_cast<std::size_t>(sizes.at(k)), {}};
    std::string line;
    std::getline(layouts, line);
    std::istringstream fields(line);
    FieldLayout field;
    int is_integer = 0;
    while (fields >> field.name >> field.components >> is_integer) {
      field.is_integer = is_integer != 0;
      entry.fields.push_back(field);
    }
    entries_.push_back(std::move(entry));
  }
  write_index();
}

namespace {

// A dataset of `rows` x `components` values (rank 1 when rank is 1), stored
// as `stored` and read from memory as `in_memory`.
void write_dataset(hid_t file, const std::string& name, const void* data, hid_t stored,
                   hid_t in_memory, std::size_t rows, int components, int rank,
                   const std::string& path) {
  const hsize_t dims[2] = {rows, static_cast<hsize_t>(components)};
  const hid_t space = H5Screate_simple(rank, dims, nullptr);
  const hid_t set =
      H5Dcreate2(file, name.c_str(), stored, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  const herr_t status =
      set < 0 ? -1 : H5Dwrite(set, in_memory, H5S_ALL, H5S_ALL, H5P_DEFAULT, data);
  if (set >= 0) H5Dclose(set);
  H5Sclose(space);
  if (status < 0) throw std::runtime_error(path + ": cannot write dataset " + name);
}

void write_dataset(hid_t file, const std::string& name, const std::vector<double>& data,
                   std::size_t rows, int components, const std::string& path) {
  write_dataset(file, name, data.data(), H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, rows, components,
                components == 1 ? 1 : 2, path);
}

void write_dataset(hid_t file, const std::string& name, const std::vector<std::int32_t>& data,
                   std::size_t rows, int components, const std::string& path) {
  write_dataset(file, name, data.data(), H5T_STD_I32LE, H5T_NATIVE_INT32, rows, components,
                components == 1 ? 1 : 2, path);
}

// Element k of the Polyvertex topology is particle k alone. N x 1, as the
// readers expect connectivity to be elements x nodes per element.
void write_connectivity(hid_t file, std::size_t size, const std::string& path) {
  std::vector<std::int32_t> nodes(size);
  std::iota(nodes.begin(), nodes.end(), 0);
  write_dataset(file, "/connectivity", nodes.data(), H5T_STD_I32LE, H5T_NATIVE_INT32, size, 1, 2,
                path);
}

}  // namespace

void SnapshotWriter::write_file(const Snapshot& snapshot, double time,
                                const std::string& path) const {
  // Built in memory, written whole (hdf5_in_memory.hpp).
  const hid_t file = create_in_memory(path);
  std::string image;
  try {
    write_dataset(file, "/position", snapshot.positions(), snapshot.size(), 3, path);
    write_connectivity(file, snapshot.size(), path);
    for (const auto& field : snapshot.fields())
      std::visit(
          [&](const auto& data) {
            write_dataset(file, "/" + field.name, data, snapshot.size(), field.components, path);
          },
          field.data);
    const hid_t scalar = H5Screate(H5S_SCALAR);
    const hid_t attribute =
        H5Acreate2(file, "time", H5T_IEEE_F64LE, scalar, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(attribute, H5T_NATIVE_DOUBLE, &time);
    H5Aclose(attribute);
    H5Sclose(scalar);
    image = image_of(file, path);
  } catch (...) {
    H5Fclose(file);
    throw;
  }
  H5Fclose(file);
  write_whole_file(path, image);
}

void SnapshotWriter::write_index() const {
  std::ostringstream out;
  {
    out.precision(12);
    out << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
        << "  <Grid Name=\"" << name_
        << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const Entry& e : entries_) {
      // Dimensions as the dataset's shape; rank 2 when `columns` is given.
      auto item = [&](const std::string& dataset, int columns, bool is_integer) {
        out << "      <DataItem Dimensions=\"" << e.size;
        if (columns > 0) out << " " << columns;
        out << (is_integer ? "\" NumberType=\"Int\" Precision=\"4\""
                           : "\" NumberType=\"Float\" Precision=\"8\"")
            << " Format=\"HDF\">" << e.file << ":/" << dataset << "</DataItem>\n";
      };
      out << "   <Grid Name=\"" << name_ << "\" GridType=\"Uniform\">\n"
          << "    <Time Value=\"" << e.time << "\"/>\n"
          << "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << e.size
          << "\" NodesPerElement=\"1\">\n";
      item("connectivity", 1, true);
      out << "    </Topology>\n"
          << "    <Geometry GeometryType=\"XYZ\">\n";
      item("position", 3, false);
      out << "    </Geometry>\n";
      for (const FieldLayout& field : e.fields) {
        const bool scalar = field.components == 1;
        out << "    <Attribute Name=\"" << field.name << "\" AttributeType=\""
            << (scalar ? "Scalar" : "Vector") << "\" Center=\"Node\">\n";
        item(field.name, scalar ? 0 : field.components, field.is_integer);
        out << "    </Attribute>\n";
      }
      out << "   </Grid>\n";
    }
    out << "  </Grid>\n </Domain>\n</Xdmf>\n";
  }
  // Whole or not at all: a full disk must not replace the good index with a torn one.
  write_whole_file(out_dir_ + "/" + name_ + ".xdmf", out.str());
}

}  // namespace sph
