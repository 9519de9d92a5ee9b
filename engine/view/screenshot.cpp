#include "engine/view/screenshot.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <ctime>
#include <vector>

#include "core/error.h"
#include "core/image_io.h"
#include "core/tone_curve.h"

namespace iblkit {

namespace fs = std::filesystem;

ScreenshotFiles screenshotFiles(const fs::path& requested) {
  std::string extension = requested.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  fs::path stem = requested;
  if (extension == ".exr" || extension == ".png")
    stem.replace_extension();
  else if (!extension.empty())
    fail(requested, "unsupported screenshot format (expected .exr, .png or no extension)");
  ScreenshotFiles files{fs::path(stem).concat(".exr"), fs::path(stem).concat(".png")};
  if (extension == ".exr") files.exr = requested;
  if (extension == ".png") files.png = requested;
  return files;
}

ScreenshotFiles timestampedScreenshotFiles(const fs::path& folder) {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &utc);
  const std::string base = std::string("iblkit-view-") + stamp;
  for (int n = 0;; ++n) {
    const fs::path stem = folder / (n == 0 ? base : base + "-" + std::to_string(n));
    ScreenshotFiles files = screenshotFiles(stem);
    if (!fs::exists(files.exr) && !fs::exists(files.png)) return files;
  }
}

Image readDisplayedPixels(int x, int y, int width, int height) {
  std::vector<unsigned char> bytes(std::size_t(width) * std::size_t(height) * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(x, y, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
  Image image(width, height);
  for (int row = 0; row < height; ++row)
    for (int column = 0; column < width; ++column) {
      // GL's row 0 is the bottom one.
      const unsigned char* p =
          &bytes[(std::size_t(height - 1 - row) * std::size_t(width) + std::size_t(column)) * 4];
      image.at(column, row) =
          glm::vec4(srgbDecode(p[0] / 255.0f), srgbDecode(p[1] / 255.0f), srgbDecode(p[2] / 255.0f), 1.0f);
    }
  return image;
}

void writeScreenshot(const ScreenshotFiles& files, const Image& radiance, const Image& displayed) {
  writeExr(files.exr, radiance, {.pixelType = PixelType::Float, .writeAlpha = true});
  writePng(files.png, displayed, {.exposure = 0.0f, .curve = ToneCurve::Clamp});
}

}  // namespace iblkit
