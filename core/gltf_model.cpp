#include "core/gltf_model.h"

#include <draco/compression/decode.h>
#include <draco/core/decoder_buffer.h>
#include <meshoptimizer.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstring>
#include <glm/gtc/type_ptr.hpp>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string_view>
#include <system_error>

#include "core/error.h"
#include "core/input_file.h"

namespace iblkit::gltf {

namespace fs = std::filesystem;

namespace {

constexpr const char* kDracoExtension = "KHR_draco_mesh_compression";
constexpr const char* kMeshoptExtension = "EXT_meshopt_compression";

// ---------------------------------------------------------------------------------------------
// Files and folders

// A model file or one of its buffers: regular files only, at most kMaxBinaryInputBytes.
std::vector<unsigned char> readModelBytes(const fs::path& path) {
  const std::vector<char> bytes = readInputFile(path, kMaxBinaryInputBytes);
  return std::vector<unsigned char>(bytes.begin(), bytes.end());
}

// True when `path` (resolved, symbolic links followed) lies inside the canonical `folder`.
bool isInsideFolder(const fs::path& folder, const fs::path& path) {
  std::error_code error;
  const fs::path resolved = fs::weakly_canonical(path, error);
  if (error) return false;
  const fs::path relative = resolved.lexically_relative(folder);
  return !relative.empty() && *relative.begin() != ".." && relative.is_relative();
}

// URIs are percent-encoded (RFC 3986 section 2.1); tinygltf decodes them before opening a file.
std::string percentDecode(const std::string& uri) {
  std::string decoded;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
      decoded += static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      decoded += uri[i];
    }
  }
  return decoded;
}

// tinygltf's file system, confined to the scene folder: only files inside it exist, ~ and $VAR
// are not expanded (tinygltf's default uses wordexp), and nothing is ever written.
struct SceneFolder {
  fs::path folder;  // canonical
};

bool folderFileExists(const std::string& path, void* user) {
  const auto* scene = static_cast<const SceneFolder*>(user);
  std::error_code error;
  return isInsideFolder(scene->folder, path) && fs::is_regular_file(path, error);
}

std::string keepFilePath(const std::string& path, void*) { return path; }

bool folderReadWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                         void* user) {
  const auto* scene = static_cast<const SceneFolder*>(user);
  if (!isInsideFolder(scene->folder, path)) {
    *err = "'" + path + "' is outside the scene folder";
    return false;
  }
  try {
    *out = readModelBytes(path);
  } catch (const Error& e) {
    *err = e.what();
    return false;
  }
  return true;
}

bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  *err = "writing is disabled while loading";
  return false;
}

// Geometry only: image bytes embedded as data URIs are kept as they are (gltf_write.cpp stores
// them again), images in buffer views are left in place, nothing is decoded.
bool keepImageBytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                    const unsigned char* bytes, int size, void*) {
  if (image->bufferView < 0) {
    image->image.assign(bytes, bytes + size);
    image->as_is = true;
  }
  return true;
}

// ---------------------------------------------------------------------------------------------
// The document handed to tinygltf

// A .glb around its JSON chunk (glTF 2.0 section 4.4), when the header is intact.
struct GlbLayout {
  std::string_view json;
  std::size_t jsonEnd = 0;  // where the chunks after the JSON chunk (BIN) start
};

std::optional<GlbLayout> glbLayout(const std::vector<unsigned char>& bytes) {
  if (bytes.size() < 20 || std::memcmp(bytes.data(), "glTF", 4) != 0) return std::nullopt;
  std::uint32_t length = 0, type = 0;
  std::memcpy(&length, bytes.data() + 12, 4);
  std::memcpy(&type, bytes.data() + 16, 4);
  if (type != 0x4E4F534Au || length > bytes.size() - 20) return std::nullopt;
  return GlbLayout{std::string_view(reinterpret_cast<const char*>(bytes.data()) + 20, length), 20 + length};
}

// The chunk after the JSON chunk (BIN), if any, must fit in the file with its 8-byte header.
// tinygltf 2.7.0 compares the chunk's length with the header's total length but leaves out that
// chunk header, so a BIN chunk claiming up to 8 bytes more than the file holds was read past the
// end of the bytes (a heap overflow, found by fuzz_gltf).
void checkBinChunk(const std::vector<unsigned char>& bytes, const GlbLayout& layout, const fs::path& file) {
  const std::size_t rest = bytes.size() - layout.jsonEnd;
  if (rest == 0) return;
  if (rest < 8) fail(file, "truncated chunk after the JSON chunk (" + std::to_string(rest) + " bytes)");
  std::uint32_t length = 0;
  std::memcpy(&length, bytes.data() + layout.jsonEnd, 4);
  if (length > rest - 8)
    fail(file, "BIN chunk of " + std::to_string(length) + " bytes runs past the end of the file (" +
                   std::to_string(rest - 8) + " bytes left; truncated file?)");
}

void appendU32(std::vector<unsigned char>& out, std::uint32_t value) {
  unsigned char bytes[4];
  std::memcpy(bytes, &value, 4);
  out.insert(out.end(), bytes, bytes + 4);
}

