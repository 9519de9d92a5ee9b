#pragma once
// Screenshots of the viewer: the live frame's linear radiance as OpenEXR (float RGBA, alpha = the
// coverage of non-ground objects, as iblkit-view --headless -o writes it) and what the window shows
// (tone-mapped, and the reference comparison when one is on; the panel left out) as PNG.
#include <filesystem>

#include "core/image.h"

namespace iblkit {

struct ScreenshotFiles {
  std::filesystem::path exr, png;
};

// --screenshot FILE: FILE.exr or FILE.png names one of the pair, the other gets the same stem;
// no extension: FILE.exr and FILE.png. Any other extension throws Error("<FILE>: ...").
ScreenshotFiles screenshotFiles(const std::filesystem::path& requested);
// The P key: iblkit-view-YYYYMMDD-HHMMSS[-N].{exr,png} in `folder`, N counting up so that no
// existing screenshot is overwritten.
ScreenshotFiles timestampedScreenshotFiles(const std::filesystem::path& folder);

// Reads back the (x, y, w, h) rectangle of the current read framebuffer (the window's back
// buffer, display values) as linear values (sRGB decoded), row 0 at the top, alpha 1.
Image readDisplayedPixels(int x, int y, int width, int height);

// Writes both files (each under a temporary name, then renamed): `radiance` as float RGBA EXR,
// `displayed` (linear, from readDisplayedPixels) as 8-bit sRGB PNG without further tone mapping.
void writeScreenshot(const ScreenshotFiles& files, const Image& radiance, const Image& displayed);

}  // namespace iblkit
