#include "report/page_images.h"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/base64.h"
#include "core/error.h"
#include "core/file_io.h"

namespace iblkit {

namespace fs = std::filesystem;

std::vector<std::uint8_t> encodeRgbe(const Image& image) {
  std::vector<std::uint8_t> bytes;
  bytes.reserve(image.pixelCount() * 4);
  for (const glm::vec4& pixel : image.pixels()) {
    float rgb[3];
    for (int c = 0; c < 3; ++c) rgb[c] = std::isfinite(pixel[c]) && pixel[c] > 0.0f ? pixel[c] : 0.0f;
    const float largest = std::max({rgb[0], rgb[1], rgb[2]});
    if (largest < 1e-32f) {
      bytes.insert(bytes.end(), {0, 0, 0, 0});
      continue;
    }
    int exponent = 0;
    const float mantissa = std::frexp(largest, &exponent);  // largest = mantissa 2^exponent, mantissa in [0.5, 1)
    if (exponent > 127) {  // beyond RGBE's range: the largest it holds
      bytes.insert(bytes.end(), {255, 255, 255, 255});
      continue;
    }
    const float scale = mantissa * 256.0f / largest;
    for (int c = 0; c < 3; ++c) bytes.push_back(std::uint8_t(std::min(255.0f, rgb[c] * scale)));
    bytes.push_back(std::uint8_t(exponent + 128));
  }
  return bytes;
}

glm::vec3 decodeRgbe(const std::uint8_t* rgbe) {
  if (rgbe[3] == 0) return glm::vec3(0.0f);
  const float factor = std::ldexp(1.0f, int(rgbe[3]) - (128 + 8));
  return glm::vec3((rgbe[0] + 0.5f) * factor, (rgbe[1] + 0.5f) * factor, (rgbe[2] + 0.5f) * factor);
}

std::vector<std::uint8_t> zlibCompress(const std::vector<std::uint8_t>& bytes) {
  uLongf size = compressBound(uLong(bytes.size()));
  std::vector<std::uint8_t> compressed(size);
  if (compress2(compressed.data(), &size, bytes.data(), uLong(bytes.size()), 6) != Z_OK)
    throw Error("zlib: cannot compress");
  compressed.resize(size);
  return compressed;
}

std::vector<std::uint8_t> zlibDecompress(const std::vector<std::uint8_t>& bytes, std::size_t maxBytes) {
  z_stream stream{};
  if (inflateInit(&stream) != Z_OK) throw Error("zlib: cannot start inflate");
  std::vector<std::uint8_t> result;
  std::uint8_t buffer[65536];
  stream.next_in = const_cast<Bytef*>(bytes.data());
  stream.avail_in = uInt(bytes.size());
  int status = Z_OK;
  while (status == Z_OK) {
    stream.next_out = buffer;
    stream.avail_out = sizeof(buffer);
    status = inflate(&stream, Z_NO_FLUSH);
    result.insert(result.end(), buffer, buffer + (sizeof(buffer) - stream.avail_out));
    if (result.size() > maxBytes) {
      inflateEnd(&stream);
      throw Error("zlib: the data inflates to more than the " + std::to_string(maxBytes) + " bytes expected");
    }
  }
  inflateEnd(&stream);
  if (status != Z_STREAM_END) throw Error("zlib: corrupt data");
  return result;
}

void writeCaseImagesScript(const fs::path& file, const std::string& caseName,
                           const std::vector<std::pair<std::string, const Image*>>& images) {
  if (images.empty() || !images.front().second) fail(file, "no images to write");
  const Image& first = *images.front().second;
  std::string script = "iblkitCaseImages(\"" + caseName + "\", {\"width\": " + std::to_string(first.width()) +
                       ", \"height\": " + std::to_string(first.height()) + ", \"images\": {\n";
  for (std::size_t i = 0; i < images.size(); ++i) {
    const Image& image = *images[i].second;
    if (image.width() != first.width() || image.height() != first.height())
      fail(file, "image '" + images[i].first + "' differs in size from '" + images.front().first + "'");
    script += "\"" + images[i].first + "\": \"" + base64(zlibCompress(encodeRgbe(image))) + "\"" +
              (i + 1 < images.size() ? ",\n" : "\n");
  }
  script += "}});\n";
  writeAtomically(file, [&](const fs::path& temporary) {
    std::ofstream stream(temporary, std::ios::binary);
    stream << script;
    if (!stream.flush()) fail(file, "cannot write file");
  });
}

}  // namespace iblkit

namespace iblkit {

CaseImagesScript readCaseImagesScript(const fs::path& file) {
  std::ifstream stream(file, std::ios::binary);
  if (!stream) fail(file, "cannot open: No such file or directory");
  std::ostringstream text;
  text << stream.rdbuf();
  const std::string script = text.str();
  // iblkitCaseImages("CASE", {...});  the object is JSON (writeCaseImagesScript).
  static constexpr std::string_view kCall = "iblkitCaseImages(\"";
  const std::size_t nameEnd = script.find('"', kCall.size());
  const std::size_t objectStart = script.find('{');
  const std::size_t objectEnd = script.rfind('}');
  if (script.rfind(kCall, 0) != 0 || nameEnd == std::string::npos || objectStart == std::string::npos ||
      objectEnd == std::string::npos || objectEnd < objectStart)
    fail(file, "not a report's linear images script (expected iblkitCaseImages(\"CASE\", {...}))");
  CaseImagesScript result;
  result.caseName = script.substr(kCall.size(), nameEnd - kCall.size());
  try {
    const nlohmann::ordered_json object = nlohmann::ordered_json::parse(script.substr(objectStart, objectEnd - objectStart + 1));
    const int width = object.at("width").get<int>(), height = object.at("height").get<int>();
    constexpr int kMaxSide = 16384;  // the programs' largest image side
    if (width <= 0 || height <= 0 || width > kMaxSide || height > kMaxSide)
      fail(file, "bad size " + std::to_string(width) + "x" + std::to_string(height) + " (each side 1.." +
                     std::to_string(kMaxSide) + ")");
    const std::size_t expected = std::size_t(width) * std::size_t(height) * 4;
    for (const auto& [name, data] : object.at("images").items()) {
      // No more than the size asks for is inflated (a zlib bomb stops there).
      const std::vector<std::uint8_t> rgbe = zlibDecompress(base64Decode(data.get<std::string>()), expected);
      if (rgbe.size() != expected)
        fail(file, "image '" + name + "' has " + std::to_string(rgbe.size() / 4) + " pixels, not " +
                       std::to_string(width) + "x" + std::to_string(height));
      Image image(width, height);
      for (std::size_t i = 0; i < image.pixelCount(); ++i) image.pixels()[i] = glm::vec4(decodeRgbe(&rgbe[4 * i]), 1.0f);
      result.images.emplace_back(name, std::move(image));
    }
  } catch (const nlohmann::json::exception& e) {
    fail(file, std::string("not a report's linear images script: ") + e.what());
  } catch (const Error& e) {
    const std::string what = e.what();
    if (what.rfind(file.string() + ":", 0) == 0) throw;
    fail(file, what);  // zlib's or base64's
  }
  if (result.images.empty()) fail(file, "no images");
  return result;
}

}  // namespace iblkit