// The same .glb with another JSON chunk (space-padded); the chunks after it are kept as they are.
std::vector<unsigned char> replaceGlbJson(const std::vector<unsigned char>& glb, const GlbLayout& layout,
                                          std::string json) {
  json.resize((json.size() + 3) / 4 * 4, ' ');
  const std::size_t rest = glb.size() - layout.jsonEnd;
  std::vector<unsigned char> out(glb.begin(), glb.begin() + 8);  // magic and version
  appendU32(out, std::uint32_t(20 + json.size() + rest));
  appendU32(out, std::uint32_t(json.size()));
  appendU32(out, 0x4E4F534Au);
  out.insert(out.end(), json.begin(), json.end());
  out.insert(out.end(), glb.begin() + std::ptrdiff_t(layout.jsonEnd), glb.end());
  return out;
}

// Rejects external buffer URIs that leave the scene folder, before tinygltf opens anything.
void checkBufferUris(const nlohmann::json& document, const fs::path& folder, const fs::path& file) {
  if (!document.contains("buffers") || !document["buffers"].is_array()) return;
  const nlohmann::json& buffers = document["buffers"];
  for (std::size_t i = 0; i < buffers.size(); ++i) {
    if (!buffers[i].is_object() || !buffers[i].contains("uri") || !buffers[i]["uri"].is_string()) continue;
    const std::string uri = buffers[i]["uri"].get<std::string>();
    if (uri.rfind("data:", 0) == 0) continue;
    if (!isInsideFolder(folder, folder / percentDecode(uri)))
      fail(file, "buffer " + std::to_string(i) + " uri '" + uri + "' points outside the scene folder");
  }
}

// The indices accessor of a KHR_draco_mesh_compression primitive has no buffer view (the Draco
// stream holds the data), which tinygltf 2.7.0 rejects unless its own Draco decoder ran first. So
// these "indices" are taken out of the document tinygltf parses and put back afterwards.
struct DracoIndices {
  std::size_t mesh, primitive;
  int accessor;
};

std::vector<DracoIndices> takeDracoIndices(nlohmann::json& document) {
  std::vector<DracoIndices> taken;
  if (!document.contains("meshes") || !document["meshes"].is_array()) return taken;
  nlohmann::json& meshes = document["meshes"];
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    if (!meshes[m].is_object() || !meshes[m].contains("primitives") || !meshes[m]["primitives"].is_array())
      continue;
    nlohmann::json& primitives = meshes[m]["primitives"];
    for (std::size_t p = 0; p < primitives.size(); ++p) {
      nlohmann::json& primitive = primitives[p];
      if (!primitive.is_object() || !primitive.contains("indices") ||
          !primitive["indices"].is_number_integer() || !primitive.contains("extensions") ||
          !primitive["extensions"].is_object() || !primitive["extensions"].contains(kDracoExtension))
        continue;
      const std::int64_t accessor = primitive["indices"].get<std::int64_t>();
      if (accessor < 0 || accessor > std::numeric_limits<int>::max()) continue;
      taken.push_back(DracoIndices{m, p, int(accessor)});
      primitive.erase("indices");
    }
  }
  return taken;
}

// EXT_meshopt_compression's fallback buffers (extension `fallback: true`) may have no data: a
// reader that decodes the compressed views never reads them. tinygltf would copy a .glb's BIN
// chunk into any buffer without a uri (and fail where the fallback is the larger), or look for a
// file: each gets a 3-byte data URI instead. Returns whether the document changed. A view left
// pointing into one reads past its 3 bytes: an error (bufferViewBytes).
bool placeholdMeshoptFallbacks(nlohmann::json& document) {
  if (!document.contains("buffers") || !document["buffers"].is_array()) return false;
  bool changed = false;
  for (nlohmann::json& buffer : document["buffers"]) {
    if (!buffer.is_object() || buffer.contains("uri") || !buffer.contains("extensions") ||
        !buffer["extensions"].is_object() || !buffer["extensions"].contains(kMeshoptExtension))
      continue;
    const nlohmann::json& extension = buffer["extensions"][kMeshoptExtension];
    if (!extension.is_object() || !extension.contains("fallback") || extension["fallback"] != true) continue;
    buffer["uri"] = "data:application/octet-stream;base64,AAAA";
    buffer["byteLength"] = 3;
    changed = true;
  }
  return changed;
}

void restoreDracoIndices(tinygltf::Model& model, const std::vector<DracoIndices>& taken) {
  for (const DracoIndices& t : taken)
    if (t.mesh < model.meshes.size() && t.primitive < model.meshes[t.mesh].primitives.size())
      model.meshes[t.mesh].primitives[t.primitive].indices = t.accessor;
}

// The non-empty lines of tinygltf's messages, trailing spaces removed.
std::vector<std::string> messageLines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    if (!line.empty()) lines.push_back(std::move(line));
    start = end + 1;
  }
  return lines;
}

// Extensions a file may require: those iblkit decodes (gltf_load.h), and the material extensions
// whose data it ignores. Texture extensions other than KHR_texture_transform and EXT_texture_webp
// (KHR_texture_basisu's KTX2, EXT_texture_avif, ...) would leave textures unread, so requiring
// them is an error; merely using them is handled per texture (gltf_load.cpp).
void checkRequiredExtensions(const tinygltf::Model& model, const fs::path& file) {
  for (const std::string& name : model.extensionsRequired) {
    const bool known = name == kDracoExtension || name == kMeshoptExtension || name == "KHR_mesh_quantization" ||
                       name == "EXT_mesh_gpu_instancing" ||
                       name.rfind("KHR_materials_", 0) == 0 || name == "KHR_texture_transform" ||
                       name == "EXT_texture_webp";
    if (!known)
      fail(file, "requires unsupported extension " + name +
                     (name == "KHR_texture_basisu" ? " (KTX2 textures; PNG, JPEG and WebP are read)" : ""));
  }
}

