#include "sphcore/case_file.hpp"

#include <google/protobuf/io/tokenizer.h>
#include <google/protobuf/stubs/logging.h>
#include <google/protobuf/text_format.h>

#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

namespace sph {
namespace {

namespace pb = google::protobuf;

// Collects the parser's first error as "FILE:LINE:COLUMN: message" (1-based).
class FirstErrorCollector : public pb::io::ErrorCollector {
 public:
  explicit FirstErrorCollector(std::string path) : path_(std::move(path)) {}
  void AddError(int line, pb::io::ColumnNumber column, const std::string& message) override {
    if (!first_error_.empty()) return;
    first_error_ =
        path_ + ":" + std::to_string(line + 1) + ":" + std::to_string(column + 1) + ": " + message;
  }
  const std::string& first_error() const { return first_error_; }

 private:
  std::string path_, first_error_;
};

std::string known_fields(const pb::Descriptor& descriptor) {
  std::string names;
  for (int i = 0; i < descriptor.field_count(); ++i)
    names += (i ? ", " : "") + descriptor.field(i)->name();
  return names;
}

// The first float or double field of `message`, at any depth, whose value is
// not finite: its path as --set spells it ("fluid.water[0].max.x") and value.
struct NonFinite {
  std::string field;
  double value;
};

std::optional<NonFinite> first_non_finite(const pb::Message& message, const std::string& scope) {
  const pb::Reflection& reflection = *message.GetReflection();
  std::vector<const pb::FieldDescriptor*> fields;
  reflection.ListFields(message, &fields);
  for (const pb::FieldDescriptor* field : fields) {
    const std::string name = (scope.empty() ? "" : scope + ".") + field->name();
    const int count = field->is_repeated() ? reflection.FieldSize(message, field) : 1;
    for (int k = 0; k < count; ++k) {
      const std::string where = field->is_repeated() ? name + "[" + std::to_string(k) + "]" : name;
      double value = 0.0;
      switch (field->cpp_type()) {
        case pb::FieldDescriptor::CPPTYPE_MESSAGE: {
          const pb::Message& inner = field->is_repeated()
                                         ? reflection.GetRepeatedMessage(message, field, k)
                                         : reflection.GetMessage(message, field);
          if (auto found = first_non_finite(inner, where)) return found;
          continue;
        }
        case pb::FieldDescriptor::CPPTYPE_DOUBLE:
          value = field->is_repeated() ? reflection.GetRepeatedDouble(message, field, k)
                                       : reflection.GetDouble(message, field);
          break;
        case pb::FieldDescriptor::CPPTYPE_FLOAT:
          value = field->is_repeated() ? reflection.GetRepeatedFloat(message, field, k)
                                       : reflection.GetFloat(message, field);
          break;
        default:
          continue;
      }
      if (!std::isfinite(value)) return NonFinite{where, value};
    }
  }
  return std::nullopt;
}

}  // namespace

CaseFile load_case(const std::string& path, const std::vector<std::string>& overrides) {
  std::ifstream in(path);
  if (!in) throw ConfigError(path + ": cannot open case file (missing or unreadable)");
  std::stringstream text;
  text << in.rdbuf();

  CaseFile case_file{path, {}};
  FirstErrorCollector errors(path);
  pb::TextFormat::Parser parser;
  parser.RecordErrorsTo(&errors);
  if (!parser.ParseFromString(text.str(), &case_file.config))
    throw ConfigError(errors.first_error().empty() ? path + ": not a valid case file"
                                                   : errors.first_error());
  for (const std::string& assignment : overrides) apply_override(case_file, assignment);
  require_finite(case_file);
  return case_file;
}

void apply_override(CaseFile& case_file, const std::string& assignment) {
  // Our message says what went wrong; protobuf's own log line would be a second one.
  pb::LogSilencer silence_protobuf_log;
  const std::string where = case_file.path + ": --set " + assignment + ": ";
  const auto equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0)
    throw ConfigError(where + "expected FIELD=VALUE, for example fluid.spacing=0.004");
  const std::string path = assignment.substr(0, equals);
  const std::string value = assignment.substr(equals + 1);

