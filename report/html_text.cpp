#include "report/html_text.h"

#include <cmath>
#include <sstream>

namespace iblkit {

std::string escapeHtml(const std::string& text) {
  std::string escaped;
  for (const char c : text) {
    if (c == '<') escaped += "&lt;";
    else if (c == '>') escaped += "&gt;";
    else if (c == '&') escaped += "&amp;";
    else if (c == '"') escaped += "&quot;";
    else escaped += c;
  }
  return escaped;
}

std::string fixedText(double value, int digits) {
  if (!std::isfinite(value)) return "&ndash;";
  std::ostringstream text;
  text.setf(std::ios::fixed);
  text.precision(digits);
  text << value;
  return text.str();
}

}  // namespace iblkit