// ---------------------------------------------------------------------------------------------
// Accessors

std::string accessorName(int accessor, const std::string& semantic) {
  return "accessor " + std::to_string(accessor) + " (" + semantic + ")";
}

int componentSize(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:
      return 0;
  }
}

// The bytes of an accessor after checking every index and range: element i starts at
// data + i * stride. A sparse accessor's elements are gathered into `dense` (data points there).
struct AccessorBytes {
  const unsigned char* data = nullptr;
  std::size_t stride = 0;
  std::size_t count = 0;
  std::vector<unsigned char> dense;
};

// The most bytes a sparse accessor may expand to (its base is zeros when it has no buffer view, so
// its count is not bounded by any buffer): 256 MiB, 22 million VEC3 floats.
constexpr std::size_t kMaxSparseAccessorBytes = std::size_t(256) << 20;

// `count` elements of `elementSize` bytes at byteOffset of buffer view `index`, tightly packed
// (sparse indices and values, glTF 2.0 section 3.6.2.3), checked to fit.
std::span<const unsigned char> packedRange(const tinygltf::Model& model, int index, std::size_t byteOffset,
                                           std::size_t count, std::size_t elementSize, const std::string& what,
                                           const fs::path& file) {
  if (index < 0 || std::size_t(index) >= model.bufferViews.size())
    fail(file, what + ": buffer view " + std::to_string(index) + " does not exist");
  const std::span<const unsigned char> view = bufferViewBytes(model, index, file);
  if (byteOffset > view.size() || count > view.size() || count * elementSize > view.size() - byteOffset)
    fail(file, what + " reads past the end of buffer view " + std::to_string(index));
  return view.subspan(byteOffset, count * elementSize);
}

AccessorBytes locate(const tinygltf::Model& model, int index, int components, const std::string& semantic,
                     const fs::path& file) {
  const std::string name = accessorName(index, semantic);
  if (index < 0 || std::size_t(index) >= model.accessors.size()) fail(file, name + " does not exist");
  const tinygltf::Accessor& accessor = model.accessors[index];
  // MAT4 (inverse bind matrices) is 16 components, column-major; float MAT4 has no padding.
  const int declared = accessor.type == TINYGLTF_TYPE_MAT4 ? 16 : componentCount(accessor.type);
  if (declared != components)
    fail(file, name + " has " + std::to_string(declared) + " components per element, expected " +
                   std::to_string(components));
  const int size = componentSize(accessor.componentType);
  if (size == 0)
    fail(file, name + " has unsupported component type " + std::to_string(accessor.componentType));
  const std::size_t elementSize = std::size_t(size) * std::size_t(components);
  const std::size_t count = accessor.count;
  AccessorBytes bytes;
  if (accessor.bufferView < 0) {
    if (!accessor.sparse.isSparse) fail(file, name + " has no buffer view");
  } else {
    const std::span<const unsigned char> view = bufferViewBytes(model, accessor.bufferView, file);
    const std::string viewName = "buffer view " + std::to_string(accessor.bufferView);
    const std::size_t byteStride = model.bufferViews[accessor.bufferView].byteStride;
    const std::size_t stride = byteStride ? byteStride : elementSize;
    if (stride < elementSize)
      fail(file, viewName + " has byteStride " + std::to_string(stride) + ", less than the " +
                     std::to_string(elementSize) + "-byte elements of " + name);
    // Each element needs at least one byte, so count > view.size() is already out of range and the
    // product below cannot overflow.
    const bool fits = count == 0 || (accessor.byteOffset <= view.size() && count <= view.size() &&
                                     (count - 1) * stride + elementSize <= view.size() - accessor.byteOffset);
    if (!fits) fail(file, name + " reads past the end of " + viewName);
    bytes = AccessorBytes{view.data() + accessor.byteOffset, stride, count, {}};
  }
  if (!accessor.sparse.isSparse) return bytes;

  // Sparse (glTF 2.0 section 3.6.2.3): the base (zeros without a buffer view) with sparse.count
  // elements replaced, at strictly increasing indices below count.
  if (count > kMaxSparseAccessorBytes / elementSize)
    fail(file, name + " is sparse with " + std::to_string(count) + " elements, beyond the limit of " +
                   std::to_string(kMaxSparseAccessorBytes >> 20) + " MiB");
  std::vector<unsigned char> dense(count * elementSize, 0);
  for (std::size_t i = 0; i < bytes.count; ++i)
    std::memcpy(dense.data() + i * elementSize, bytes.data + i * bytes.stride, elementSize);
  const auto& sparse = accessor.sparse;
  if (sparse.count < 1 || std::size_t(sparse.count) > count)
    fail(file, name + ": sparse count " + std::to_string(sparse.count) + " is not in 1.." + std::to_string(count));
  const int indexType = sparse.indices.componentType;
  const std::size_t indexSize = indexType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? 1
                                : indexType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                                : indexType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT   ? 4
                                                                                      : 0;
  if (indexSize == 0) fail(file, name + ": sparse indices must be unsigned byte, short or int");
  if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0)
    fail(file, name + ": sparse byteOffset must be >= 0");
  const std::size_t replaced = std::size_t(sparse.count);
  const std::span<const unsigned char> indices =
      packedRange(model, sparse.indices.bufferView, std::size_t(sparse.indices.byteOffset), replaced, indexSize,
                  name + " sparse indices", file);
  const std::span<const unsigned char> values =
      packedRange(model, sparse.values.bufferView, std::size_t(sparse.values.byteOffset), replaced, elementSize,
                  name + " sparse values", file);
  std::size_t previous = 0;
  for (std::size_t i = 0; i < replaced; ++i) {
    std::uint32_t target = 0;
    std::memcpy(&target, indices.data() + i * indexSize, indexSize);  // little-endian, as glTF
    if (target >= count)
      fail(file, name + ": sparse index " + std::to_string(target) + " out of range (" + std::to_string(count) +
                     " elements)");
    if (i > 0 && target <= previous) fail(file, name + ": sparse indices do not strictly increase");
    previous = target;
    std::memcpy(dense.data() + std::size_t(target) * elementSize, values.data() + i * elementSize, elementSize);
  }
  bytes.dense = std::move(dense);
  bytes.data = bytes.dense.data();
  bytes.stride = elementSize;
  bytes.count = count;
  return bytes;
}

