// OpenEXR reading and writing through the general FrameBuffer interface, so every compression
// OpenEXR knows (the fetched maps are DWAB) and both half and float channels read the same way.
#include <Iex.h>
#include <Imath/half.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>
#include <ImfTestFile.h>
#include <ImfThreading.h>
#include <ImfTiledInputFile.h>
#include <ImfTiledOutputFile.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/error.h"
#include "core/file_io.h"
#include "core/image_io.h"

namespace iblkit {

namespace {

// Channel names in Image component order.
constexpr const char* kRgbaNames[4] = {"R", "G", "B", "A"};
// Tile size of mip-mapped files; levels smaller than a tile are stored as one partial tile.
constexpr int kTileSize = 64;
// The largest finite half.
constexpr float kHalfMax = static_cast<float>(HALF_MAX);

// OpenEXR reads the file from memory rather than opening it itself, so that a missing or empty
// file reads the same for every format (readFileBytes), and so that a truncated file can be told
// apart from other damage: any read past the end is recorded.
class MemoryStream final : public Imf::IStream {
 public:
  MemoryStream(const std::filesystem::path& file, std::vector<char> bytes)
      : Imf::IStream(file.c_str()), bytes_(std::move(bytes)) {}

  bool isMemoryMapped() const override { return true; }
  char* readMemoryMapped(int n) override { return take(n); }
  bool read(char c[], int n) override {
    std::memcpy(c, take(n), static_cast<std::size_t>(n));
    return position_ < bytes_.size();
  }
  uint64_t tellg() override { return position_; }
  void seekg(uint64_t position) override { position_ = position; }  // checked by the next read

  bool readPastEnd() const { return readPastEnd_; }
  const std::vector<char>& bytes() const { return bytes_; }

 private:
  char* take(int n) {
    if (n < 0 || position_ > bytes_.size() || bytes_.size() - position_ < static_cast<std::uint64_t>(n)) {
      readPastEnd_ = true;
      throw Iex::InputExc("unexpected end of file");
    }
    char* data = bytes_.data() + position_;
    position_ += static_cast<std::uint64_t>(n);
    return data;
  }

