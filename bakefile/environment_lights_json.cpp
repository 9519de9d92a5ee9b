#include "bakefile/environment_lights_json.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <glm/gtc/constants.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/file_io.h"
#include "core/input_file.h"

namespace iblkit {
namespace {

using nlohmann::json;

constexpr const char* kKind = "iblkit environment lights";

// Decimal text with 9 significant digits, enough to read back the same float. Throws for a
// non-finite value (JSON has none), naming what it is.
std::string number(float value, const std::filesystem::path& path, const std::string& what) {
  if (!std::isfinite(value)) fail(path, "cannot write non-finite " + what);
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", static_cast<double>(value));
  return text;
}

std::string vector3(const glm::vec3& v, const std::filesystem::path& path, const std::string& what) {
  std::string text = "[";
  text += number(v.x, path, what) + ", " + number(v.y, path, what) + ", " + number(v.z, path, what) + "]";
  return text;
}

std::string lightText(const EnvironmentLight& light, const std::filesystem::path& path,
                      const std::string& what) {
  std::string text = "    {\"direction\": " + vector3(light.direction, path, what + ".direction") +
                     ", \"irradiance\": " + vector3(light.irradiance, path, what + ".irradiance") +
                     ", \"radiance\": " + vector3(light.radiance, path, what + ".radiance") +
                     ",\n     \"solidAngle\": " + number(light.solidAngle, path, what + ".solidAngle") +
                     ", \"angularRadius\": " + number(light.angularRadius, path, what + ".angularRadius") +
                     ", \"texels\": [" + std::to_string(light.x0) + ", " + std::to_string(light.y0) + ", " +
                     std::to_string(light.x1) + ", " + std::to_string(light.y1) + "],\n     \"sh9\": [";
  for (int k = 0; k < kShCoefficients; ++k) {
    if (k > 0) text += ", ";
    text += vector3(light.sh9.coefficients[std::size_t(k)], path, what + ".sh9");
  }
  return text + "]}";
}

std::string listText(const std::vector<EnvironmentLight>& lights, const std::filesystem::path& path,
                     const std::string& name) {
  if (lights.empty()) return "[]";
  std::string text = "[\n";
  for (std::size_t i = 0; i < lights.size(); ++i)
    text += lightText(lights[i], path, name + "[" + std::to_string(i) + "]") +
            (i + 1 < lights.size() ? ",\n" : "\n");
  return text + "  ]";
}

// Readers of one entry; each throws Error("<path>: <what>: <problem>").
class EntryReader {
 public:
  explicit EntryReader(const std::filesystem::path& path) : path_(path) {}

  [[noreturn]] void bad(const std::string& what, const std::string& problem) const {
    fail(path_, what + ": " + problem);
  }

  const json& member(const json& object, const char* key, const std::string& what) const {
    if (!object.is_object()) bad(what, "expected an object");
    const auto found = object.find(key);
    if (found == object.end()) bad(what, std::string("missing \"") + key + "\"");
    return *found;
  }

  float finite(const json& value, const std::string& what) const {
    if (!value.is_number()) bad(what, "expected a number");
    const double number = value.get<double>();
    if (!std::isfinite(number) || std::abs(number) > 3.4e38) bad(what, "expected a finite number");
    return float(number);
  }

  glm::vec3 vector3(const json& value, const std::string& what) const {
    if (!value.is_array() || value.size() != 3) bad(what, "expected 3 numbers");
    return {finite(value[0], what), finite(value[1], what), finite(value[2], what)};
  }

  int integer(const json& value, const std::string& what) const {
    if (!value.is_number_integer()) bad(what, "expected an integer");
    const long long n = value.get<long long>();
    if (n < 0 || n > (1 << 30)) bad(what, "expected an integer in 0..2^30");
    return int(n);
  }