template <typename T>
T loadComponent(const unsigned char* bytes) {
  T value;
  std::memcpy(&value, bytes, sizeof(T));
  return value;
}

// One component as float: normalised integers per glTF 2.0 section 3.11 (signed values clamp at
// -1), other integers as their value.
float componentAsFloat(const unsigned char* bytes, int componentType, bool normalized) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const float c = loadComponent<std::int8_t>(bytes);
      return normalized ? std::max(c / 127.0f, -1.0f) : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
      const float c = loadComponent<std::uint8_t>(bytes);
      return normalized ? c / 255.0f : c;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      const float c = loadComponent<std::int16_t>(bytes);
      return normalized ? std::max(c / 32767.0f, -1.0f) : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      const float c = loadComponent<std::uint16_t>(bytes);
      return normalized ? c / 65535.0f : c;
    }
    default:
      return loadComponent<float>(bytes);
  }
}

// ---------------------------------------------------------------------------------------------
// KHR_draco_mesh_compression

// Decoded data go into one new buffer per primitive, each attribute in its own 4-byte aligned
// buffer view.
class DecodedBuffer {
 public:
  explicit DecodedBuffer(tinygltf::Model& model) : model_(model), index_(int(model.buffers.size())) {}

  int addView(const std::vector<unsigned char>& bytes, int target) {
    data_.resize((data_.size() + 3) / 4 * 4, 0);
    tinygltf::BufferView view;
    view.buffer = index_;
    view.byteOffset = data_.size();
    view.byteLength = bytes.size();
    view.target = target;
    data_.insert(data_.end(), bytes.begin(), bytes.end());
    model_.bufferViews.push_back(view);
    return int(model_.bufferViews.size()) - 1;
  }

  void commit() {
    tinygltf::Buffer buffer;
    buffer.data = std::move(data_);
    model_.buffers.push_back(std::move(buffer));
  }

 private:
  tinygltf::Model& model_;
  int index_;
  std::vector<unsigned char> data_;
};

template <typename T>
bool convertDracoValues(const draco::PointAttribute& attribute, std::uint32_t points, int components,
                        std::vector<unsigned char>* out) {
  out->resize(std::size_t(points) * std::size_t(components) * sizeof(T));
  std::array<T, 4> value{};
  for (std::uint32_t i = 0; i < points; ++i) {
    if (!attribute.ConvertValue<T>(attribute.mapped_index(draco::PointIndex(i)), std::int8_t(components),
                                   value.data()))
      return false;
    std::memcpy(out->data() + std::size_t(i) * components * sizeof(T), value.data(), components * sizeof(T));
  }
  return true;
}

bool convertDracoAttribute(const draco::PointAttribute& attribute, std::uint32_t points, int components,
                           int componentType, std::vector<unsigned char>* out) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return convertDracoValues<std::int8_t>(attribute, points, components, out);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return convertDracoValues<std::uint8_t>(attribute, points, components, out);
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return convertDracoValues<std::int16_t>(attribute, points, components, out);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return convertDracoValues<std::uint16_t>(attribute, points, components, out);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return convertDracoValues<std::uint32_t>(attribute, points, components, out);
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return convertDracoValues<float>(attribute, points, components, out);
    default:
      return false;
  }
}

