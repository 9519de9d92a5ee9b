#pragma once
// Text for the report's HTML and SVG: escaped for element content and attribute values, and
// numbers with a fixed number of digits (a missing number, NaN or infinite, as a dash).

#include <string>

namespace iblkit {

// `text` with & < > and " replaced by their entities (safe in content and in "..." attributes).
std::string escapeHtml(const std::string& text);

// `value` with `digits` decimals, or "&ndash;" when it is not finite.
std::string fixedText(double value, int digits);

}  // namespace iblkit
