// Reading a case file (protobuf text format, schema proto/case.proto) and the
// command line's --set FIELD=VALUE overrides, with errors that name the file,
// the line and column or the field, and the reason.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "case.pb.h"

namespace sph {

// Bad input: the message is ready to show a user.
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct CaseFile {
  std::string path;
  cosph::config::Case config;
};

// Parses the file, then applies each "field.path=value" override in turn
// (repeated fields by index: "fluid.water[0].max.x=0.2"), then refuses any
// number that is not finite (require_finite).
CaseFile load_case(const std::string& path, const std::vector<std::string>& overrides = {});

void apply_override(CaseFile& case_file, const std::string& assignment);

// Throws ConfigError "FILE: FIELD: must be a finite number, got inf" for the
// first float or double field, at any depth, that is an infinity or NaN
// (load_case calls it after the overrides).
void require_finite(const CaseFile& case_file);

// Throws ConfigError "FILE: FIELD: REASON" unless ok: the one way a solver
// refuses a case.
void require(bool ok, const CaseFile& case_file, const std::string& field,
             const std::string& reason);

// "0.004" with the shortest exact-enough formatting, for error messages; a
// sentence's number takes fewer significant digits.
std::string format_number(double value, int significant_digits = 6);

}  // namespace sph
