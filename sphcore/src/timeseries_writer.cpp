#include "sphcore/timeseries_writer.hpp"

#include <stdexcept>

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

void TimeSeriesWriter::write_row(std::span<const double> values) {
  if (values.size() != columns_.size())
    throw std::logic_error(path_ + ": row has " + std::to_string(values.size()) + " values for " +
                           std::to_string(columns_.size()) + " columns");
  for (std::size_t c = 0; c < values.size(); ++c) out_ << (c ? "," : "") << values[c];
  out_ << '\n';
  out_.flush();
  if (!out_) throw std::runtime_error(path_ + ": write failed (disk full?)");
}

}  // namespace sph
