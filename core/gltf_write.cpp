#include "core/gltf_write.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <span>
#include <system_error>

#include "core/error.h"
#include "core/file_io.h"
#include "core/gltf_model.h"

namespace iblkit {

namespace fs = std::filesystem;

namespace {

constexpr int kAccessorTypes[] = {TINYGLTF_TYPE_SCALAR, TINYGLTF_TYPE_VEC2, TINYGLTF_TYPE_VEC3,
                                  TINYGLTF_TYPE_VEC4};

// Appends `bytes` to `buffer` at an offset that is a multiple of 4 plus `residue`, so that the
// alignment of the accessors inside (glTF 2.0 section 3.6.2.4) is unchanged.
std::size_t appendAligned(std::vector<unsigned char>& buffer, const unsigned char* bytes, std::size_t size,
                          std::size_t residue = 0) {
  const std::size_t offset = (buffer.size() + 3) / 4 * 4 + residue % 4;
  buffer.resize(offset, 0);
  buffer.insert(buffer.end(), bytes, bytes + size);
  return offset;
}

// How many places refer to accessor `index` (primitives, morph targets, skins, animations).
int accessorUses(const tinygltf::Model& model, int index) {
  int uses = 0;
  for (const tinygltf::Mesh& mesh : model.meshes)
    for (const tinygltf::Primitive& primitive : mesh.primitives) {
      uses += primitive.indices == index;
      for (const auto& attribute : primitive.attributes) uses += attribute.second == index;
      for (const auto& target : primitive.targets)
        for (const auto& attribute : target) uses += attribute.second == index;
    }
  for (const tinygltf::Skin& skin : model.skins) uses += skin.inverseBindMatrices == index;
  for (const tinygltf::Animation& animation : model.animations)
    for (const tinygltf::AnimationSampler& sampler : animation.samplers)
      uses += (sampler.input == index) + (sampler.output == index);
  return uses;
}

void checkAttributes(const tinygltf::Model& model, const PrimitiveAttributes& a, const fs::path& output) {
  const std::string where =
      "mesh " + std::to_string(a.meshIndex) + " primitive " + std::to_string(a.primitiveIndex);
  if (a.name.size() < 2 || a.name[0] != '_')
    fail(output, "attribute name '" + a.name + "' must start with '_' (glTF custom attribute)");
  if (a.componentCount < 1 || a.componentCount > 4)
    fail(output,
         "attribute " + a.name + ": componentCount " + std::to_string(a.componentCount) + " is not in 1..4");
  if (a.meshIndex < 0 || std::size_t(a.meshIndex) >= model.meshes.size() || a.primitiveIndex < 0 ||
      std::size_t(a.primitiveIndex) >= model.meshes[a.meshIndex].primitives.size())
    fail(output, "attribute " + a.name + ": " + where + " does not exist");
  const tinygltf::Primitive& primitive = model.meshes[a.meshIndex].primitives[a.primitiveIndex];
  const auto position = primitive.attributes.find("POSITION");
  if (position == primitive.attributes.end() || position->second < 0 ||
      std::size_t(position->second) >= model.accessors.size())
    fail(output, "attribute " + a.name + ": " + where + " has no valid POSITION accessor");
  const std::size_t vertices = model.accessors[position->second].count;
  if (a.data.size() != vertices * std::size_t(a.componentCount))
    fail(output, "attribute " + a.name + " has " + std::to_string(a.data.size()) + " values; " + where +
                     " needs " + std::to_string(vertices * std::size_t(a.componentCount)) + " (" +
                     std::to_string(vertices) + " vertices x " + std::to_string(a.componentCount) +
                     " components)");
  for (std::size_t i = 0; i < a.data.size(); ++i)
    if (!std::isfinite(a.data[i]))
      fail(output, "attribute " + a.name + ": non-finite value at vertex " +
                       std::to_string(i / a.componentCount) + " of " + where);
}

// Adds each attribute as a float accessor in one new buffer.
void addAttributes(tinygltf::Model& model, const std::vector<PrimitiveAttributes>& attributes) {
  tinygltf::Buffer buffer;
  const int bufferIndex = int(model.buffers.size());
  for (const PrimitiveAttributes& a : attributes) {
    tinygltf::BufferView view;
    view.buffer = bufferIndex;
    view.byteLength = a.data.size() * sizeof(float);
    view.byteOffset =
        appendAligned(buffer.data, reinterpret_cast<const unsigned char*>(a.data.data()), view.byteLength);
    view.target = TINYGLTF_TARGET_ARRAY_BUFFER;
    model.bufferViews.push_back(view);

    tinygltf::Accessor accessor;
    accessor.name = a.name;
    accessor.bufferView = int(model.bufferViews.size()) - 1;
    accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    accessor.type = kAccessorTypes[a.componentCount - 1];
    accessor.count = a.data.size() / a.componentCount;

    tinygltf::Primitive& primitive = model.meshes[a.meshIndex].primitives[a.primitiveIndex];
    const auto existing = primitive.attributes.find(a.name);
    if (existing != primitive.attributes.end() && existing->second >= 0 &&
        std::size_t(existing->second) < model.accessors.size() &&
        accessorUses(model, existing->second) == 1) {
      model.accessors[existing->second] = accessor;
    } else {
      model.accessors.push_back(accessor);
      primitive.attributes[a.name] = int(model.accessors.size()) - 1;
    }
  }
  model.buffers.push_back(std::move(buffer));
}

// Merges all buffers into buffer 0, keeping only the buffer views that accessors and images use
// (the Draco streams are no longer used once decoded), and moves images embedded as data URIs into
// buffer views so one binary buffer holds everything.
void repackBuffers(tinygltf::Model& model, const fs::path& input) {
  std::vector<unsigned char> merged;
  std::vector<tinygltf::BufferView> views;
  std::vector<int> remap(model.bufferViews.size(), -1);
  const auto keep = [&](int& reference) {
    if (reference < 0) return;
    const std::span<const unsigned char> bytes = gltf::bufferViewBytes(model, reference, input);
    if (remap[reference] < 0) {
      tinygltf::BufferView view = model.bufferViews[reference];
      view.byteOffset = appendAligned(merged, bytes.data(), bytes.size(), view.byteOffset);
      view.buffer = 0;
      remap[reference] = int(views.size());
      views.push_back(view);
    }
    reference = remap[reference];
  };
  for (tinygltf::Accessor& accessor : model.accessors) {
    keep(accessor.bufferView);
    if (accessor.sparse.isSparse) {
      keep(accessor.sparse.indices.bufferView);
      keep(accessor.sparse.values.bufferView);
    }
  }
  for (tinygltf::Image& image : model.images) {
    if (image.bufferView >= 0) {
      keep(image.bufferView);
    } else if (image.uri.empty() && !image.image.empty()) {
      tinygltf::BufferView view;
      view.buffer = 0;
      view.byteLength = image.image.size();
      view.byteOffset = appendAligned(merged, image.image.data(), image.image.size());
      image.bufferView = int(views.size());
      views.push_back(view);
    }
  }
  model.bufferViews = std::move(views);
  model.buffers.clear();
  if (!merged.empty()) {
    tinygltf::Buffer buffer;
    buffer.data = std::move(merged);
    model.buffers.push_back(std::move(buffer));
  }
}

bool isBinaryOutput(const fs::path& output) {
  std::string extension = output.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".glb" && extension != ".gltf")
    fail(output, "unknown glTF extension '" + output.extension().string() + "' (expected .gltf or .glb)");
  return extension == ".glb";
}

}  // namespace

void writeGltfWithAttributes(const fs::path& input, const fs::path& output,
                             const std::vector<PrimitiveAttributes>& attributes) {
  const bool binary = isBinaryOutput(output);
  tinygltf::Model model = gltf::readModel(input);
  for (const PrimitiveAttributes& a : attributes) checkAttributes(model, a, output);
  try {
    addAttributes(model, attributes);
    repackBuffers(model, input);

    writeAtomically(output, [&](const fs::path& temporary) {
      std::ofstream stream(temporary, std::ios::binary);
      if (!stream) fail(output, "cannot create " + temporary.string());
      tinygltf::TinyGLTF writer;
      writer.WriteGltfSceneToStream(&model, stream, /*prettyPrint=*/!binary, /*writeBinary=*/binary);
      stream.close();
      if (!stream) fail(output, "cannot write " + temporary.string());
    });
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    fail(output, std::string("cannot write glTF: ") + e.what());
  }
}

}  // namespace iblkit