void decodeDracoPrimitive(tinygltf::Model& model, tinygltf::Primitive& primitive,
                          const tinygltf::Value& extension, const std::string& where, const fs::path& file) {
  const tinygltf::Value& viewValue = extension.Get("bufferView");
  const tinygltf::Value& attributesValue = extension.Get("attributes");
  if (!viewValue.IsInt() || !attributesValue.IsObject())
    fail(file, where + ": " + kDracoExtension + " needs an integer bufferView and an attributes object");
  const std::span<const unsigned char> stream = bufferViewBytes(model, viewValue.GetNumberAsInt(), file);

  draco::DecoderBuffer input;
  input.Init(reinterpret_cast<const char*>(stream.data()), stream.size());
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&input);
  if (!decoded.ok())
    fail(file, where + ": Draco stream does not decode (" + decoded.status().error_msg_string() + ")");
  const draco::Mesh& mesh = *decoded.value();
  const std::uint32_t points = mesh.num_points();

  DecodedBuffer output(model);
  if (primitive.indices >= 0) {
    if (std::size_t(primitive.indices) >= model.accessors.size())
      fail(file, where + ": indices refer to missing accessor " + std::to_string(primitive.indices));
    tinygltf::Accessor& accessor = model.accessors[primitive.indices];
    // Keep the declared index type when every vertex fits (unsigned short for most files).
    const int declared = accessor.componentType;
    const int type = (declared == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && points <= 0x100u) ||
                             (declared == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT && points <= 0x10000u)
                         ? declared
                         : TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    const std::size_t size = std::size_t(componentSize(type));
    std::vector<unsigned char> indexBytes(std::size_t(mesh.num_faces()) * 3 * size);
    for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f)
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t index = mesh.face(f)[k].value();
        if (index >= points) fail(file, where + ": Draco stream has a face index out of range");
        // Little-endian, as glTF and every platform iblkit builds on: the low bytes come first.
        std::memcpy(indexBytes.data() + (std::size_t(f.value()) * 3 + k) * size, &index, size);
      }
    accessor.bufferView = output.addView(indexBytes, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    accessor.byteOffset = 0;
    accessor.count = std::size_t(mesh.num_faces()) * 3;
    accessor.componentType = type;
    accessor.type = TINYGLTF_TYPE_SCALAR;
    accessor.sparse.isSparse = false;
  }

  for (const std::string& semantic : attributesValue.Keys()) {
    const tinygltf::Value& idValue = attributesValue.Get(semantic);
    const auto gltfAttribute = primitive.attributes.find(semantic);
    if (!idValue.IsInt() || gltfAttribute == primitive.attributes.end())
      fail(file, where + ": Draco attribute " + semantic + " is not an attribute of the primitive");
    const int accessorIndex = gltfAttribute->second;
    if (accessorIndex < 0 || std::size_t(accessorIndex) >= model.accessors.size())
      fail(file, where + ": " + semantic + " refers to missing accessor " + std::to_string(accessorIndex));
    const draco::PointAttribute* attribute =
        mesh.GetAttributeByUniqueId(std::uint32_t(idValue.GetNumberAsInt()));
    if (!attribute)
      fail(file, where + ": Draco stream has no attribute " + std::to_string(idValue.GetNumberAsInt()) +
                     " (" + semantic + ")");
    tinygltf::Accessor& accessor = model.accessors[accessorIndex];
    const int components = componentCount(accessor.type);
    std::vector<unsigned char> values;
    if (components != attribute->num_components() ||
        !convertDracoAttribute(*attribute, points, components, accessor.componentType, &values))
      fail(file, where + ": Draco attribute " + semantic + " does not match " +
                     accessorName(accessorIndex, semantic));
    accessor.bufferView = output.addView(values, TINYGLTF_TARGET_ARRAY_BUFFER);
    accessor.byteOffset = 0;
    accessor.count = points;
    accessor.sparse.isSparse = false;
  }
  output.commit();
  primitive.extensions.erase(kDracoExtension);
}

// ---------------------------------------------------------------------------------------------
// EXT_meshopt_compression (meshoptimizer's codecs, the Debian package; the extension's README)

// The most bytes one compressed view may decode to.
constexpr std::size_t kMaxMeshoptViewBytes = std::size_t(256) << 20;

std::size_t meshoptSize(const tinygltf::Value& extension, const char* key, bool required, const std::string& what,
                        const fs::path& file) {
  const tinygltf::Value& value = extension.Get(key);
  if (!value.IsNumber()) {
    if (required) fail(file, what + " needs an integer " + key);
    return 0;
  }
  const double number = value.GetNumberAsDouble();
  if (!(number >= 0.0 && number <= 9.0e15) || number != double(std::size_t(number)))
    fail(file, what + "." + key + " must be an integer >= 0");
  return std::size_t(number);
}

