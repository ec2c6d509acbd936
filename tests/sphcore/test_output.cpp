// Output formats: timeseries.csv (header with units, one row per call) and the
// HDF5 snapshots with their XDMF index, read back with the HDF5 C API.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "sphcore/snapshot_writer.hpp"
#include "sphcore/timeseries_writer.hpp"
#include "test_support.hpp"

namespace {

using cosph::testing::read_text;
using cosph::testing::ScratchDir;
using sph::Vec2;

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

TEST(TimeSeriesWriter, HeaderWithUnitsAndRows) {
  ScratchDir dir("timeseries");
  const std::string path = dir.file("timeseries.csv");
  {
    sph::TimeSeriesWriter writer(path, {{"t", "s"}, {"front", "m"}});
    EXPECT_EQ(writer.column_count(), 2u);
    writer.write_row(std::vector<double>{0.0, 0.144});
    // Rows are flushed as written: a run that dies keeps them.
    EXPECT_EQ(lines(read_text(path)).size(), 2u);
    writer.write_row(std::vector<double>{0.002, 0.1441234567891});
    EXPECT_THROW(writer.write_row(std::vector<double>{1.0}), std::logic_error);
  }
  const std::vector<std::string> rows = lines(read_text(path));
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0], "t [s],front [m]");
  EXPECT_EQ(rows[1], "0,0.144");
  // Nine significant digits are kept.
  double t = 0.0, front = 0.0;
  char comma = 0;
  std::stringstream(rows[2]) >> t >> comma >> front;
  EXPECT_EQ(comma, ',');
  EXPECT_DOUBLE_EQ(t, 0.002);
  EXPECT_NEAR(front, 0.1441234567891, 1e-9);
}

TEST(TimeSeriesWriter, UnwritablePathThrows) {
  EXPECT_THROW(sph::TimeSeriesWriter("/nonexistent/folder/t.csv", {{"t", "s"}}),
               std::runtime_error);
}

// Reads a whole double dataset; dims gets its shape.
std::vector<double> read_dataset(hid_t file, const std::string& name, std::vector<hsize_t>& dims) {
  const hid_t set = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
  if (set < 0) throw std::runtime_error("no dataset " + name);
  const hid_t space = H5Dget_space(set);
  const int rank = H5Sget_simple_extent_ndims(space);
  dims.assign(static_cast<std::size_t>(rank), 0);
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  hsize_t count = 1;
  for (const hsize_t d : dims) count *= d;
  std::vector<double> data(count);
  const herr_t status = H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data());
  H5Sclose(space);
  H5Dclose(set);
  if (status < 0) throw std::runtime_error("cannot read dataset " + name);
  return data;
}

// The stored type of a dataset: its class (H5T_INTEGER, H5T_FLOAT) and size in bytes.
std::pair<H5T_class_t, std::size_t> stored_type(hid_t file, const std::string& name) {
  const hid_t set = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
  if (set < 0) throw std::runtime_error("no dataset " + name);
  const hid_t type = H5Dget_type(set);
  const std::pair<H5T_class_t, std::size_t> result{H5Tget_class(type), H5Tget_size(type)};
  H5Tclose(type);
  H5Dclose(set);
  return result;
}

double read_time(hid_t file) {
  const hid_t attribute = H5Aopen(file, "time", H5P_DEFAULT);
  double time = -1.0;
  H5Aread(attribute, H5T_NATIVE_DOUBLE, &time);
  H5Aclose(attribute);
  return time;
}

