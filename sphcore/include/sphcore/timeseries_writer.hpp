// DIR/timeseries.csv: one row per output interval, a header naming every
// column with its unit ("t [s]"), flushed row by row so that a run that stops
// early keeps everything it measured.
#pragma once

#include <fstream>
#include <span>
#include <string>
#include <vector>

namespace sph {

struct Column {
  std::string name;
  std::string unit;  // "1" for dimensionless
};

class TimeSeriesWriter {
 public:
  TimeSeriesWriter(const std::string& path, std::vector<Column> columns);
  void write_row(std::span<const double> values);
  std::size_t column_count() const { return columns_.size(); }

 private:
  std::string path_;
  std::vector<Column> columns_;
  std::ofstream out_;
};

}  // namespace sph
