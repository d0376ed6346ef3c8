#pragma once
// Node parameters: declared with defaults and meaning (shown by `papercraft nodes`),
// given in YAML, converted and checked by the builder before any node runs.

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace papercraft {

enum class ParamType { Number, Integer, Boolean, String, StringList };

using ParamValue = std::variant<double, long, bool, std::string, std::vector<std::string>>;

/// The range a Number or Integer parameter must lie in (unset ends are open).
struct ParamRange {
  std::optional<double> minimum;
  std::optional<double> maximum;
  bool minimum_exclusive = false;  // value > minimum instead of >=
  bool maximum_exclusive = false;  // value < maximum instead of <=

  /// "at least 1", "greater than 0", "between 0 and 0.5", "at most 180"; "" when unbounded.
  std::string describe() const;
  bool contains(double value) const;
};

/// A closed range [minimum, maximum]; at_least(x) and greater_than(x) are open above.
ParamRange between(double minimum, double maximum);
ParamRange at_least(double minimum);
ParamRange greater_than(double minimum);

struct ParamSpec {
  std::string name;
  ParamType type = ParamType::Number;
  std::string default_value;  // as written in YAML: "0.05", "true", "A4", "[pdf, svg]"
  std::string description;
  std::vector<std::string> choices = {};  // for String / StringList: allowed values (empty: any)
  ParamRange range = {};                  // for Number / Integer
  /// Further checks of a parsed value (throws std::invalid_argument saying what is wrong),
  /// run wherever the value is parsed, so `validate` catches what only the node understands.
  std::function<void(const ParamValue&)> check = {};
};

const char* to_string(ParamType type);

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
/// the given type, checked against the spec's choices and range. Throws std::invalid_argument
/// with "expected ..." (or "must be ...") on a bad value.
ParamValue parse_param_value(const ParamSpec& spec, const std::string& text);

std::string format_param_value(const ParamValue& value);

/// A number as a person writes it and as it reads back exactly: "0.05", "200", "1e-09".
std::string format_number(double value);

/// Reads the number at the start of `text` (as std::stod) into `value` and returns how many
/// characters it used: 0 when `text` does not start with a number or it is out of range.
std::size_t parse_number_prefix(const std::string& text, double& value);

}  // namespace papercraft