  pb::Message* message = &case_file.config;
  std::string walked;
  std::stringstream segments(path);
  std::string segment;
  std::vector<std::string> parts;
  while (std::getline(segments, segment, '.')) parts.push_back(segment);
  for (std::size_t p = 0; p < parts.size(); ++p) {
    std::string name = parts[p];
    int index = -1;
    if (const auto bracket = name.find('['); bracket != std::string::npos) {
      if (name.back() != ']') throw ConfigError(where + "malformed index in '" + name + "'");
      try {
        index = std::stoi(name.substr(bracket + 1, name.size() - bracket - 2));
      } catch (const std::exception&) {
        throw ConfigError(where + "malformed index in '" + name + "'");
      }
      name = name.substr(0, bracket);
    }
    const pb::Descriptor* descriptor = message->GetDescriptor();
    const pb::FieldDescriptor* field = descriptor->FindFieldByName(name);
    const std::string scope = walked.empty() ? "the case" : walked;
    if (field == nullptr)
      throw ConfigError(where + "unknown field '" + name + "' in " + scope +
                        " (known: " + known_fields(*descriptor) + ")");
    walked += (walked.empty() ? "" : ".") + parts[p];
    const pb::Reflection* reflection = message->GetReflection();
    const bool last = p + 1 == parts.size();
    if (field->is_repeated() != (index >= 0))
      throw ConfigError(where + "'" + name + "' " +
                        (field->is_repeated() ? "is a list: give an index, as " + name + "[0]"
                                              : "is not a list: drop the index"));
    if (field->is_repeated() && index >= reflection->FieldSize(*message, field))
      throw ConfigError(where + name + " has " +
                        std::to_string(reflection->FieldSize(*message, field)) +
                        " entries, no index " + std::to_string(index));
    if (last) {
      if (field->cpp_type() == pb::FieldDescriptor::CPPTYPE_MESSAGE) {
        pb::Message* target = field->is_repeated()
                                  ? reflection->MutableRepeatedMessage(message, field, index)
                                  : reflection->MutableMessage(message, field);
        target->Clear();
        if (!pb::TextFormat::ParseFromString(value, target))
          throw ConfigError(where + "cannot read '" + value + "' as " +
                            field->message_type()->name());
        return;
      }
      if (field->is_repeated())
        throw ConfigError(where + "setting one entry of a list of numbers is not supported");
      // A string as typed on a command line (solid.model=total_lagrangian) or
      // quoted as in a case file (title="short").
      if (field->cpp_type() == pb::FieldDescriptor::CPPTYPE_STRING && !value.starts_with('"') &&
          !value.starts_with('\'')) {
        reflection->SetString(message, field, value);
        return;
      }
      if (!pb::TextFormat::ParseFieldValueFromString(value, field, message))
        throw ConfigError(where + "cannot read '" + value + "' as the " + field->type_name() +
                          " that " + walked + " takes");
      return;
    }
    if (field->cpp_type() != pb::FieldDescriptor::CPPTYPE_MESSAGE)
      throw ConfigError(where + walked + " is a value, it has no field '" + parts[p + 1] + "'");
    message = field->is_repeated() ? reflection->MutableRepeatedMessage(message, field, index)
                                   : reflection->MutableMessage(message, field);
  }
}

void require_finite(const CaseFile& case_file) {
  // One walk over every number of the case, so that no field's own check can
  // forget it: an infinity or NaN compares false with everything and would
  // pass a check written as "refuse if x < 0".
  if (const auto found = first_non_finite(case_file.config, ""))
    throw ConfigError(case_file.path + ": " + found->field + ": must be a finite number, got " +
                      format_number(found->value));
}

void require(bool ok, const CaseFile& case_file, const std::string& field,
             const std::string& reason) {
  if (!ok) throw ConfigError(case_file.path + ": " + field + ": " + reason);
}

std::string format_number(double value, int significant_digits) {
  std::ostringstream out;
  out.precision(significant_digits);
  out << value;
  return out.str();
}

}  // namespace sph
