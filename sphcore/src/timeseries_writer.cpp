#include "sphcore/timeseries_writer.hpp"

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "sphcore/case_file.hpp"
#include "sphcore/whole_file.hpp"

namespace sph {

namespace {

std::string header_of(const std::vector<Column>& columns) {
  std::string header;
  for (std::size_t c = 0; c < columns.size(); ++c)
    header += (c ? "," : "") + columns[c].name + " [" + columns[c].unit + "]";
  return header;
}

}  // namespace

TimeSeriesWriter::TimeSeriesWriter(const std::string& path, std::vector<Column> columns)
    : path_(path), columns_(std::move(columns)) {
  start_with(header_of(columns_) + "\n");
}

void TimeSeriesWriter::start_with(const std::string& text) {
  write_whole_file(path_, text);
  whole_size_ = text.size();
  out_.open(path_, std::ios::app);
  if (!out_) throw std::runtime_error(path_ + ": cannot append to it: " + system_reason(errno));
  out_.precision(9);
}

TimeSeriesWriter::TimeSeriesWriter(const std::string& path, std::vector<Column> columns,
                                   ContinueAfter kept)
    : path_(path), columns_(std::move(columns)), rows_(kept.rows) {
  std::ifstream in(path);
  if (!in) throw ConfigError(path + ": cannot read the time series the run wrote so far");
  std::string header, line, text;
  std::getline(in, header);
  if (header != header_of(columns_))
    throw ConfigError(path + ": its columns are not this run's (\"" + header + "\")");
  text = header + "\n";
  for (std::size_t row = 0; row < kept.rows; ++row) {
    if (!std::getline(in, line))
      throw ConfigError(path + ": has " + std::to_string(row) + " rows, the checkpoint counts " +
                        std::to_string(kept.rows));
    text += line + "\n";
  }
  in.close();
  // The rows after the checkpoint are written again by the resumed run.
  start_with(text);
}

void TimeSeriesWriter::write_row(std::span<const double> values) {
  if (values.size() != columns_.size())
    throw std::logic_error(path_ + ": row has " + std::to_string(values.size()) + " values for " +
                           std::to_string(columns_.size()) + " columns");
  std::ostringstream row;
  row.precision(9);
  for (std::size_t c = 0; c < values.size(); ++c) row << (c ? "," : "") << values[c];
  row << '\n';
  const std::string text = row.str();
  errno = 0;
  out_ << text;
  out_.flush();
  if (!out_) {
    // Part of the row may have reached the file: cut it off, so that the
    // file holds whole rows only.
    const int error = errno;
    out_.close();
    std::error_code ignored;
    std::filesystem::resize_file(path_, whole_size_, ignored);
    throw std::runtime_error(path_ + ": cannot add a row (" + system_reason(error) +
                             "); it keeps its " + std::to_string(rows_) + " whole rows");
  }
  whole_size_ += text.size();
  ++rows_;
}

}  // namespace sph
