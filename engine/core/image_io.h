#pragma once
// Reading and writing images: OpenEXR (any compression OpenEXR reads; half or float; RGB, RGBA or
// Y), Radiance .hdr (RGBE, RLE), and 8-bit sRGB PNG through the tone curve.
// Loaders check what they read: NaN, Inf and negative pixels are repaired (set to 0) with a
// warning naming the file and the count; anything unreadable throws Error("<file>: <problem>").

#include <filesystem>
#include <vector>

#include "engine/core/image.h"
#include "engine/core/tone_curve.h"

namespace iblkit {

// How an OpenEXR file is laid out as an environment map (the standard `envmap` attribute).
enum class EnvmapLayout { None, LatLong, Cube };

enum class PixelType { Half, Float };

struct ExrWriteOptions {
  PixelType pixelType = PixelType::Half;
  bool writeAlpha = false;           // RGBA instead of RGB
  EnvmapLayout envmap = EnvmapLayout::None;
  // Extra string attributes written to the header (e.g. "iblkit:roughnessPerLevel").
  std::vector<std::pair<std::string, std::string>> stringAttributes;
};

struct ExrInfo {
  int width = 0, height = 0;
  EnvmapLayout envmap = EnvmapLayout::None;
  int levels = 1;  // mip levels in the file (1 for scanline or single-level tiled files)
  std::vector<std::pair<std::string, std::string>> stringAttributes;
};

// Reads level 0 (or `level`) of an OpenEXR file. Missing channels: Y becomes grey, missing A is 1.
Image readExr(const std::filesystem::path& file, ExrInfo* info = nullptr, int level = 0);
// Reads every mip level of a tiled, mip-mapped OpenEXR (a scanline file gives one level).
std::vector<Image> readExrLevels(const std::filesystem::path& file, ExrInfo* info = nullptr);
// Writes one image (scanline, ZIP), or a mip chain (tiled, MIPMAP_LEVELS, ROUND_DOWN) when
// levels.size() > 1. Writes to a temporary name and renames, so no partial file is left.
void writeExr(const std::filesystem::path& file, const Image& image, const ExrWriteOptions& options = {});
void writeExrLevels(const std::filesystem::path& file, const std::vector<Image>& levels,
                    const ExrWriteOptions& options = {});

// Radiance RGBE (.hdr / .pic), flat or run-length encoded, -Y +X orientation.
Image readRadianceHdr(const std::filesystem::path& file);

// 8-bit sRGB PNG: exposure (in stops) and the tone curve applied, then sRGB-encoded.
// Alpha is written when writeAlpha is set. Temporary name, then rename.
void writePng(const std::filesystem::path& file, const Image& image, const ToneMapping& toneMapping = {},
              bool writeAlpha = false);
// Reads an 8-bit PNG (for the scorer's LDR inputs) into linear values (sRGB decoded).
Image readPng(const std::filesystem::path& file);

// Reads .exr, .hdr/.pic or .png by extension (case-insensitive).
Image readImage(const std::filesystem::path& file);

}  // namespace iblkit