// Each buffer view with the extension is decoded from its compressed range (mode ATTRIBUTES,
// TRIANGLES or INDICES; filter NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL) into a new buffer, and
// the view points there; the extension is then gone from the model, as if the file had been
// written uncompressed.
void decodeMeshopt(tinygltf::Model& model, const fs::path& file) {
  for (std::size_t v = 0; v < model.bufferViews.size(); ++v) {
    tinygltf::BufferView& view = model.bufferViews[v];
    const auto found = view.extensions.find(kMeshoptExtension);
    if (found == view.extensions.end()) continue;
    const tinygltf::Value extension = found->second;
    const std::string what = "buffer view " + std::to_string(v) + " " + kMeshoptExtension;
    if (!extension.IsObject()) fail(file, what + " must be an object");
    const std::size_t buffer = meshoptSize(extension, "buffer", true, what, file);
    const std::size_t offset = meshoptSize(extension, "byteOffset", false, what, file);
    const std::size_t length = meshoptSize(extension, "byteLength", true, what, file);
    const std::size_t stride = meshoptSize(extension, "byteStride", true, what, file);
    const std::size_t count = meshoptSize(extension, "count", true, what, file);
    const tinygltf::Value& modeValue = extension.Get("mode");
    const tinygltf::Value& filterValue = extension.Get("filter");
    const std::string mode = modeValue.IsString() ? modeValue.Get<std::string>() : "";
    const std::string filter = filterValue.IsString() ? filterValue.Get<std::string>() : "NONE";
    if (buffer >= model.buffers.size()) fail(file, what + ": buffer " + std::to_string(buffer) + " does not exist");
    const std::vector<unsigned char>& data = model.buffers[buffer].data;
    if (offset > data.size() || length > data.size() - offset)
      fail(file, what + " reads past the end of buffer " + std::to_string(buffer));
    if (stride == 0 || stride > 256) fail(file, what + ".byteStride must be in 1..256");
    if (count > kMaxMeshoptViewBytes / stride)
      fail(file, what + " decodes to " + std::to_string(count) + " x " + std::to_string(stride) +
                     " bytes, beyond the limit of " + std::to_string(kMaxMeshoptViewBytes >> 20) + " MiB");
    if (count * stride < view.byteLength)
      fail(file, what + " decodes to " + std::to_string(count * stride) + " bytes, less than the view's " +
                     std::to_string(view.byteLength));
    std::vector<unsigned char> decoded(count * stride);
    const unsigned char* source = data.data() + offset;
    int status = 0;
    if (mode == "ATTRIBUTES") {
      if (stride % 4 != 0) fail(file, what + ": ATTRIBUTES needs a byteStride that is a multiple of 4");
      status = meshopt_decodeVertexBuffer(decoded.data(), count, stride, source, length);
    } else if (mode == "TRIANGLES" || mode == "INDICES") {
      if (stride != 2 && stride != 4) fail(file, what + ": " + mode + " needs a byteStride of 2 or 4");
      if (mode == "TRIANGLES" && count % 3 != 0) fail(file, what + ": TRIANGLES needs a count divisible by 3");
      status = mode == "TRIANGLES" ? meshopt_decodeIndexBuffer(decoded.data(), count, stride, source, length)
                                   : meshopt_decodeIndexSequence(decoded.data(), count, stride, source, length);
    } else {
      fail(file, what + ": unknown mode '" + printableExcerpt(mode) + "' (expected ATTRIBUTES, TRIANGLES or INDICES)");
    }
    if (status != 0) fail(file, what + ": compressed data does not decode (meshoptimizer error " + std::to_string(status) + ")");
    if (filter != "NONE") {
      if (mode != "ATTRIBUTES") fail(file, what + ": filter " + printableExcerpt(filter) + " needs mode ATTRIBUTES");
      if (filter == "OCTAHEDRAL" && (stride == 4 || stride == 8))
        meshopt_decodeFilterOct(decoded.data(), count, stride);
      else if (filter == "QUATERNION" && stride == 8)
        meshopt_decodeFilterQuat(decoded.data(), count, stride);
      else if (filter == "EXPONENTIAL" && stride % 4 == 0)
        meshopt_decodeFilterExp(decoded.data(), count, stride);
      else
        fail(file, what + ": filter '" + printableExcerpt(filter) + "' with byteStride " + std::to_string(stride) +
                       " (OCTAHEDRAL 4 or 8, QUATERNION 8, EXPONENTIAL a multiple of 4)");
    }
    decoded.resize(view.byteLength ? view.byteLength : decoded.size());
    tinygltf::Buffer out;
    out.data = std::move(decoded);
    model.buffers.push_back(std::move(out));
    view.buffer = int(model.buffers.size()) - 1;
    view.byteOffset = 0;
    view.byteLength = model.buffers.back().data.size();
    view.extensions.erase(kMeshoptExtension);
  }
  std::erase(model.extensionsUsed, kMeshoptExtension);
  std::erase(model.extensionsRequired, kMeshoptExtension);
}

void decodeDraco(tinygltf::Model& model, const fs::path& file) {
  for (std::size_t m = 0; m < model.meshes.size(); ++m)
    for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
      tinygltf::Primitive& primitive = model.meshes[m].primitives[p];
      const auto found = primitive.extensions.find(kDracoExtension);
      if (found == primitive.extensions.end()) continue;
      const tinygltf::Value extension = found->second;
      decodeDracoPrimitive(model, primitive, extension,
                           "mesh " + std::to_string(m) + " primitive " + std::to_string(p), file);
    }
  std::erase(model.extensionsUsed, kDracoExtension);
  std::erase(model.extensionsRequired, kDracoExtension);
}

