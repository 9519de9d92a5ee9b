#pragma once
// Generated text inside a hand-written document: the lines between "<!-- NAME:begin -->" and
// "<!-- NAME:end -->" belong to the program that writes section NAME (docs/benchmarks.md holds the
// sampling study's tables this way); everything outside the markers stays as written.

#include <filesystem>
#include <string>

namespace iblkit {

// `document` with everything between the markers of section `name` replaced by a newline and
// `text`; the markers and the rest are kept byte for byte. Throws Error("<file>: has no
// <!-- NAME:begin --> ... <!-- NAME:end --> section") when a marker is missing or the end comes
// first; `file` only names the document in that message.
std::string replaceMarkedSection(const std::string& document, const std::string& name,
                                 const std::string& text, const std::filesystem::path& file);

}  // namespace iblkit
