// Radiance RGBE (.hdr / .pic) reader, written from Greg Ward's descriptions of the format:
// "Real Pixels" (Graphics Gems II, 1991) for the RGBE encoding, and "Radiance File Formats"
// (Radiance reference manual, section "Picture File Format (.hdr suffix)") for the header, the
// resolution string and the run-length encoding of scanlines.
//
// Header lines other than FORMAT are ignored. In particular EXPOSURE (the factor the pixels have
// been multiplied by since they were computed) is not divided out: the values are read as stored,
// as other tools do, so that a map reads the same here as in every viewer.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "core/file_io.h"
#include "core/image_io.h"

namespace iblkit {

namespace {

// Widths the run-length encoding can describe: the scanline header stores the width in 15 bits,
// and scanlines shorter than 8 pixels are always stored flat.
constexpr int kMinRleWidth = 8, kMaxRleWidth = 0x7fff;
// A run of identical bytes is stored as (128 + count, byte), so one run covers at most 127.
constexpr int kMaxRun = 127;

struct Resolution {
  int width = 0, height = 0;
};

// Reads the header lines, checks the signature and FORMAT, and parses the resolution string.
// Leaves `position` at the first byte of pixel data.
class HeaderParser {
 public:
  HeaderParser(const std::filesystem::path& file, std::string_view text) : file_(file), text_(text) {}

  Resolution parse(std::size_t& position) {
    if (!text_.starts_with("#?")) fail(file_, "not a Radiance HDR file (no \"#?RADIANCE\" signature)");
    for (std::string_view line = nextLine(); !line.empty(); line = nextLine()) {
      constexpr std::string_view kFormat = "FORMAT=";
      if (!line.starts_with(kFormat)) continue;
      const std::string_view format = line.substr(kFormat.size());
      if (format != "32-bit_rle_rgbe")
        fail(file_, "unsupported FORMAT=" + printableExcerpt(format) + " (only 32-bit_rle_rgbe)");
    }
    const Resolution resolution = parseResolution(nextLine());
    position = position_;
    return resolution;
  }

 private:
  // The next line, without its line ending.
  std::string_view nextLine() {
    const std::size_t end = text_.find('\n', position_);
    if (end == std::string_view::npos) fail(file_, "truncated header (no blank line and resolution string)");
    std::string_view line = text_.substr(position_, end - position_);
    position_ = end + 1;
    if (line.ends_with('\r')) line.remove_suffix(1);
    return line;
  }

  // "-Y H +X W": H scanlines from the top down, each W pixels from left to right, which is the
  // Image layout. The other seven orientations are legal but rare, and not supported.
  Resolution parseResolution(std::string_view line) {
    std::vector<std::string_view> tokens;
    std::size_t start = line.find_first_not_of(' ');
    while (start != std::string_view::npos) {
      const std::size_t end = std::min(line.find(' ', start), line.size());
      tokens.push_back(line.substr(start, end - start));
      start = line.find_first_not_of(' ', end);
    }
    const auto isAxis = [](std::string_view t) { return t == "-Y" || t == "+Y" || t == "-X" || t == "+X"; };
    std::int64_t sizes[2] = {0, 0};
    const bool wellFormed = tokens.size() == 4 && isAxis(tokens[0]) && isAxis(tokens[2]) &&
                            tokens[0][1] != tokens[2][1] && parseSize(tokens[1], sizes[0]) &&
                            parseSize(tokens[3], sizes[1]);
    std::string quoted = "\"";  // built in steps: GCC 12 gives a false -Wrestrict on "\"" + string
    quoted.append(printableExcerpt(line)).push_back('"');
    if (!wellFormed) fail(file_, "bad resolution string " + quoted);
    if (tokens[0] != "-Y" || tokens[2] != "+X")
      fail(file_, "unsupported orientation " + quoted + " (only \"-Y H +X W\")");
    checkImageSize(file_, sizes[1], sizes[0]);
    return {static_cast<int>(sizes[1]), static_cast<int>(sizes[0])};
  }

  static bool parseSize(std::string_view token, std::int64_t& value) {
    const char* end = token.data() + token.size();
    const std::from_chars_result result = std::from_chars(token.data(), end, value);
    return result.ec == std::errc() && result.ptr == end && value >= 0;
  }

  const std::filesystem::path& file_;
  std::string_view text_;
  std::size_t position_ = 0;
};

// Decodes scanlines of RGBE quadruples, never reading past the end of the data.
class ScanlineDecoder {
 public:
  ScanlineDecoder(const std::filesystem::path& file, std::span<const std::uint8_t> data, int width)
      : file_(file), data_(data), width_(width), rgbe_(static_cast<std::size_t>(width) * 4) {}

  // The fewest bytes any scanline of this width can take (flat, or run-length encoded with every
  // component in runs of 127), so an image whose pixel data is certainly missing is rejected
  // before its pixels are allocated.
  std::size_t minScanlineBytes() const {
    const std::size_t flat = static_cast<std::size_t>(width_) * 4;
    if (width_ < kMinRleWidth || width_ > kMaxRleWidth) return flat;
    return std::min(flat, 4 + 4 * 2 * static_cast<std::size_t>((width_ + kMaxRun - 1) / kMaxRun));
  }

