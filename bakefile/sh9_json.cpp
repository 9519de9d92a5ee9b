#include "bakefile/sh9_json.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "core/error.h"
#include "core/file_io.h"
#include "core/input_file.h"

namespace iblkit {
namespace {

// Decimal text with 9 significant digits, enough to read back the same float (JSON has no
// NaN/Inf; the writer refuses them first).
std::string number(float value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", static_cast<double>(value));
  return text;
}

}  // namespace

void writeSh9Json(const std::filesystem::path& path, const SphericalHarmonics9& sh, float windowCutoff) {
  for (const glm::vec3& c : sh.coefficients)
    if (!std::isfinite(c.r) || !std::isfinite(c.g) || !std::isfinite(c.b))
      fail(path, "cannot write non-finite SH coefficients");
  std::string json = "{\n";
  json += "  \"basis\": \"real orthonormal SH, Sloan 2008 A1\",\n";
  json += "  \"order\": \"k = l(l+1)+m: Y00, Y1-1, Y10, Y11, Y2-2, Y2-1, Y20, Y21, Y22\",\n";
  json += "  \"coefficients\": \"L_k = integral L(w) Y_k(w) dw\",\n";
  json += "  \"irradiance\": \"E(n) = sum A_l L_k Y_k(n)\",\n";
  json += "  \"A_l\": [" + number(shCosineLobeBand(0)) + ", " + number(shCosineLobeBand(1)) + ", " +
          number(shCosineLobeBand(2)) + "],\n";
  json +=
      "  \"window\": \"sinc^4, w_l = (sin(x)/x)^4 with x = pi l / cutoff, applied to L_k; cutoff 0: "
      "none\",\n";
  json += "  \"windowCutoff\": " + number(windowCutoff) + ",\n";
  json += "  \"L\": [\n";
  for (int k = 0; k < kShCoefficients; ++k) {
    const glm::vec3& c = sh.coefficients[static_cast<std::size_t>(k)];
    json += "    [" + number(c.r) + ", " + number(c.g) + ", " + number(c.b) + "]";
    json += k + 1 < kShCoefficients ? ",\n" : "\n";
  }
  json += "  ]\n}\n";
  writeAtomically(path, [&](const std::filesystem::path& temporary) {
    std::ofstream out(temporary, std::ios::binary);
    out << json;
    out.close();
    if (!out) fail(path, "cannot write " + temporary.string());
  });
}

SphericalHarmonics9 readSh9Json(const std::filesystem::path& path, float* windowCutoff) {
  using nlohmann::json;
  const std::string text = readJsonText(path);
  try {
    const json document = json::parse(text);
    const json& coefficients = document.at("L");
    if (!coefficients.is_array() || coefficients.size() != kShCoefficients)
      fail(path, "\"L\" must hold 9 RGB coefficients");
    SphericalHarmonics9 sh;
    for (int k = 0; k < kShCoefficients; ++k) {
      const json& c = coefficients.at(std::size_t(k));
      sh.coefficients[std::size_t(k)] = glm::vec3(c.at(0).get<float>(), c.at(1).get<float>(), c.at(2).get<float>());
    }
    if (windowCutoff) *windowCutoff = document.at("windowCutoff").get<float>();
    return sh;
  } catch (const json::exception& e) {
    fail(path, std::string("malformed SH9 file: ") + e.what());
  }
}

}  // namespace iblkit