  std::vector<char> bytes_;
  std::uint64_t position_ = 0;
  bool readPastEnd_ = false;
};

// OpenEXR's message as the problem part of ours: one line, and without its own preamble naming
// the file ("Cannot read image file "<file>". "), which fail() already puts first.
std::string exrProblem(const std::filesystem::path& file, std::string text) {
  const std::string preambleEnd = "\"" + file.string() + "\". ";
  if (const std::size_t at = text.find(preambleEnd); at != std::string::npos)
    text.erase(0, at + preambleEnd.size());
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

// Runs `body`, turning OpenEXR's exceptions (Iex, std) into Error; our own Errors pass through.
template <class Body>
auto rethrowAsError(const std::filesystem::path& file, const MemoryStream* stream, Body&& body) {
  try {
    return body();
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    if (stream && stream->readPastEnd()) fail(file, "truncated file (unexpected end of data)");
    fail(file, exrProblem(file, e.what()));
  }
}

// A slice of `components` interleaved values of `type` per pixel, starting at component `c`,
// addressed with the data window's absolute coordinates (Slice::Make does the offset safely).
Imf::Slice interleavedSlice(Imf::PixelType type, const void* base, std::size_t componentBytes, int components,
                            int c, const Imath::Box2i& window, double fillValue = 0.0) {
  const std::size_t width = static_cast<std::size_t>(window.max.x - window.min.x + 1);
  const std::size_t xStride = componentBytes * static_cast<std::size_t>(components);
  return Imf::Slice::Make(type, static_cast<const char*>(base) + componentBytes * static_cast<std::size_t>(c),
                          window, xStride, xStride * width, 1, 1, fillValue);
}

EnvmapLayout envmapLayout(const Imf::Header& header) {
  if (!Imf::hasEnvmap(header)) return EnvmapLayout::None;
  return Imf::envmap(header) == Imf::ENVMAP_CUBE ? EnvmapLayout::Cube : EnvmapLayout::LatLong;
}

// An open OpenEXR file as a list of levels: a scanline file has one, a tiled file one per mip level.
// The image of a level is its data window; for environment maps the data window is the map
// (ImfEnvmap.h maps directions to data-window pixel positions), whatever its origin.
// A file cannot hold much more pixel data than its size: uncompressed data is stored as is, and
// OpenEXR's codecs stay far below kMaxCompressionRatio (deflate's limit is about 1032:1). A header
// claiming more (a few hundred bytes claiming a 2^27-pixel data window, found by fuzz/fuzz_exr)
// is refused before OpenEXR sizes its line buffers by it and before we allocate its image.
// `bytesPerPixel`: the stored bytes of one pixel, summed over the channels (subsampling applied).
void checkFileCanHold(const std::filesystem::path& file, std::int64_t width, std::int64_t height,
                      double bytesPerPixel, bool compressed, std::size_t fileBytes) {
  constexpr double kMaxCompressionRatio = 4096.0;
  if (width < 1 || height < 1) return;  // OpenEXR or checkImageSize reports it
  const double ratio = compressed ? kMaxCompressionRatio : 1.0;
  if (double(width) * double(height) * bytesPerPixel > ratio * double(fileBytes))
    fail(file, "data window of " + std::to_string(width) + " x " + std::to_string(height) +
                   " pixels holds more data than the file's " + std::to_string(fileBytes) +
                   " bytes can (truncated or corrupt header)");
}

class ExrLevelReader {
 public:
  // `headerEnd`: where the single-part header ends and the chunk offset table starts (0: unknown).
  ExrLevelReader(const std::filesystem::path& file, MemoryStream& stream, std::size_t fileBytes,
                 std::size_t headerEnd)
      : file_(file), fileBytes_(fileBytes) {
    bool tiled = false, deep = false, multiPart = false;
    if (!Imf::isOpenExrFile(stream, tiled, deep, multiPart))
      fail(file, "not an OpenEXR file (bad magic number)");
    if (deep) fail(file, "deep OpenEXR images are not supported");
    if (multiPart) fail(file, "multi-part OpenEXR files are not supported");
    if (tiled) {
      tiledFile_.emplace(stream);
      levels_ = countLevels(*tiledFile_);
      if (headerEnd > 0) checkTileSizes(stream.bytes(), headerEnd);
    } else {
      scanlineFile_.emplace(stream);
      checkScanlineChunkSizes();
    }
  }

  int levels() const { return levels_; }
  const Imf::Header& header() const { return tiledFile_ ? tiledFile_->header() : scanlineFile_->header(); }

  ExrInfo info() const {
    ExrInfo info;
    const Imath::Box2i& window = header().dataWindow();
    info.width = window.max.x - window.min.x + 1;
    info.height = window.max.y - window.min.y + 1;
    info.envmap = envmapLayout(header());
    info.levels = levels_;
    // "name" and "type" describe the file's structure (multi-part files), not the image.
    for (auto it = header().begin(); it != header().end(); ++it) {
      const auto* text = dynamic_cast<const Imf::StringAttribute*>(&it.attribute());
      const std::string name = it.name();
      if (text && name != "name" && name != "type") info.stringAttributes.emplace_back(name, text->value());
    }
    return info;
  }

  Image read(int level) {
    if (level < 0 || level >= levels_)
      fail(file_,
           "has no level " + std::to_string(level) + " (levels 0 to " + std::to_string(levels_ - 1) + ")");
    if (scanlineFile_) {
      const Imath::Box2i window = scanlineFile_->header().dataWindow();
      return readWindow(window, [&](const Imf::FrameBuffer& frameBuffer) {
        scanlineFile_->setFrameBuffer(frameBuffer);
        scanlineFile_->readPixels(window.min.y, window.max.y);
      });
    }
    return readWindow(tiledFile_->dataWindowForLevel(level), [&](const Imf::FrameBuffer& frameBuffer) {
      tiledFile_->setFrameBuffer(frameBuffer);
      tiledFile_->readTiles(0, tiledFile_->numXTiles(level) - 1, 0, tiledFile_->numYTiles(level) - 1, level);
    });
  }

 private:
  int countLevels(const Imf::TiledInputFile& in) const {
    switch (in.header().tileDescription().mode) {
      case Imf::ONE_LEVEL:
        return 1;
      case Imf::MIPMAP_LEVELS:
        return in.numLevels();
      default:
        fail(file_, "ripmap levels are not supported");
    }
  }

  // The bytes `window` holds uncompressed: every channel's samples (subsampled channels have
  // fewer) at their type's size, as OpenEXR lays a chunk out.
  std::uint64_t uncompressedBytes(const Imath::Box2i& window) const {
    const auto samples = [](int lo, int hi, int sampling) -> std::uint64_t {
      if (sampling <= 0 || hi < lo) return 0;
      const auto firstAtOrAbove = [&](std::int64_t v) {
        const std::int64_t r = ((v % sampling) + sampling) % sampling;
        return r == 0 ? v : v + (sampling - r);
      };
      const std::int64_t first = firstAtOrAbove(lo);
      return first > hi ? 0 : std::uint64_t((hi - first) / sampling + 1);
    };
    std::uint64_t bytes = 0;
    for (auto c = header().channels().begin(); c != header().channels().end(); ++c) {
      const std::uint64_t size = c.channel().type == Imf::HALF ? 2 : 4;
      bytes += size * samples(window.min.x, window.max.x, c.channel().xSampling) *
               samples(window.min.y, window.max.y, c.channel().ySampling);
    }
    return bytes;
  }

  // Every chunk must hold the bytes its scanlines need: OpenEXR 3.1 copies an uncompressed chunk
  // (or one stored raw because compression did not help) into the frame buffer without checking
  // its size, and so reads past the data of a chunk shorter than its lines (a dataWindow wider than
  // the chunk). A compressed chunk is at most that size; its decompressor checks the rest.
  void checkScanlineChunkSizes() {
    const Imath::Box2i window = header().dataWindow();
    const int lines = linesPerChunk(header().compression());
    for (std::int64_t y = window.min.y; y <= window.max.y; y += lines) {
      const char* data = nullptr;
      int size = 0;
      scanlineFile_->rawPixelData(int(y), data, size);
      Imath::Box2i chunk = window;
      chunk.min.y = int(y);
      chunk.max.y = int(std::min<std::int64_t>(window.max.y, y + lines - 1));
      checkChunkSize(size, uncompressedBytes(chunk), "scanline chunk at y " + std::to_string(y));
    }
  }

  // The same for a tiled file, walking its offset table ourselves (OpenEXR's rawTileData crashed on
  // a memory-mapped stream): the table follows the header, one 8-byte offset per tile, level by
  // level; each tile is tx, ty, level x, level y and a size (4-byte ints) and then its data. A
  // table too long for the file is left to OpenEXR (it reports it). An offset outside the file, or
  // a tile header naming no tile of the file, is refused: OpenEXR 3.1 then rebuilds the table by
  // scanning the tiles and read past a tile's data (a fuzz finding, fuzz/corpus/exr).
  void checkTileSizes(const std::vector<char>& bytes, std::size_t headerEnd) const {
    const Imf::TiledInputFile& in = *tiledFile_;
    std::uint64_t tiles = 0;
    for (int level = 0; level < levels_; ++level)
      tiles += std::uint64_t(in.numXTiles(level)) * std::uint64_t(in.numYTiles(level));
    if (tiles > (bytes.size() - std::min(bytes.size(), headerEnd)) / 8) return;  // OpenEXR reports it
    for (std::uint64_t i = 0; i < tiles; ++i) {
      std::uint64_t offset = 0;
      std::memcpy(&offset, bytes.data() + headerEnd + 8 * i, sizeof offset);
      if (offset < headerEnd || offset > bytes.size() || bytes.size() - offset < 20)
        fail(file_, "tile offset " + std::to_string(i) + " points outside the file (corrupt or truncated file?)");
      std::int32_t fields[5] = {};  // tx, ty, lx, ly, size
      std::memcpy(fields, bytes.data() + offset, sizeof fields);
      const auto [tx, ty, lx, ly, size] = fields;
      if (lx != ly || lx < 0 || lx >= levels_ || tx < 0 || tx >= in.numXTiles(lx) || ty < 0 ||
          ty >= in.numYTiles(lx))
        fail(file_, "tile offset " + std::to_string(i) + " points at no tile of the file (corrupt file?)");
      const std::string what = "tile " + std::to_string(tx) + ", " + std::to_string(ty) + " of level " +
                               std::to_string(lx);
      checkChunkSize(size, uncompressedBytes(in.dataWindowForTile(tx, ty, lx)), what);
      if (std::uint64_t(size) > bytes.size() - offset - 20)
        fail(file_, what + " runs past the end of the file (truncated file?)");
    }
  }

  void checkChunkSize(int size, std::uint64_t expected, const std::string& what) const {
    const bool raw = header().compression() == Imf::NO_COMPRESSION || std::uint64_t(size) >= expected;
    if (size < 0 || (raw && std::uint64_t(size) != expected))
      fail(file_, what + " holds " + std::to_string(size) + " bytes, but its pixels need " +
                      std::to_string(expected) + " uncompressed (corrupt or truncated file?)");
  }

  static int linesPerChunk(Imf::Compression compression) {
    switch (compression) {
      case Imf::ZIP_COMPRESSION:
      case Imf::PXR24_COMPRESSION:
        return 16;
      case Imf::PIZ_COMPRESSION:
      case Imf::B44_COMPRESSION:
      case Imf::B44A_COMPRESSION:
      case Imf::DWAA_COMPRESSION:
        return 32;
      case Imf::DWAB_COMPRESSION:
        return 256;
      default:  // NO, RLE, ZIPS
        return 1;
    }
  }

  // Reads the pixels of `window` as linear RGBA floats (OpenEXR converts half and uint): missing
  // channels read as 0 and a missing A as 1; a luminance-only (Y) file reads as grey.
  template <class ReadPixels>
  Image readWindow(const Imath::Box2i& window, ReadPixels&& readPixels) {
    checkImageSize(file_, std::int64_t{window.max.x} - window.min.x + 1,
                   std::int64_t{window.max.y} - window.min.y + 1);
    const Imf::ChannelList& channels = header().channels();
    const bool grey = !channels.findChannel("R") && !channels.findChannel("G") && !channels.findChannel("B");
    if (grey && !channels.findChannel("Y")) fail(file_, "no R, G, B or Y channel");
    if (grey && (channels.findChannel("RY") || channels.findChannel("BY")))
      fail(file_, "luminance/chroma (Y, RY, BY) images are not supported");
    checkFileCanHold(window);
    Image image(window.max.x - window.min.x + 1, window.max.y - window.min.y + 1);
    Imf::FrameBuffer frameBuffer;
    for (int c = 0; c < 4; ++c) {
      const char* name = grey && c == 0 ? "Y" : kRgbaNames[c];
      if (grey && (c == 1 || c == 2)) continue;
      const Imf::Channel* channel = channels.findChannel(name);
      if (channel && (channel->xSampling != 1 || channel->ySampling != 1))
        fail(file_, std::string("channel ") + name + " is subsampled (not supported)");
      frameBuffer.insert(name, interleavedSlice(Imf::FLOAT, image.pixels().data(), sizeof(float), 4, c,
                                                window, c == 3 ? 1.0 : 0.0));
    }
    readPixels(frameBuffer);
    if (grey)
      for (glm::vec4& pixel : image.pixels()) pixel.g = pixel.b = pixel.r;
    return image;
  }

  void checkFileCanHold(const Imath::Box2i& window) const {
    double bytesPerPixel = 0.0;
    for (auto it = header().channels().begin(); it != header().channels().end(); ++it)
      bytesPerPixel += (it.channel().type == Imf::HALF ? 2.0 : 4.0) /
                       (std::max(it.channel().xSampling, 1) * double(std::max(it.channel().ySampling, 1)));
    iblkit::checkFileCanHold(file_, std::int64_t{window.max.x} - window.min.x + 1,
                             std::int64_t{window.max.y} - window.min.y + 1, bytesPerPixel,
                             header().compression() != Imf::NO_COMPRESSION, fileBytes_);
  }

  std::filesystem::path file_;
  std::size_t fileBytes_ = 0;
  std::optional<Imf::InputFile> scanlineFile_;
  std::optional<Imf::TiledInputFile> tiledFile_;
  int levels_ = 1;
};

// How many bytes OpenEXR 3.1's Header::readFrom consumes for the value of an attribute of type
// `type` whose declared size is `size`, starting at `at`: the fixed size of a fixed-size type
// (read whatever the declared size), a channel list up to its empty name, and the declared size
// for the rest (strings, vectors, previews, whose size OpenEXR checks against their dimensions, and
// types it does not know, kept as opaque bytes). Nullopt when the bytes end first.
std::optional<std::uint64_t> attributeValueBytes(const std::vector<char>& bytes, std::size_t at,
                                                 std::string_view type, std::int32_t size) {
  static constexpr std::pair<std::string_view, std::uint64_t> kFixed[] = {
      {"box2i", 16},     {"box2f", 16}, {"chromaticities", 32}, {"compression", 1}, {"double", 8},
      {"envmap", 1},     {"float", 4},  {"int", 4},             {"keycode", 28},    {"lineOrder", 1},
      {"m33f", 36},      {"m33d", 72},  {"m44f", 64},           {"m44d", 128},      {"rational", 8},
      {"tiledesc", 9},   {"timecode", 8}, {"v2i", 8},           {"v2f", 8},         {"v2d", 16},
      {"v3i", 12},       {"v3f", 12},   {"v3d", 24},            {"deepImageState", 1}};
  for (const auto& [name, fixed] : kFixed)
    if (type == name) return fixed;
  if (type == "chlist") {  // name\0 and 16 bytes per channel, up to an empty name
    std::size_t end = at;
    for (;;) {
      if (end >= bytes.size()) return std::nullopt;
      if (bytes[end] == '\0') return end + 1 - at;
      const auto nul = std::find(bytes.begin() + static_cast<std::ptrdiff_t>(end), bytes.end(), '\0');
      if (nul == bytes.end()) return std::nullopt;
      end = static_cast<std::size_t>(nul - bytes.begin()) + 1 + 16;
    }
  }
  return static_cast<std::uint64_t>(std::max(size, 0));
}

// The stored bytes of one pixel of the channel list at `at` (attributeValueBytes found it whole):
// per channel, name\0, pixel type (0 uint, 1 half, 2 float), pLinear and 3 reserved bytes, x and
// y sampling.
double channelListBytesPerPixel(const std::vector<char>& bytes, std::size_t at) {
  double total = 0.0;
  while (bytes[at] != '\0') {
    at = static_cast<std::size_t>(std::find(bytes.begin() + static_cast<std::ptrdiff_t>(at), bytes.end(), '\0') -
                                  bytes.begin()) + 1;
    std::int32_t fields[4] = {};  // pixel type, pLinear + reserved, x sampling, y sampling
    std::memcpy(fields, bytes.data() + at, sizeof fields);
    total += (fields[0] == 1 ? 2.0 : 4.0) / (std::max(fields[2], 1) * double(std::max(fields[3], 1)));
    at += 16;
  }
  return total;
}

// OpenEXR allocates an attribute's value before reading it: an attribute of a type it does not
// know at the size the header claims (OpaqueAttribute). A 445-byte file claiming a 2 GiB
// attribute made it allocate and clear 2 GiB before it found the file truncated (found by
// fuzz/fuzz_exr). So the header is walked first as OpenEXR reads it (a walk by the declared sizes
// alone got out of step with OpenEXR's reads through a channel list on a second fuzzed file), and
// a value running past the end of the file is a truncated file. What the walk cannot follow (a
// name without its NUL) is left to OpenEXR, which reports it. Returns where a single-part header
// ends (its offset table starts), 0 for a multi-part file or a header the walk could not follow.
std::size_t checkHeaderAttributeSizes(const std::filesystem::path& file, const std::vector<char>& bytes) {
  constexpr std::uint32_t kMultiPartFlag = 0x1000;
  constexpr char kMagic[4] = {0x76, 0x2f, 0x31, 0x01};
  if (bytes.size() < 8 || std::memcmp(bytes.data(), kMagic, 4) != 0) return 0;  // OpenEXR reports it
  std::uint32_t version = 0;
  std::memcpy(&version, bytes.data() + 4, sizeof version);
  std::size_t at = 8;
  const auto readString = [&](std::string_view* text) {
    const auto end = std::find(bytes.begin() + static_cast<std::ptrdiff_t>(at), bytes.end(), '\0');
    if (end == bytes.end()) return false;
    *text = std::string_view(bytes.data() + at, static_cast<std::size_t>(end - bytes.begin()) - at);
    at = static_cast<std::size_t>(end - bytes.begin()) + 1;
    return true;
  };
  for (;;) {  // one header, or each part's header up to the empty one ending a multi-part file
    bool empty = true;
    std::optional<std::array<std::int32_t, 4>> dataWindow;
    bool compressed = true;      // OpenEXR's default header is ZIP-compressed
    double bytesPerPixel = 0.0;  // a second channel list adds its channels to the first
    for (;;) {
      if (at >= bytes.size()) return 0;
      if (bytes[at] == '\0') {
        ++at;
        // The data window against the file before OpenEXR sizes its line buffers by it.
        if (dataWindow)
          checkFileCanHold(file, std::int64_t{(*dataWindow)[2]} - (*dataWindow)[0] + 1,
                           std::int64_t{(*dataWindow)[3]} - (*dataWindow)[1] + 1, bytesPerPixel, compressed,
                           bytes.size());
        break;
      }
      empty = false;
      std::string_view name, type;
      if (!readString(&name) || !readString(&type) || bytes.size() - at < 4) return 0;
      std::int32_t size = 0;
      std::memcpy(&size, bytes.data() + at, sizeof size);
      at += 4;
      if (size < 0) return 0;  // OpenEXR refuses it before reading
      const std::optional<std::uint64_t> value = attributeValueBytes(bytes, at, type, size);
      if (!value || *value > bytes.size() - at) fail(file, "truncated file (unexpected end of data)");
      if (name == "dataWindow" && type == "box2i") {
        dataWindow.emplace();
        std::memcpy(dataWindow->data(), bytes.data() + at, 16);
      } else if (name == "compression" && type == "compression") {
        compressed = bytes[at] != 0;
      } else if (name == "channels" && type == "chlist") {
        bytesPerPixel += channelListBytesPerPixel(bytes, at);
      }
      at += static_cast<std::size_t>(*value);
    }
    if (!(version & kMultiPartFlag)) return at;
    if (empty) return 0;
  }
}

// Opens `file` and runs use(reader), with OpenEXR's errors turned into Error.
template <class Use>
auto withExrFile(const std::filesystem::path& file, Use&& use) {
  std::vector<char> bytes = readFileBytes(file);
  const std::size_t headerEnd = checkHeaderAttributeSizes(file, bytes);
  const std::size_t fileBytes = bytes.size();
  MemoryStream stream(file, std::move(bytes));
  return rethrowAsError(file, &stream, [&] {
    ExrLevelReader reader(file, stream, fileBytes, headerEnd);
    return use(reader);
  });
}

// Checks what OpenEXR cannot represent or we would not read back: an empty image, a chain whose
// sizes are not the ROUND_DOWN mip sizes, a cube map not laid out as six stacked faces, NaN/Inf.
void checkLevelsForWriting(const std::filesystem::path& file, std::span<const Image> levels,
                           const ExrWriteOptions& options) {
  if (levels.empty() || levels[0].empty()) fail(file, "cannot write an empty image");
  const int width = levels[0].width(), height = levels[0].height();
  if (levels.size() > 1) {
    // MIPMAP_LEVELS with ROUND_DOWN: level l is floor(size / 2^l), at least 1, down to 1 x 1.
    const int expected = static_cast<int>(std::floor(std::log2(std::max(width, height)))) + 1;
    if (static_cast<int>(levels.size()) != expected)
      fail(file, "a " + std::to_string(width) + " x " + std::to_string(height) + " mip chain needs " +
                     std::to_string(expected) + " levels, got " + std::to_string(levels.size()));
    for (std::size_t l = 1; l < levels.size(); ++l) {
      const int w = std::max(1, width >> l), h = std::max(1, height >> l);
      if (levels[l].width() != w || levels[l].height() != h)
        fail(file, "mip level " + std::to_string(l) + " is " + std::to_string(levels[l].width()) + " x " +
                       std::to_string(levels[l].height()) + ", expected " + std::to_string(w) + " x " +
                       std::to_string(h) + " (ROUND_DOWN)");
    }
  }
  if (options.envmap == EnvmapLayout::Cube && height != 6 * width)
    fail(file, "a cube envmap is six square faces stacked vertically (W x 6W), got " + std::to_string(width) +
                   " x " + std::to_string(height));
  for (std::size_t l = 0; l < levels.size(); ++l) {
    const std::vector<glm::vec4>& pixels = levels[l].pixels();
    for (std::size_t i = 0; i < pixels.size(); ++i) {
      if (!glm::any(glm::isnan(pixels[i])) && !glm::any(glm::isinf(pixels[i]))) continue;
      const int x = static_cast<int>(i % static_cast<std::size_t>(levels[l].width()));
      const int y = static_cast<int>(i / static_cast<std::size_t>(levels[l].width()));
      fail(file, "cannot write NaN or Inf (level " + std::to_string(l) + ", pixel " + std::to_string(x) +
                     ", " + std::to_string(y) + ")");
    }
  }
}

// A level's pixels as the file stores them: the Image's own floats, or a half copy. Values beyond
// the largest half (65504) would become Inf, so they are clamped there; `clamped` counts them.
class WritablePixels {
 public:
  WritablePixels(const Image& image, PixelType type, std::size_t& clamped) : image_(image) {
    if (type == PixelType::Float) return;
    halves_.reserve(image.pixelCount() * 4);
    for (const glm::vec4& pixel : image.pixels()) {
      for (int c = 0; c < 4; ++c) {
        if (std::abs(pixel[c]) > kHalfMax) ++clamped;
        halves_.emplace_back(std::clamp(pixel[c], -kHalfMax, kHalfMax));
      }
    }
  }

  Imf::FrameBuffer frameBuffer(const Imath::Box2i& window, int channelCount) const {
    Imf::FrameBuffer frameBuffer;
    for (int c = 0; c < channelCount; ++c) {
      frameBuffer.insert(
          kRgbaNames[c],
          halves_.empty() ? interleavedSlice(Imf::FLOAT, image_.pixels().data(), sizeof(float), 4, c, window)
                          : interleavedSlice(Imf::HALF, halves_.data(), sizeof(Imath::half), 4, c, window));
    }
    return frameBuffer;
  }

 private:
  const Image& image_;
  std::vector<Imath::half> halves_;
};

void writeLevels(const std::filesystem::path& file, std::span<const Image> levels,
                 const ExrWriteOptions& options) {
  checkLevelsForWriting(file, levels, options);
  const int channelCount = options.writeAlpha ? 4 : 3;
  const Imf::PixelType type = options.pixelType == PixelType::Half ? Imf::HALF : Imf::FLOAT;
  std::size_t clamped = 0;
  std::vector<WritablePixels> pixels;
  pixels.reserve(levels.size());
  for (const Image& level : levels) pixels.emplace_back(level, options.pixelType, clamped);
  if (clamped) warn(file, std::to_string(clamped) + " pixel values beyond the largest half (65504) clamped");

  writeAtomically(file, [&](const std::filesystem::path& temporary) {
    rethrowAsError(file, nullptr, [&] {
      Imf::Header header(levels[0].width(), levels[0].height());
      header.compression() = Imf::ZIP_COMPRESSION;
      for (int c = 0; c < channelCount; ++c) header.channels().insert(kRgbaNames[c], Imf::Channel(type));
      if (options.envmap != EnvmapLayout::None)
        Imf::addEnvmap(header, options.envmap == EnvmapLayout::Cube ? Imf::ENVMAP_CUBE : Imf::ENVMAP_LATLONG);
      for (const auto& [name, value] : options.stringAttributes)
        header.insert(name, Imf::StringAttribute(value));
      if (levels.size() == 1) {
        Imf::OutputFile out(temporary.c_str(), header);
        out.setFrameBuffer(pixels[0].frameBuffer(header.dataWindow(), channelCount));
        out.writePixels(levels[0].height());
        return;
      }
      header.setTileDescription(
          Imf::TileDescription(kTileSize, kTileSize, Imf::MIPMAP_LEVELS, Imf::ROUND_DOWN));
      Imf::TiledOutputFile out(temporary.c_str(), header);
      for (int l = 0; l < out.numLevels(); ++l) {
        out.setFrameBuffer(
            pixels[static_cast<std::size_t>(l)].frameBuffer(out.dataWindowForLevel(l), channelCount));
        out.writeTiles(0, out.numXTiles(l) - 1, 0, out.numYTiles(l) - 1, l);
      }
    });
  });
}

}  // namespace

Image readExr(const std::filesystem::path& file, ExrInfo* info, int level, PixelRepair repair) {
  Image image = withExrFile(file, [&](ExrLevelReader& reader) {
    if (info) *info = reader.info();
    return reader.read(level);
  });
  if (repair == PixelRepair::Repair) repairPixels(file, {&image, 1});
  return image;
}

std::vector<Image> readExrLevels(const std::filesystem::path& file, ExrInfo* info) {
  std::vector<Image> levels = withExrFile(file, [&](ExrLevelReader& reader) {
    if (info) *info = reader.info();
    std::vector<Image> images;
    for (int l = 0; l < reader.levels(); ++l) images.push_back(reader.read(l));
    return images;
  });
  repairPixels(file, levels);
  return levels;
}

void writeExr(const std::filesystem::path& file, const Image& image, const ExrWriteOptions& options) {
  writeLevels(file, {&image, 1}, options);
}

void writeExrLevels(const std::filesystem::path& file, const std::vector<Image>& levels,
                    const ExrWriteOptions& options) {
  writeLevels(file, levels, options);
}

void setExrThreads(int count) { Imf::setGlobalThreadCount(std::max(count, 0)); }

}  // namespace iblkit
