// A solver's measurement, one column of timeseries.csv.
#pragma once

#include <string>

namespace sph {

// One measurement of a solver, a column of timeseries.csv.
struct Gauge {
  std::string name;
  std::string unit;
  double value;
};

}  // namespace sph
