#pragma once
// Text helpers for tests that read what a program printed or wrote: its lines, and how often a
// string occurs in it.

#include <sstream>
#include <string>
#include <vector>

namespace iblkit::test {

// The lines of `text`, without their newlines.
inline std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);) out.push_back(line);
  return out;
}

// How many times `what` (not empty) occurs in `text`, without overlaps.
inline std::size_t countOccurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

}  // namespace iblkit::test
