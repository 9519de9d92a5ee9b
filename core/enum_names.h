#pragma once
// One name table per enum, e.g. {{IntegratorKind::Path, "path"}, ...}: the one place an enum's
// spellings live, read both to parse a name (command line, scene file) and to list the choices
// (--help, the error message), so the two cannot drift apart.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"

namespace iblkit {

template <class E>
struct EnumName {
  E value;
  std::string_view name;
};

// "unknown <noun> '<text>' (expected one of a, b, c)".
std::string unknownNameProblem(std::string_view noun, std::string_view text,
                               const std::vector<std::string>& names);

// The names in table order, for CLI11 checks and help text.
template <class E, std::size_t N>
std::vector<std::string> enumNames(const EnumName<E> (&table)[N]) {
  std::vector<std::string> names;
  for (const EnumName<E>& entry : table) names.emplace_back(entry.name);
  return names;
}

// The value named `text`; otherwise throws Error("<what>: unknown <noun> '<text>' (expected one
// of a, b, c)"), `what` being the option or the file that gave the name.
template <class E, std::size_t N>
E parseEnumName(const EnumName<E> (&table)[N], std::string_view text, const std::string& what,
                std::string_view noun) {
  for (const EnumName<E>& entry : table)
    if (entry.name == text) return entry.value;
  fail(what, unknownNameProblem(noun, text, enumNames(table)));
}

// The name of `value`; "?" for a value the table lacks (a cast integer).
template <class E, std::size_t N>
std::string_view enumNameOf(const EnumName<E> (&table)[N], E value) {
  for (const EnumName<E>& entry : table)
    if (entry.value == value) return entry.name;
  return "?";
}

}  // namespace iblkit
