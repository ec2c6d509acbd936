// Small solid cases for the tests, written as case files so that the tests go
// through the same reading and validation as a user's case.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

namespace cosph::solid::testing {

inline std::string temporary_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("cosph_solid_test_" + name)).string();
}

inline std::string write_case(const std::string& name, const std::string& text) {
  const std::string path = temporary_path(name + ".pbtxt");
  std::ofstream(path) << text;
  return path;
}

// The oscillating plate of cases/oscillating_plate.pbtxt.
inline std::string plate_case_path() {
  return std::string(COSPH_SOURCE_DIR) + "/cases/oscillating_plate.pbtxt";
}

}  // namespace cosph::solid::testing
