#pragma once
// Reading and writing images: OpenEXR (any compression OpenEXR reads; half or float; RGB, RGBA or
// Y), Radiance .hdr (RGBE, RLE), and 8-bit sRGB PNG through the tone curve.
// Loaders check what they read: NaN, Inf and negative pixels are repaired (set to 0) with a
// warning naming the file and the count, unless PixelRepair::Keep asks for the values as stored
// (the scorer reports such values itself; loadEnvironmentMap repairs negatives keeping the map's
// energy instead, energy_preserving_repair.h); anything unreadable throws Error("<file>: <problem>").

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/image.h"
#include "core/tone_curve.h"

namespace iblkit {

// How an OpenEXR file is laid out as an environment map (the standard `envmap` attribute).
enum class EnvmapLayout { None, LatLong, Cube };

enum class PixelType { Half, Float };

// What a loader does with NaN, infinite and negative pixel components: set them to 0 with a
// warning (repairPixels), or keep them as the file stores them.
enum class PixelRepair { Repair, Keep };

struct ExrWriteOptions {
  PixelType pixelType = PixelType::Half;
  bool writeAlpha = false;  // RGBA instead of RGB
  EnvmapLayout envmap = EnvmapLayout::None;
  // Extra string attributes written to the header (e.g. "iblkit:roughnessPerLevel"). The `{}`
  // lets callers write designated initializers ({.envmap = ...}) without -Wmissing-field-initializers.
  std::vector<std::pair<std::string, std::string>> stringAttributes{};
};

struct ExrInfo {
  int width = 0, height = 0;  // of level 0's data window
  EnvmapLayout envmap = EnvmapLayout::None;
  int levels = 1;  // mip levels in the file (1 for scanline or single-level tiled files)
  // Every string attribute, sorted by name, except the multi-part structure's "name" and "type".
  std::vector<std::pair<std::string, std::string>> stringAttributes;
};

// Reads level 0 (or `level`) of an OpenEXR file. Missing channels: Y becomes grey, missing A is 1.
// The image is the data window, wherever its origin (the pixels the file stores; ImfEnvmap.h also
// maps directions onto the data window). Deep, ripmapped and luminance/chroma files are refused.
Image readExr(const std::filesystem::path& file, ExrInfo* info = nullptr, int level = 0,
              PixelRepair repair = PixelRepair::Repair);
// Reads every mip level of a tiled, mip-mapped OpenEXR (a scanline file gives one level).
std::vector<Image> readExrLevels(const std::filesystem::path& file, ExrInfo* info = nullptr);
// Writes one image (scanline, ZIP), or a mip chain (tiled, MIPMAP_LEVELS, ROUND_DOWN) when
// levels.size() > 1. Writes to a temporary name and renames, so no partial file is left.
// Refuses NaN/Inf pixels, chains whose sizes are not floor(size / 2^level), and cube maps not
// W x 6W; values beyond the largest half (65504) are clamped with a warning when writing half.
void writeExr(const std::filesystem::path& file, const Image& image, const ExrWriteOptions& options = {});
void writeExrLevels(const std::filesystem::path& file, const std::vector<Image>& levels,
                    const ExrWriteOptions& options = {});

// Threads OpenEXR decodes and encodes line blocks and tiles with, for every file read or written
// after the call (Imf::setGlobalThreadCount; 0, OpenEXR's default, decodes on the calling thread).
// The same pixels whatever the count. runProgram (cli/program.h) gives every program the machine's
// cores: a large photograph's compressed blocks are most of its load time.
void setExrThreads(int count);

// Radiance RGBE (.hdr / .pic), flat or run-length encoded, -Y +X orientation.
Image readRadianceHdr(const std::filesystem::path& file, PixelRepair repair = PixelRepair::Repair);

// 8-bit sRGB PNG: exposure (in stops) and the tone curve applied, then sRGB-encoded.
// Alpha is written when writeAlpha is set. Temporary name, then rename.
void writePng(const std::filesystem::path& file, const Image& image, const ToneMapping& toneMapping = {},
              bool writeAlpha = false);
// Reads an 8-bit PNG (for the scorer's LDR inputs) into linear values (sRGB decoded).
Image readPng(const std::filesystem::path& file, PixelRepair repair = PixelRepair::Repair);

// Reads .exr, .hdr/.pic or .png by extension (case-insensitive).
Image readImage(const std::filesystem::path& file, PixelRepair repair = PixelRepair::Repair);

// Shared by the loaders above.

// How many pixel components (R, G, B or A) repairPixels set to 0. -Inf counts as Inf, not negative.
struct PixelRepairCounts {
  std::size_t nan = 0, inf = 0, negative = 0;
};
// Sets every NaN, infinite or negative component to 0 and, if any was found, warns once for
// `file` with the counts: "<file>: warning: 3 NaN, 1 Inf and 2 negative pixel values set to 0".
// All mip levels of a file are passed together, so a file gets at most one warning.
PixelRepairCounts repairPixels(const std::filesystem::path& file, std::span<Image> images);
// Counts what repairPixels would repair, changing nothing and warning nothing.
PixelRepairCounts countInvalidPixels(const Image& image);
// Sets NaN and infinite components to 0 and counts them (.negative stays 0), warning nothing:
// the first step of loadEnvironmentMap, whose negative values are repaired keeping the map's
// energy (energy_preserving_repair.h) rather than clamped.
PixelRepairCounts repairNonFinitePixels(Image& image);
// "3 NaN, 1 Inf and 2 negative pixel values set to 0" ("1 negative pixel value set to 0" for a
// single one), or "" when the counts are all 0: the text of repairPixels' warning.
std::string pixelRepairSummary(const PixelRepairCounts& counts);

// The largest image a loader accepts: 2^28 pixels (16384 x 16384, 4 GiB as RGBA float). A header
// claiming more is far more likely corrupt than real, and must not make us allocate it.
inline constexpr std::int64_t kMaxImagePixels = std::int64_t{1} << 28;
// Throws Error unless width and height are at least 1 and width * height <= kMaxImagePixels.
void checkImageSize(const std::filesystem::path& file, std::int64_t width, std::int64_t height);

}  // namespace iblkit
