#include "core/enum_names.h"

namespace iblkit {

std::string unknownNameProblem(std::string_view noun, std::string_view text,
                               const std::vector<std::string>& names) {
  std::string problem = "unknown ";
  problem += noun;
  problem += " '";
  problem += text;
  problem += "' (expected one of ";
  for (std::size_t i = 0; i < names.size(); ++i) problem += (i ? ", " : "") + names[i];
  return problem + ")";
}

}  // namespace iblkit
