#pragma once
// Node parameters: declared with defaults and meaning (shown by `papercraft nodes`),
// given in YAML, converted and checked by the builder before any node runs.

#include <map>
#include <string>
#include <variant>
#include <vector>

namespace papercraft {

enum class ParamType { Number, Integer, Boolean, String, StringList };

struct ParamSpec {
  std::string name;
  ParamType type = ParamType::Number;
  std::string default_value;  // as written in YAML: "0.05", "true", "A4", "[pdf, svg]"
  std::string description;
  std::vector<std::string> choices = {};  // for String / StringList: allowed values (empty: any)
};

const char* to_string(ParamType type);

using ParamValue = std::variant<double, long, bool, std::string, std::vector<std::string>>;

/// Checked parameter values of one node (defaults filled in).
class Params {
 public:
  Params() = default;
  explicit Params(std::map<std::string, ParamValue> values) : values_(std::move(values)) {}

  double number(const std::string& name) const;
  long integer(const std::string& name) const;
  bool boolean(const std::string& name) const;
  const std::string& string(const std::string& name) const;
  const std::vector<std::string>& strings(const std::string& name) const;
  bool has(const std::string& name) const { return values_.count(name) > 0; }
  const std::map<std::string, ParamValue>& values() const { return values_; }

 private:
  const ParamValue& at(const std::string& name) const;
  std::map<std::string, ParamValue> values_;
};

/// Convert a scalar or list written in YAML style ("0.5", "true", "[a, b]") to a value of
/// the given type. Throws std::invalid_argument with "expected ..." on a bad value.
ParamValue parse_param_value(const ParamSpec& spec, const std::string& text);

std::string format_param_value(const ParamValue& value);

/// Reads the number at the start of `text` (as std::stod) into `value` and returns how many
/// characters it used: 0 when `text` does not start with a number or it is out of range.
std::size_t parse_number_prefix(const std::string& text, double& value);

}  // namespace papercraft
