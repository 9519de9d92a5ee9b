#pragma once
// The linear images of a case for the report page's large view (compare_view.h), whose exposure
// control tone-maps them in the browser: a page opened from the file system cannot read the
// pixels of its own PNGs (file:// images taint a canvas), but it can run a script beside it. So
// each case gets OUT/images/CASE-linear.js, which calls
//   iblkitCaseImages("CASE", {width, height, images: {"reference": "<base64>", MODE: ...}})
// with each image as RGBE (Ward's shared-exponent format: 4 bytes a pixel, 8 bits of mantissa),
// zlib-compressed (the browser's DecompressionStream("deflate")), in base64.

#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "core/image.h"

namespace iblkit {

// RGBE bytes of `image`, rows top to bottom; negative, NaN and infinite channels are written as 0
// (the report never writes a failed frame). decodeRgbe is the page's decoder, for tests.
std::vector<std::uint8_t> encodeRgbe(const Image& image);
glm::vec3 decodeRgbe(const std::uint8_t* rgbe);

// zlib (RFC 1950) compression (the text is then core/base64.h).
std::vector<std::uint8_t> zlibCompress(const std::vector<std::uint8_t>& bytes);
// Throws Error("zlib: ...") for corrupt data, or data that inflates to more than `maxBytes`.
std::vector<std::uint8_t> zlibDecompress(const std::vector<std::uint8_t>& bytes,
                                         std::size_t maxBytes = std::numeric_limits<std::size_t>::max());

// Writes `file` (atomically): the script above, `images` named as the page names them.
void writeCaseImagesScript(const std::filesystem::path& file, const std::string& caseName,
                           const std::vector<std::pair<std::string, const Image*>>& images);

// A script written by writeCaseImagesScript, read back (iblkit-view --reference REPORT --case):
// the images in the order written, linear (decodeRgbe), rows top to bottom, alpha 1.
struct CaseImagesScript {
  std::string caseName;
  std::vector<std::pair<std::string, Image>> images;
};
// Throws Error("<file>: <problem>") for a missing file or one that is not such a script.
CaseImagesScript readCaseImagesScript(const std::filesystem::path& file);

}  // namespace iblkit