tinygltf::Model parse(const fs::path& file) {
  std::vector<unsigned char> bytes = readModelBytes(file);

  std::error_code error;
  SceneFolder scene{fs::weakly_canonical(fs::absolute(file), error).parent_path()};
  if (error) fail(file, "cannot resolve path: " + error.message());
  const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  const std::optional<GlbLayout> layout = glbLayout(bytes);
  if (layout) checkBinChunk(bytes, *layout, file);
  const std::string_view text =
      binary ? (layout ? layout->json : std::string_view())
             : std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  // tinygltf turns JSON into its Values recursively, one call per level (extras, extensions).
  requireJsonNesting(text, file);
  // A document that does not parse is left to tinygltf, which reports why.
  nlohmann::json document = nlohmann::json::parse(text.begin(), text.end(), nullptr, false);
  std::vector<DracoIndices> dracoIndices;
  if (document.is_object()) {
    checkBufferUris(document, scene.folder, file);
    dracoIndices = takeDracoIndices(document);
    const bool fallbacks = placeholdMeshoptFallbacks(document);
    if (!dracoIndices.empty() || fallbacks) {
      const std::string json = document.dump();
      bytes = binary ? replaceGlbJson(bytes, *layout, json)
                     : std::vector<unsigned char>(json.begin(), json.end());
    }
  }
  if (bytes.size() > std::numeric_limits<unsigned int>::max()) fail(file, "file is larger than 4 GiB");

  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks(
      tinygltf::FsCallbacks{&folderFileExists, &keepFilePath, &folderReadWholeFile, &refuseWrite, &scene});
  loader.SetImageLoader(&keepImageBytes, nullptr);
  tinygltf::Model model;
  std::string errors, warnings;
  const unsigned int size = static_cast<unsigned int>(bytes.size());
  const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &errors, &warnings, bytes.data(), size,
                                                       scene.folder.string())
                         : loader.LoadASCIIFromString(&model, &errors, &warnings,
                                                      reinterpret_cast<const char*>(bytes.data()), size,
                                                      scene.folder.string());
  if (!ok) {
    std::string message;
    for (const std::string& line : messageLines(errors)) message += (message.empty() ? "" : "; ") + line;
    fail(file, message.empty() ? "not a valid glTF file" : message);
  }
  for (const std::string& line : messageLines(errors + "\n" + warnings)) warn(file, line);
  restoreDracoIndices(model, dracoIndices);
  return model;
}

// RFC 4648 section 4 base64, as data URIs carry it (RFC 2397); padding optional, nothing else
// tolerated. nullopt for a character outside the alphabet.
std::optional<std::vector<std::uint8_t>> base64Decode(std::string_view text) {
  while (!text.empty() && text.back() == '=') text.remove_suffix(1);
  std::vector<std::uint8_t> out;
  out.reserve(text.size() / 4 * 3 + 3);
  std::uint32_t bits = 0;
  int count = 0;
  for (const char c : text) {
    int value;
    if (c >= 'A' && c <= 'Z') value = c - 'A';
    else if (c >= 'a' && c <= 'z') value = c - 'a' + 26;
    else if (c >= '0' && c <= '9') value = c - '0' + 52;
    else if (c == '+') value = 62;
    else if (c == '/') value = 63;
    else return std::nullopt;
    bits = bits << 6 | std::uint32_t(value);
    if (++count == 4) {
      out.push_back(std::uint8_t(bits >> 16));
      out.push_back(std::uint8_t(bits >> 8));
      out.push_back(std::uint8_t(bits));
      bits = 0;
      count = 0;
    }
  }
  if (count == 1) return std::nullopt;  // 6 bits cannot end a byte
  if (count == 2) out.push_back(std::uint8_t(bits >> 4));
  if (count == 3) {
    out.push_back(std::uint8_t(bits >> 10));
    out.push_back(std::uint8_t(bits >> 2));
  }
  return out;
}

// A data: URI (RFC 2397, "data:[<mediatype>][;base64],<data>") that tinygltf left alone.
std::vector<std::uint8_t> dataUriBytes(const std::string& uri, const fs::path& file, const std::string& what,
                                       std::string* mediaType) {
  const std::size_t comma = uri.find(',');
  if (comma == std::string::npos) fail(file, what + ": data URI has no ',' before its data");
  std::string header = uri.substr(5, comma - 5);
  const bool base64 = header.size() >= 7 && header.compare(header.size() - 7, 7, ";base64") == 0;
  if (base64) header.resize(header.size() - 7);
  *mediaType = header.substr(0, header.find(';'));
  std::vector<std::uint8_t> bytes;
  if (base64) {
    std::optional<std::vector<std::uint8_t>> decoded = base64Decode(std::string_view(uri).substr(comma + 1));
    if (!decoded) fail(file, what + ": data URI is not valid base64");
    bytes = std::move(*decoded);
  } else {
    const std::string text = percentDecode(uri.substr(comma + 1));
    bytes.assign(text.begin(), text.end());
  }
  if (bytes.empty()) fail(file, what + ": data URI holds no data");
  return bytes;
}

// True for a URI with a scheme (RFC 3986 section 3.1: a letter, then letters, digits, '+', '-' or
// '.', then ':'), which is not a relative file reference.
bool hasUriScheme(const std::string& uri) {
  if (uri.empty() || !std::isalpha(static_cast<unsigned char>(uri[0]))) return false;
  for (const char c : uri) {
    if (c == ':') return true;
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '+' && c != '-' && c != '.') return false;
  }
  return false;
}

}  // namespace

tinygltf::Model readModel(const fs::path& file) {
  try {
    tinygltf::Model model = parse(file);
    checkRequiredExtensions(model, file);
    decodeMeshopt(model, file);
    decodeDraco(model, file);
    return model;
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    fail(file, std::string("cannot load glTF: ") + e.what());
  }
}

