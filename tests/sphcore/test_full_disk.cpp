// Output on a full disk: the XDMF index, the CSV files and the HDF5 snapshots
// are written whole or not at all. A full disk is played by a file-size limit
// (RLIMIT_FSIZE, as `ulimit -f`), with SIGXFSZ ignored so that a write past it
// fails with EFBIG as one on a full disk fails with ENOSPC.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <csignal>
#include <filesystem>
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

// No file of this process may grow past `bytes` while it lives.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    getrlimit(RLIMIT_FSIZE, &before_);
    previous_handler_ = std::signal(SIGXFSZ, SIG_IGN);
    const rlimit lowered{bytes, before_.rlim_max};
    EXPECT_EQ(setrlimit(RLIMIT_FSIZE, &lowered), 0);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &before_);
    std::signal(SIGXFSZ, previous_handler_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  rlimit before_{};
  void (*previous_handler_)(int) = SIG_DFL;
};

std::vector<std::string> partial_files(const ScratchDir& dir) {
  std::vector<std::string> found;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
    if (entry.path().extension() == ".partial") found.push_back(entry.path().filename());
  return found;
}

sph::Snapshot small_snapshot(std::size_t particles) {
  const std::vector<Vec2> x(particles, Vec2(0.1, 0.2));
  sph::Snapshot snapshot(x);
  snapshot.add_scalar("pressure", std::vector<double>(particles, 1000.0));
  snapshot.add_vector("velocity", std::vector<Vec2>(particles, Vec2(1.0, -1.0)));
  return snapshot;
}

TEST(FullDisk, TheIndexKeepsItsLastWholeVersion) {
  ScratchDir dir("full_disk");
  sph::SnapshotWriter writer(dir.path().string(), "solid");
  const sph::Snapshot snapshot = small_snapshot(4);
  const std::string first = writer.write(snapshot, 0.0);
  // Room for any number of these snapshots, but not for the index they grow.
  FileSizeLimit limit(std::filesystem::file_size(first) + 512);
  std::string last_whole = read_text(dir.file("solid.xdmf"));
  std::string failure;
  for (int k = 1; k < 200 && failure.empty(); ++k) {
    try {
      writer.write(snapshot, 0.01 * k);
      last_whole = read_text(dir.file("solid.xdmf"));
    } catch (const std::runtime_error& error) {
      failure = error.what();
    }
  }
  ASSERT_FALSE(failure.empty()) << "the index never passed the limit";
  EXPECT_NE(failure.find(dir.file("solid.xdmf") + ": cannot write it ("), std::string::npos)
      << failure;
  EXPECT_EQ(read_text(dir.file("solid.xdmf")), last_whole);
  EXPECT_TRUE(last_whole.ends_with("</Xdmf>\n"));
  EXPECT_EQ(partial_files(dir), std::vector<std::string>{});
}

TEST(FullDisk, ASnapshotThatDoesNotFitLeavesNoPartialFile) {
  ScratchDir dir("full_disk");
  sph::SnapshotWriter writer(dir.path().string(), "fluid");
  writer.write(small_snapshot(4), 0.0);
  const std::string index = read_text(dir.file("fluid.xdmf"));
  {
    FileSizeLimit limit(std::filesystem::file_size(dir.file("fluid_000000.h5")) + 512);
    // Some 10^5 bytes of arrays: past the limit.
    EXPECT_THROW(writer.write(small_snapshot(2000), 0.01), std::runtime_error);
  }
  EXPECT_FALSE(std::filesystem::exists(dir.file("fluid_000001.h5")));
  EXPECT_EQ(read_text(dir.file("fluid.xdmf")), index);
  EXPECT_EQ(partial_files(dir), std::vector<std::string>{});
}

TEST(FullDisk, TheTimeSeriesHoldsWholeRowsOnly) {
  ScratchDir dir("full_disk");
  const std::string path = dir.file("timeseries.csv");
  sph::TimeSeriesWriter writer(path, {{"t", "s"}, {"front", "m"}, {"height", "m"}});
  const std::vector<double> row{0.123456789, 0.144123456, 0.288987654};
  writer.write_row(row);
  std::string failure;
  {
    FileSizeLimit limit(std::filesystem::file_size(path) + 1000);
    for (int k = 0; k < 1000 && failure.empty(); ++k) {
      try {
        writer.write_row(row);
      } catch (const std::runtime_error& error) {
        failure = error.what();
      }
    }
  }
  ASSERT_FALSE(failure.empty()) << "the file never passed the limit";
  EXPECT_NE(failure.find(path + ": cannot add a row ("), std::string::npos) << failure;
  // The header, then every row written, whole, and nothing else.
  std::string expected = "t [s],front [m],height [m]\n";
  for (std::size_t k = 0; k < writer.rows(); ++k)
    expected += "0.123456789,0.144123456,0.288987654\n";
  EXPECT_EQ(read_text(path), expected);
  EXPECT_GT(writer.rows(), 20u);
}

TEST(FullDisk, ATimeSeriesThatCannotStartIsNotLeftBehind) {
  ScratchDir dir("full_disk");
  const std::string path = dir.file("coupling.csv");
  FileSizeLimit limit(8);
  EXPECT_THROW(sph::TimeSeriesWriter(path, {{"t", "s"}, {"front", "m"}}), std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_EQ(partial_files(dir), std::vector<std::string>{});
}

}  // namespace