TEST(SnapshotWriter, WritesHdf5ThatReadsBack) {
  ScratchDir dir("snapshot");
  const std::vector<Vec2> x{{0.1, 0.2}, {-0.3, 0.4}, {0.5, -0.6}};
  const std::vector<double> density{1000.5, 999.25, 1001.125};
  const std::vector<int> id{7, 8, 9};
  const std::vector<Vec2> velocity{{1.0, -1.0}, {0.0, 2.0}, {-3.0, 0.5}};
  sph::Snapshot snapshot(x);
  snapshot.add_scalar("density", density);
  snapshot.add_scalar("id", id);
  snapshot.add_vector("velocity", velocity);
  sph::SnapshotWriter writer(dir.path().string(), "fluid");
  const std::string path = writer.write(snapshot, 0.125);
  EXPECT_EQ(path, dir.file("fluid_000000.h5"));
  EXPECT_FALSE(std::filesystem::exists(path + ".partial"));

  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0) << path;
  std::vector<hsize_t> dims;
  const std::vector<double> position = read_dataset(file, "/position", dims);
  EXPECT_EQ(dims, (std::vector<hsize_t>{3, 3}));
  for (std::size_t i = 0; i < x.size(); ++i) {
    EXPECT_EQ(position[3 * i], x[i].x());
    EXPECT_EQ(position[3 * i + 1], x[i].y());
    EXPECT_EQ(position[3 * i + 2], 0.0);
  }
  EXPECT_EQ(read_dataset(file, "/density", dims), density);
  EXPECT_EQ(dims, (std::vector<hsize_t>{3}));
  EXPECT_EQ(read_dataset(file, "/id", dims), (std::vector<double>{7.0, 8.0, 9.0}));
  // Integer fields stay integers (int32), real ones float64.
  EXPECT_EQ(stored_type(file, "/id"), std::make_pair(H5T_INTEGER, std::size_t{4}));
  EXPECT_EQ(stored_type(file, "/density"), std::make_pair(H5T_FLOAT, std::size_t{8}));
  // One Polyvertex element per particle: element k is particle k.
  EXPECT_EQ(read_dataset(file, "/connectivity", dims), (std::vector<double>{0.0, 1.0, 2.0}));
  EXPECT_EQ(dims, (std::vector<hsize_t>{3, 1}));
  EXPECT_EQ(stored_type(file, "/connectivity"), std::make_pair(H5T_INTEGER, std::size_t{4}));
  const std::vector<double> v = read_dataset(file, "/velocity", dims);
  EXPECT_EQ(dims, (std::vector<hsize_t>{3, 3}));
  EXPECT_EQ(v[3 * 2], -3.0);
  EXPECT_EQ(v[3 * 2 + 1], 0.5);
  EXPECT_EQ(read_time(file), 0.125);
  H5Fclose(file);

  // The index declares what each dataset holds (the Xdmf3 readers convert to
  // the declared type) and reads the topology from /connectivity.
  const std::string index = read_text(dir.file("fluid.xdmf"));
  EXPECT_NE(index.find("<DataItem Dimensions=\"3\" NumberType=\"Int\" Precision=\"4\" "
                       "Format=\"HDF\">fluid_000000.h5:/id<"),
            std::string::npos)
      << index;
  EXPECT_NE(index.find("<DataItem Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" "
                       "Format=\"HDF\">fluid_000000.h5:/density<"),
            std::string::npos)
      << index;
  EXPECT_NE(index.find("<DataItem Dimensions=\"3 1\" NumberType=\"Int\" Precision=\"4\" "
                       "Format=\"HDF\">fluid_000000.h5:/connectivity<"),
            std::string::npos)
      << index;
}

TEST(SnapshotWriter, XdmfIndexReferencesEverySnapshot) {
  ScratchDir dir("snapshot");
  sph::SnapshotWriter writer(dir.path().string(), "fluid");
  std::vector<std::string> files;
  for (int k = 0; k < 3; ++k) {
    const std::vector<Vec2> x(static_cast<std::size_t>(k + 2), Vec2(0.01 * k, 0.0));
    const std::vector<double> pressure(x.size(), 100.0 * k);
    sph::Snapshot snapshot(x);
    snapshot.add_scalar("pressure", pressure);
    files.push_back(writer.write(snapshot, 0.02 * k));
    ASSERT_TRUE(std::filesystem::exists(files.back()));
  }
  const std::string extra =
      writer.write_extra(sph::Snapshot(std::vector<Vec2>{}), 0.05, "last_good");
  EXPECT_EQ(extra, dir.file("fluid_last_good.h5"));
  EXPECT_TRUE(std::filesystem::exists(extra));

  const std::string index = read_text(dir.file("fluid.xdmf"));
  // Version 3: meshio's reader refuses 2.x; ParaView's three readers take it.
  EXPECT_NE(index.find("<Xdmf Version=\"3.0\">"), std::string::npos);
  for (int k = 0; k < 3; ++k) {
    const std::string name = std::filesystem::path(files[k]).filename().string();
    EXPECT_EQ(name, "fluid_00000" + std::to_string(k) + ".h5");
    EXPECT_NE(index.find(name + ":/position"), std::string::npos) << name;
    EXPECT_NE(index.find(name + ":/pressure"), std::string::npos) << name;
    EXPECT_NE(index.find(name + ":/connectivity"), std::string::npos) << name;
    // Each grid gives its own particle count.
    EXPECT_NE(index.find("NumberOfElements=\"" + std::to_string(k + 2) + "\""), std::string::npos);
  }
  EXPECT_NE(index.find("<Time Value=\"0.04\"/>"), std::string::npos) << index;
  // The extra file is outside the time series.
  EXPECT_EQ(index.find("last_good"), std::string::npos);
  // The index is one well-formed document: every Grid opened is closed.
  std::size_t opened = 0, closed = 0;
  for (std::size_t at = 0; (at = index.find("<Grid ", at)) != std::string::npos; ++at) ++opened;
  for (std::size_t at = 0; (at = index.find("</Grid>", at)) != std::string::npos; ++at) ++closed;
  EXPECT_EQ(opened, 4u);
  EXPECT_EQ(closed, 4u);
}

}  // namespace