  // Decodes scanline y into `row` (width linear RGB pixels, alpha 1).
  void decode(int y, glm::vec4* row) {
    y_ = y;
    if (isRleScanline())
      decodeRle();
    else
      decodeFlat();
    for (int x = 0; x < width_; ++x) {
      const std::uint8_t* p = &rgbe_[static_cast<std::size_t>(x) * 4];
      row[x] = glm::vec4(rgbeToFloat(p[0], p[3]), rgbeToFloat(p[1], p[3]), rgbeToFloat(p[2], p[3]), 1.0f);
    }
  }

 private:
  // Ward, "Real Pixels": three 8-bit mantissas share one exponent byte, biased by 128. Like
  // Radiance's colr_color (src/common/color.c), we decode to the middle of the quantisation step:
  // (m + 0.5) * 2^(e - 128 - 8). An exponent byte of 0 is black.
  static float rgbeToFloat(std::uint8_t mantissa, std::uint8_t exponent) {
    if (exponent == 0) return 0.0f;
    return std::ldexp(static_cast<float>(mantissa) + 0.5f, static_cast<int>(exponent) - (128 + 8));
  }

  // A run-length encoded scanline starts with the bytes 2, 2 and the width in 15 bits (high
  // byte first); a flat scanline cannot start that way, since a normalised RGBE pixel with an
  // exponent has a mantissa of at least 128.
  bool isRleScanline() const {
    if (width_ < kMinRleWidth || width_ > kMaxRleWidth || data_.size() - position_ < 4) return false;
    const std::uint8_t* p = &data_[position_];
    return p[0] == 2 && p[1] == 2 && (p[2] & 0x80) == 0;
  }

  // The four components are stored one after the other, each as a sequence of runs
  // (128 + count, byte) and literal spans (count, count bytes), count > 0.
  void decodeRle() {
    const int encodedWidth = (data_[position_ + 2] << 8) | data_[position_ + 3];
    if (encodedWidth != width_)
      corrupt("run-length scanline of width " + std::to_string(encodedWidth) + " in an image of width " +
              std::to_string(width_));
    position_ += 4;
    for (int c = 0; c < 4; ++c) {
      for (int x = 0; x < width_;) {
        const int code = next();
        const bool run = code > 128;
        const int count = run ? code - 128 : code;
        if (count == 0 || count > width_ - x)
          corrupt("run of " + std::to_string(count) + " at pixel " + std::to_string(x) + " of " +
                  std::to_string(width_));
        const int value = run ? next() : 0;
        for (int i = 0; i < count; ++i, ++x)
          rgbe_[static_cast<std::size_t>(x) * 4 + static_cast<std::size_t>(c)] =
              static_cast<std::uint8_t>(run ? value : next());
      }
    }
  }

  // Uncompressed RGBE quadruples. The original, pre-1991 encoding marked runs in them with
  // (1, 1, 1, n), which no normalised pixel can be; that encoding is refused, not misread.
  void decodeFlat() {
    const std::size_t bytes = rgbe_.size();
    if (data_.size() - position_ < bytes) truncated();
    std::copy_n(&data_[position_], bytes, rgbe_.begin());
    position_ += bytes;
    for (std::size_t i = 0; i < bytes; i += 4)
      if (rgbe_[i] == 1 && rgbe_[i + 1] == 1 && rgbe_[i + 2] == 1)
        fail(file_, "scanline " + std::to_string(y_) + " uses the old run-length encoding (not supported)");
  }

  int next() {
    if (position_ >= data_.size()) truncated();
    return data_[position_++];
  }

  [[noreturn]] void truncated() const {
    fail(file_, "truncated pixel data (scanline " + std::to_string(y_) + " is incomplete)");
  }
  [[noreturn]] void corrupt(const std::string& what) const {
    fail(file_, "corrupt scanline " + std::to_string(y_) + ": " + what);
  }

  const std::filesystem::path& file_;
  std::span<const std::uint8_t> data_;
  int width_;
  std::vector<std::uint8_t> rgbe_;  // one scanline, RGBE interleaved
  std::size_t position_ = 0;
  int y_ = 0;
};

}  // namespace

Image readRadianceHdr(const std::filesystem::path& file, PixelRepair repair) {
  const std::vector<char> bytes = readFileBytes(file);
  std::size_t position = 0;
  const Resolution resolution =
      HeaderParser(file, std::string_view(bytes.data(), bytes.size())).parse(position);
  const std::span<const std::uint8_t> pixelData(
      reinterpret_cast<const std::uint8_t*>(bytes.data()) + position, bytes.size() - position);
  ScanlineDecoder decoder(file, pixelData, resolution.width);
  if (pixelData.size() / decoder.minScanlineBytes() < static_cast<std::size_t>(resolution.height))
    fail(file, "truncated pixel data: " + std::to_string(resolution.width) + " x " +
                   std::to_string(resolution.height) + " pixels need at least " +
                   std::to_string(decoder.minScanlineBytes() * static_cast<std::size_t>(resolution.height)) +
                   " bytes, the file has " + std::to_string(pixelData.size()));
  Image image(resolution.width, resolution.height);
  for (int y = 0; y < resolution.height; ++y)
    decoder.decode(y,
                   &image.pixels()[static_cast<std::size_t>(y) * static_cast<std::size_t>(resolution.width)]);
  if (repair == PixelRepair::Repair) repairPixels(file, {&image, 1});
  return image;
}

}  // namespace iblkit