  EnvironmentLight light(const json& entry, EnvironmentLightKind kind, const std::string& what) const {
    EnvironmentLight light;
    light.kind = kind;
    const glm::vec3 direction = vector3(member(entry, "direction", what), what + ".direction");
    if (std::abs(glm::length(direction) - 1.0f) > 1e-3f) bad(what + ".direction", "not a unit vector");
    // Written unit length; renormalised only when a hand edit left it a little off.
    light.direction = std::abs(glm::length(direction) - 1.0f) > 1e-6f ? glm::normalize(direction) : direction;
    light.irradiance = vector3(member(entry, "irradiance", what), what + ".irradiance");
    light.radiance = vector3(member(entry, "radiance", what), what + ".radiance");
    if (glm::any(glm::lessThan(light.irradiance, glm::vec3(0.0f)))) bad(what + ".irradiance", "negative");
    if (glm::any(glm::lessThan(light.radiance, glm::vec3(0.0f)))) bad(what + ".radiance", "negative");
    const float pi = glm::pi<float>();
    light.solidAngle = finite(member(entry, "solidAngle", what), what + ".solidAngle");
    if (!(light.solidAngle > 0.0f && light.solidAngle <= 4.0f * pi * (1.0f + 1e-6f)))
      bad(what + ".solidAngle", "expected a solid angle in (0, 4 pi]");
    light.angularRadius = finite(member(entry, "angularRadius", what), what + ".angularRadius");
    if (!(light.angularRadius >= 0.0f && light.angularRadius <= pi * (1.0f + 1e-6f)))
      bad(what + ".angularRadius", "expected an angle in [0, pi]");
    // The engine's suns are disks of at most kMaxSunAngularRadius (sun extraction keeps no wider
    // one): its horizon-band irradiance (shaders/lights.glsl sunDiskIrradiance) and its shadow
    // maps' blocker search hold up to there. A hand edit past it is refused, not drawn wrong.
    if (kind == EnvironmentLightKind::Sun && light.angularRadius > kMaxSunAngularRadius * (1.0f + 1e-6f))
      bad(what + ".angularRadius", "wider than a sun (at most 10 degrees, 0.1745 radians)");
    const json& texels = member(entry, "texels", what);
    if (!texels.is_array() || texels.size() != 4) bad(what + ".texels", "expected [x0, y0, x1, y1]");
    light.x0 = integer(texels[0], what + ".texels");
    light.y0 = integer(texels[1], what + ".texels");
    light.x1 = integer(texels[2], what + ".texels");
    light.y1 = integer(texels[3], what + ".texels");
    if (light.x1 <= light.x0 || light.y1 <= light.y0) bad(what + ".texels", "empty rectangle");
    const json& sh9 = member(entry, "sh9", what);
    if (!sh9.is_array() || sh9.size() != kShCoefficients) bad(what + ".sh9", "expected 9 RGB coefficients");
    for (int k = 0; k < kShCoefficients; ++k)
      light.sh9.coefficients[std::size_t(k)] = vector3(sh9[std::size_t(k)], what + ".sh9");
    return light;
  }

  std::vector<EnvironmentLight> list(const json& document, const char* key, EnvironmentLightKind kind) const {
    const json& entries = member(document, key, "lights");
    if (!entries.is_array()) bad(key, "expected a list");
    std::vector<EnvironmentLight> lights;
    for (std::size_t i = 0; i < entries.size(); ++i)
      lights.push_back(light(entries[i], kind, std::string(key) + "[" + std::to_string(i) + "]"));
    return lights;
  }

 private:
  const std::filesystem::path& path_;
};

}  // namespace

void writeEnvironmentLightsJson(const std::filesystem::path& path, const EnvironmentLights& lights) {
  std::string text = "{\n";
  text += "  \"kind\": \"" + std::string(kKind) + "\",\n";
  text +=
      "  \"units\": \"world directions toward the light; irradiance = sum of radiance x solid angle of its "
      "texels, radiance = irradiance / solidAngle, 2 pi (1 - cos angularRadius) = solidAngle; the map's "
      "intensity applied; sh9 as env/sh9.json\",\n";
  text += "  \"sunThreshold\": " + number(lights.sunThreshold, path, "sunThreshold") + ",\n";
  text += "  \"medianCutLevels\": " + std::to_string(lights.medianCutLevels) + ",\n";
  text += "  \"suns\": " + listText(lights.suns, path, "suns") + ",\n";
  text += "  \"medianCut\": " + listText(lights.medianCut, path, "medianCut") + "\n}\n";
  writeAtomically(path, [&](const std::filesystem::path& temporary) {
    std::ofstream out(temporary, std::ios::binary);
    out << text;
    out.close();
    if (!out) fail(path, "cannot write " + temporary.string());
  });
}

EnvironmentLights readEnvironmentLightsJson(const std::filesystem::path& path) {
  const std::string text = readJsonText(path);
  json document;
  try {
    document = json::parse(text);
  } catch (const json::exception& e) {
    fail(path, std::string("not valid JSON: ") + e.what());
  }
  const EntryReader reader(path);
  const json& kind = reader.member(document, "kind", "lights");
  if (kind != kKind)
    reader.bad("kind", std::string("expected \"") + kKind + "\" (not an iblkit lights file)");
  EnvironmentLights lights;
  lights.sunThreshold = reader.finite(reader.member(document, "sunThreshold", "lights"), "sunThreshold");
  if (lights.sunThreshold < 0.0f) reader.bad("sunThreshold", "negative");
  lights.medianCutLevels =
      reader.integer(reader.member(document, "medianCutLevels", "lights"), "medianCutLevels");
  if (lights.medianCutLevels > 12) reader.bad("medianCutLevels", "expected 0..12");
  lights.suns = reader.list(document, "suns", EnvironmentLightKind::Sun);
  lights.medianCut = reader.list(document, "medianCut", EnvironmentLightKind::MedianCut);
  return lights;
}

}  // namespace iblkit
