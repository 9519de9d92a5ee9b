#include "bench/marked_section.h"

#include "core/error.h"

namespace iblkit {

std::string replaceMarkedSection(const std::string& document, const std::string& name,
                                 const std::string& text, const std::filesystem::path& file) {
  const std::string beginMarker = "<!-- " + name + ":begin -->", endMarker = "<!-- " + name + ":end -->";
  const std::size_t begin = document.find(beginMarker), end = document.find(endMarker);
  if (begin == std::string::npos || end == std::string::npos || end < begin)
    fail(file, "has no " + beginMarker + " ... " + endMarker + " section");
  const std::size_t afterBegin = begin + beginMarker.size();
  return document.substr(0, afterBegin) + "\n" + text + document.substr(end);
}

}  // namespace iblkit
