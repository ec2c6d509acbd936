#include "sphcore/timeseries_writer.hpp"

#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "sphcore/case_file.hpp"

namespace sph {

TimeSeriesWriter::TimeSeriesWriter(const std::string& path, std::vector<Column> columns)
    : path_(path), columns_(std::move(columns)), out_(path) {
  if (!out_) throw std::runtime_error(path + ": cannot create time-series file");
  for (std::size_t c = 0; c < columns_.size(); ++c)
    out_ << (c ? "," : "") << columns_[c].name << " [" << columns_[c].unit << "]";
  out_ << '\n';
  out_.precision(9);
  out_.flush();
}

namespace {

std::string header_of(const std::vector<Column>& columns) {
  std::string header;
  for (std::size_t c = 0; c < columns.size(); ++c)
    header += (c ? "," : "") + columns[c].name + " [" + columns[c].unit + "]";
  return header;
}

}  // namespace

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
  const std::string partial = path + ".partial";
  {
    std::ofstream whole(partial, std::ios::trunc);
    whole << text;
    whole.flush();
    if (!whole) throw std::runtime_error(partial + ": write failed (disk full?)");
  }
  if (std::rename(partial.c_str(), path.c_str()) != 0)
    throw std::runtime_error(path + ": cannot replace the time series");
  out_.open(path, std::ios::app);
  if (!out_) throw std::runtime_error(path + ": cannot append to time-series file");
  out_.precision(9);
}

void TimeSeriesWriter::write_row(std::span<const double> values) {
  if (values.size() != columns_.size())
    throw std::logic_error(path_ + ": row has " + std::to_string(values.size()) + " values for " +
                           std::to_string(columns_.size()) + " columns");
  for (std::size_t c = 0; c < values.size(); ++c) out_ << (c ? "," : "") << values[c];
  out_ << '\n';
  out_.flush();
  if (!out_) throw std::runtime_error(path_ + ": write failed (disk full?)");
  ++rows_;
}

}  // namespace sph