std::vector<std::uint8_t> imageBytes(const tinygltf::Model& model, int index, const fs::path& file,
                                     const std::string& what, std::string* declaredMimeType, fs::path* source) {
  if (index < 0 || std::size_t(index) >= model.images.size()) fail(file, what + " does not exist");
  const tinygltf::Image& image = model.images[index];
  *source = file;
  if (image.bufferView >= 0) {
    *declaredMimeType = image.mimeType;
    const std::span<const unsigned char> view = bufferViewBytes(model, image.bufferView, file);
    if (view.empty()) fail(file, what + ": buffer view " + std::to_string(image.bufferView) + " is empty");
    return std::vector<std::uint8_t>(view.begin(), view.end());
  }
  if (image.as_is) {  // a data URI tinygltf decoded (keepImageBytes); it set the media type
    *declaredMimeType = image.mimeType;
    return std::vector<std::uint8_t>(image.image.begin(), image.image.end());
  }
  const std::string& uri = image.uri;
  if (uri.rfind("data:", 0) == 0) return dataUriBytes(uri, file, what, declaredMimeType);
  declaredMimeType->clear();
  if (uri.empty()) fail(file, what + " has neither a uri nor a buffer view");
  const fs::path relative = percentDecode(uri);
  std::error_code error;
  const fs::path folder = fs::weakly_canonical(fs::absolute(file), error).parent_path();
  if (error) fail(file, "cannot resolve path: " + error.message());
  if (hasUriScheme(uri) || relative.is_absolute() || !isInsideFolder(folder, folder / relative))
    fail(file, what + ": uri '" + printableExcerpt(uri, 80) + "' points outside the scene folder");
  *source = (file.parent_path() / relative).lexically_normal();
  try {
    const std::vector<char> bytes = readInputFile(*source, kMaxBinaryInputBytes);
    return std::vector<std::uint8_t>(bytes.begin(), bytes.end());
  } catch (const Error& e) {
    fail(file, what + ": " + e.what());
  }
}

int componentCount(int accessorType) {
  switch (accessorType) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC2:
      return 2;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    case TINYGLTF_TYPE_VEC4:
      return 4;
    default:
      return 0;
  }
}

std::span<const unsigned char> bufferViewBytes(const tinygltf::Model& model, int index,
                                               const fs::path& file) {
  const std::string name = "buffer view " + std::to_string(index);
  if (index < 0 || std::size_t(index) >= model.bufferViews.size()) fail(file, name + " does not exist");
  const tinygltf::BufferView& view = model.bufferViews[index];
  if (view.buffer < 0 || std::size_t(view.buffer) >= model.buffers.size())
    fail(file, name + " refers to missing buffer " + std::to_string(view.buffer));
  const std::vector<unsigned char>& buffer = model.buffers[view.buffer].data;
  if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset)
    fail(file, name + " reads past the end of buffer " + std::to_string(view.buffer));
  return std::span<const unsigned char>(buffer.data() + view.byteOffset, view.byteLength);
}

std::vector<float> readFloats(const tinygltf::Model& model, int accessor, int components,
                              const std::string& semantic, const fs::path& file) {
  const AccessorBytes bytes = locate(model, accessor, components, semantic, file);
  const tinygltf::Accessor& info = model.accessors[accessor];
  if (info.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    fail(file, accessorName(accessor, semantic) +
                   " has unsigned int components, which glTF allows only for indices");
  const int size = componentSize(info.componentType);
  std::vector<float> values(bytes.count * std::size_t(components));
  for (std::size_t i = 0; i < bytes.count; ++i)
    for (int c = 0; c < components; ++c)
      values[i * components + c] = componentAsFloat(bytes.data + i * bytes.stride + std::size_t(c) * size,
                                                    info.componentType, info.normalized);
  return values;
}

std::vector<glm::mat4> readMatrices(const tinygltf::Model& model, int accessor, const std::string& semantic,
                                    const fs::path& file) {
  if (accessor >= 0 && std::size_t(accessor) < model.accessors.size() &&
      model.accessors[accessor].componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
    fail(file, accessorName(accessor, semantic) + " must have float components");
  const std::vector<float> values = readFloats(model, accessor, 16, semantic, file);
  std::vector<glm::mat4> matrices(values.size() / 16);
  for (std::size_t i = 0; i < matrices.size(); ++i)
    std::memcpy(glm::value_ptr(matrices[i]), values.data() + 16 * i, 16 * sizeof(float));  // column-major, as glm
  return matrices;
}

std::vector<std::uint32_t> readIndices(const tinygltf::Model& model, int accessor, const fs::path& file) {
  const AccessorBytes bytes = locate(model, accessor, 1, "indices", file);
  const int componentType = model.accessors[accessor].componentType;
  if (componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
      componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    fail(file, accessorName(accessor, "indices") + " must have unsigned byte, short or int components");
  std::vector<std::uint32_t> indices(bytes.count);
  for (std::size_t i = 0; i < bytes.count; ++i) {
    const unsigned char* element = bytes.data + i * bytes.stride;
    switch (componentType) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        indices[i] = loadComponent<std::uint8_t>(element);
        break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        indices[i] = loadComponent<std::uint16_t>(element);
        break;
      default:
        indices[i] = loadComponent<std::uint32_t>(element);
    }
  }
  return indices;
}

}  // namespace iblkit::gltf
