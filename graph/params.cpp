#include "graph/params.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace papercraft {

const char* to_string(ParamType type) {
  switch (type) {
    case ParamType::Number:
      return "number";
    case ParamType::Integer:
      return "integer";
    case ParamType::Boolean:
      return "boolean";
    case ParamType::String:
      return "string";
    case ParamType::StringList:
      return "list of strings";
  }
  return "?";
}

const ParamValue& Params::at(const std::string& name) const {
  auto it = values_.find(name);
  if (it == values_.end()) throw std::logic_error("parameter '" + name + "' was not declared");
  return it->second;
}

double Params::number(const std::string& name) const {
  const ParamValue& value = at(name);
  if (const long* i = std::get_if<long>(&value)) return static_cast<double>(*i);
  return std::get<double>(value);
}
long Params::integer(const std::string& name) const {
  return std::get<long>(at(name));
}
bool Params::boolean(const std::string& name) const {
  return std::get<bool>(at(name));
}
const std::string& Params::string(const std::string& name) const {
  return std::get<std::string>(at(name));
}
const std::vector<std::string>& Params::strings(const std::string& name) const {
  return std::get<std::vector<std::string>>(at(name));
}

namespace {

std::string trim(std::string text) {
  auto not_space = [](unsigned char c) { return !std::isspace(c); };
  text.erase(text.begin(), std::find_if(text.begin(), text.end(), not_space));
  text.erase(std::find_if(text.rbegin(), text.rend(), not_space).base(), text.end());
  return text;
}

void check_choice(const ParamSpec& spec, const std::string& value) {
  if (spec.choices.empty() ||
      std::find(spec.choices.begin(), spec.choices.end(), value) != spec.choices.end()) {
    return;
  }
  std::string list;
  for (const auto& c : spec.choices) list += (list.empty() ? "" : ", ") + c;
  throw std::invalid_argument("expected one of " + list + ", got '" + value + "'");
}

void check_range(const ParamSpec& spec, double value, const std::string& text) {
  if (spec.range.contains(value)) return;
  throw std::invalid_argument("must be " + spec.range.describe() + ", got " + text);
}

}  // namespace

std::string format_number(double value) {
  char buffer[40];
  for (int digits : {15, 17}) {
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
    if (std::strtod(buffer, nullptr) == value) break;
  }
  return buffer;
}

bool ParamRange::contains(double value) const {
  if (minimum && (minimum_exclusive ? !(value > *minimum) : !(value >= *minimum))) return false;
  if (maximum && (maximum_exclusive ? !(value < *maximum) : !(value <= *maximum))) return false;
  return true;
}

std::string ParamRange::describe() const {
  const std::string low = minimum ? format_number(*minimum) : "";
  const std::string high = maximum ? format_number(*maximum) : "";
  if (minimum && maximum) {
    if (!minimum_exclusive && !maximum_exclusive) return "between " + low + " and " + high;
    return std::string(minimum_exclusive ? "greater than " : "at least ") + low + " and " +
           (maximum_exclusive ? "less than " : "at most ") + high;
  }
  if (minimum) return (minimum_exclusive ? "greater than " : "at least ") + low;
  if (maximum) return (maximum_exclusive ? "less than " : "at most ") + high;
  return "";
}

ParamRange between(double minimum, double maximum) {
  return {minimum, maximum, false, false};
}
ParamRange at_least(double minimum) {
  return {minimum, std::nullopt, false, false};
}
ParamRange greater_than(double minimum) {
  return {minimum, std::nullopt, true, false};
}

std::size_t parse_number_prefix(const std::string& text, double& value) {
  std::size_t used = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  return used;
}

namespace {

ParamValue parse_unchecked(const ParamSpec& spec, const std::string& raw) {
  const std::string text = trim(raw);
  switch (spec.type) {
    case ParamType::Number: {
      double value = 0;
      const std::size_t used = parse_number_prefix(text, value);
      if (used == 0 || used != text.size() || !std::isfinite(value)) {
        throw std::invalid_argument("expected a number, got '" + text + "'");
      }
      check_range(spec, value, text);
      return value;
    }
    case ParamType::Integer: {
      std::size_t used = 0;
      long value = 0;
      try {
        value = std::stol(text, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != text.size()) {
        throw std::invalid_argument("expected an integer, got '" + text + "'");
      }
      check_range(spec, static_cast<double>(value), text);
      return value;
    }
    case ParamType::Boolean:
      if (text == "true" || text == "yes" || text == "on") return true;
      if (text == "false" || text == "no" || text == "off") return false;
      throw std::invalid_argument("expected true or false, got '" + text + "'");
    case ParamType::String:
      check_choice(spec, text);
      return text;
    case ParamType::StringList: {
      std::string inner = text;
      if (!inner.empty() && inner.front() == '[') {
        if (inner.back() != ']')
          throw std::invalid_argument("expected a list [a, b], got '" + text + "'");
        inner = inner.substr(1, inner.size() - 2);
      }
      std::vector<std::string> items;
      std::size_t start = 0;
      while (start <= inner.size()) {
        std::size_t comma = inner.find(',', start);
        if (comma == std::string::npos) comma = inner.size();
        std::string item = trim(inner.substr(start, comma - start));
        if (!item.empty()) {
          check_choice(spec, item);
          items.push_back(item);
        }
        start = comma + 1;
      }
      return items;
    }
  }
  throw std::logic_error("unknown parameter type");
}

}  // namespace

ParamValue parse_param_value(const ParamSpec& spec, const std::string& raw) {
  ParamValue value = parse_unchecked(spec, raw);
  if (spec.check) spec.check(value);
  return value;
}

std::string format_param_value(const ParamValue& value) {
  struct Visitor {
    std::string operator()(double v) const { return format_number(v); }
    std::string operator()(long v) const { return std::to_string(v); }
    std::string operator()(bool v) const { return v ? "true" : "false"; }
    std::string operator()(const std::string& v) const { return v; }
    std::string operator()(const std::vector<std::string>& v) const {
      std::string s = "[";
      for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + v[i];
      return s + "]";
    }
  };
  return std::visit(Visitor{}, value);
}

}  // namespace papercraft
