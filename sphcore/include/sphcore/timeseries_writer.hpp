// DIR/timeseries.csv (and the coupler's coupling.csv): one row per output
// interval, a header naming every column with its unit ("t [s]"), flushed row
// by row so that a run that stops early keeps everything it measured. The
// file holds whole rows only: it starts whole or not at all (sph::
// write_whole_file), and a row that cannot be written whole is cut off again.
#pragma once

#include <cstdint>
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
  // A resumed run's: keeps the header and the first `rows` rows of the file
  // (those written up to its checkpoint), drops the rest, and appends. The
  // header must name `columns`, else ConfigError.
  struct ContinueAfter {
    std::size_t rows;
  };
  TimeSeriesWriter(const std::string& path, std::vector<Column> columns, ContinueAfter kept);
  void write_row(std::span<const double> values);
  std::size_t column_count() const { return columns_.size(); }
  // Rows written so far, the resumed run's kept ones included.
  std::size_t rows() const { return rows_; }

 private:
  std::string path_;
  std::vector<Column> columns_;
  // Writes `text` (the header and any kept rows) whole, then opens it to append.
  void start_with(const std::string& text);

  std::ofstream out_;
  std::size_t rows_ = 0;
  std::uintmax_t whole_size_ = 0;  // bytes of the file up to its last whole row
};

}  // namespace sph
