#pragma once
// A node's parameters declared once, next to the Options struct they fill: each entry names
// the YAML key, the field (an accessor returning a reference into the Options), what it means
// and its range. The default shown by `papercraft nodes` and used when the YAML omits the key
// is the field's value in a default-constructed Options, so the two cannot drift apart.
//
//   const auto table = ParamTable<UnfoldOptions>().add(
//       "overlap_tolerance", [](UnfoldOptions& o) -> auto& { return o.overlap_tolerance; },
//       "relative penetration below which touching triangles do not overlap", at_least(0));
//   spec.params = table.specs();                      // declared, with defaults
//   UnfoldOptions options = table.read(params);       // filled from checked values

#include <functional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "graph/params.h"

namespace papercraft {

template <class Options>
class ParamTable {
 public:
  /// A field of type double (Number), bool (Boolean), an integer type (Integer),
  /// std::string (String) or std::vector<std::string> (StringList).
  template <class Access>
  ParamTable& add(std::string name, Access access, std::string description,
                  ParamRange range = {}, std::vector<std::string> choices = {}) {
    using Field = std::remove_reference_t<decltype(access(std::declval<Options&>()))>;
    Options defaults;
    ParamSpec spec{std::move(name), type_of<Field>(), "", std::move(description),
                   std::move(choices), range};
    spec.default_value = text_of(access(defaults));
    const std::string key = spec.name;
    entries_.push_back({std::move(spec), [key, access](const Params& params, Options& options) {
                          assign(access(options), params, key);
                        }});
    return *this;
  }

  /// An enum field written as one of `names` (name -> value, the first matching value names
  /// the default).
  template <class Access, class Enum>
  ParamTable& choice(std::string name, Access access,
                     std::vector<std::pair<std::string, Enum>> names, std::string description) {
    Options defaults;
    const Enum initial = access(defaults);
    std::vector<std::string> choices;
    std::string default_name;
    for (const auto& [text, value] : names) {
      choices.push_back(text);
      if (value == initial && default_name.empty()) default_name = text;
    }
    ParamSpec spec{std::move(name), ParamType::String, default_name, std::move(description),
                   choices};
    const std::string key = spec.name;
    entries_.push_back(
        {std::move(spec), [key, access, names](const Params& params, Options& options) {
           const std::string& text = params.string(key);
           for (const auto& [candidate, value] : names) {
             if (candidate == text) access(options) = value;
           }
         }});
    return *this;
  }

  /// A field of any type, converted by `to_text` (for the default) and `from_value` (from the
  /// value of the declared `type`; it throws std::invalid_argument on a value it cannot take,
  /// which the config parser reports with the value's file:line:column).
  template <class Access, class ToText, class FromValue>
  ParamTable& convert(std::string name, ParamType type, Access access, ToText to_text,
                      FromValue from_value, std::string description,
                      std::vector<std::string> choices = {}) {
    Options defaults;
    ParamSpec spec{std::move(name), type, to_text(access(defaults)), std::move(description),
                   std::move(choices)};
    spec.check = [from_value](const ParamValue& value) { (void)from_value(value); };
    const std::string key = spec.name;
    entries_.push_back(
        {std::move(spec), [key, access, from_value](const Params& params, Options& options) {
           access(options) = from_value(params.values().at(key));
         }});
    return *this;
  }

  std::vector<ParamSpec> specs() const {
    std::vector<ParamSpec> out;
    for (const auto& entry : entries_) out.push_back(entry.spec);
    return out;
  }

  /// `options` with every declared field set from `params` (which the builder filled with
  /// defaults and checked).
  Options read(const Params& params, Options options = {}) const {
    for (const auto& entry : entries_) entry.assign(params, options);
    return options;
  }

 private:
  struct Entry {
    ParamSpec spec;
    std::function<void(const Params&, Options&)> assign;
  };

  template <class Field>
  static constexpr ParamType type_of() {
    if constexpr (std::is_same_v<Field, bool>) {
      return ParamType::Boolean;
    } else if constexpr (std::is_integral_v<Field>) {
      return ParamType::Integer;
    } else if constexpr (std::is_floating_point_v<Field>) {
      return ParamType::Number;
    } else if constexpr (std::is_same_v<Field, std::string>) {
      return ParamType::String;
    } else {
      static_assert(std::is_same_v<Field, std::vector<std::string>>, "unsupported field type");
      return ParamType::StringList;
    }
  }

  template <class Field>
  static std::string text_of(const Field& value) {
    if constexpr (std::is_same_v<Field, bool>) {
      return value ? "true" : "false";
    } else if constexpr (std::is_integral_v<Field>) {
      return std::to_string(value);
    } else if constexpr (std::is_floating_point_v<Field>) {
      return format_number(value);
    } else {
      return format_param_value(ParamValue(value));
    }
  }

  template <class Field>
  static void assign(Field& field, const Params& params, const std::string& key) {
    if constexpr (std::is_same_v<Field, bool>) {
      field = params.boolean(key);
    } else if constexpr (std::is_integral_v<Field>) {
      field = static_cast<Field>(params.integer(key));
    } else if constexpr (std::is_floating_point_v<Field>) {
      field = static_cast<Field>(params.number(key));
    } else if constexpr (std::is_same_v<Field, std::string>) {
      field = params.string(key);
    } else {
      field = params.strings(key);
    }
  }

  std::vector<Entry> entries_;
};

}  // namespace papercraft
