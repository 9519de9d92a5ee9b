// EXT_meshopt_compression (core/gltf_model.cpp decodeMeshopt): files compressed here with
// meshoptimizer's own encoders, as gltfpack writes them (compressed views in buffer 0, the views
// themselves on a fallback buffer without data), load as their uncompressed twins.
#include <gtest/gtest.h>
#include <meshoptimizer.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/gltf_load.h"
#include "core/procedural_mesh.h"
#include "support/gltf_builder.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

using nlohmann::json;
using test::GltfBuilder;

struct Compressed {
  std::vector<unsigned char> bytes;
  std::size_t count = 0, stride = 0;
  std::string mode, filter = "NONE";
};

// A view on the fallback buffer (1) at `fallbackOffset`, its data `c` compressed in buffer 0.
int addCompressedView(GltfBuilder& builder, const Compressed& c, std::size_t& fallbackOffset, bool strided) {
  const int raw = builder.addBufferView(c.bytes.data(), c.bytes.size());
  json& views = builder.document()["bufferViews"];
  json view = {{"buffer", 1},
               {"byteOffset", fallbackOffset},
               {"byteLength", c.count * c.stride},
               {"extensions",
                {{"EXT_meshopt_compression",
                  {{"buffer", 0},
                   {"byteOffset", views[raw]["byteOffset"]},
                   {"byteLength", c.bytes.size()},
                   {"byteStride", c.stride},
                   {"count", c.count},
                   {"mode", c.mode},
                   {"filter", c.filter}}}}}};
  if (strided) view["byteStride"] = c.stride;
  fallbackOffset += (c.count * c.stride + 3) / 4 * 4;
  views.push_back(view);
  return int(views.size()) - 1;
}

class GltfMeshopt : public ::testing::Test {
 protected:
  std::filesystem::path dir = test::scratchDir();
  Mesh sphere = toMesh(uvSphere(glm::vec3(0.0f), 1.0f, 12, 24), "sphere", 0);

  // The sphere compressed: positions ATTRIBUTES (float VEC3), normals ATTRIBUTES with the
  // OCTAHEDRAL filter (normalised bytes, KHR_mesh_quantization), indices TRIANGLES.
  std::filesystem::path write(const std::function<void(json&)>& edit = {}) {
    GltfBuilder builder;
    Compressed positions{{}, sphere.vertexCount(), 12, "ATTRIBUTES"};
    positions.bytes.resize(meshopt_encodeVertexBufferBound(positions.count, 12));
    positions.bytes.resize(
        meshopt_encodeVertexBuffer(positions.bytes.data(), positions.bytes.size(), sphere.positions.data(), positions.count, 12));
    std::vector<float> normals4;
    for (const glm::vec3& n : sphere.normals) normals4.insert(normals4.end(), {n.x, n.y, n.z, 0.0f});
    std::vector<std::int8_t> octahedral(4 * sphere.vertexCount());
    meshopt_encodeFilterOct(octahedral.data(), sphere.vertexCount(), 4, 8, normals4.data());
    Compressed normals{{}, sphere.vertexCount(), 4, "ATTRIBUTES", "OCTAHEDRAL"};
    normals.bytes.resize(meshopt_encodeVertexBufferBound(normals.count, 4));
    normals.bytes.resize(
        meshopt_encodeVertexBuffer(normals.bytes.data(), normals.bytes.size(), octahedral.data(), normals.count, 4));
    Compressed indices{{}, sphere.indices.size(), 4, "TRIANGLES"};
    indices.bytes.resize(meshopt_encodeIndexBufferBound(indices.count, sphere.vertexCount()));
    indices.bytes.resize(
        meshopt_encodeIndexBuffer(indices.bytes.data(), indices.bytes.size(), sphere.indices.data(), indices.count));

    std::size_t fallback = 0;
    const int positionView = addCompressedView(builder, positions, fallback, true);
    const int normalView = addCompressedView(builder, normals, fallback, true);
    const int indexView = addCompressedView(builder, indices, fallback, false);
    json& accessors = builder.document()["accessors"];
    accessors.push_back({{"bufferView", positionView}, {"componentType", test::kFloat}, {"count", positions.count},
                         {"type", "VEC3"}, {"min", {-1, -1, -1}}, {"max", {1, 1, 1}}});
    // VEC3 normalised bytes in 4-byte elements (the view's byteStride), as gltfpack writes normals.
    accessors.push_back({{"bufferView", normalView}, {"componentType", 5120}, {"normalized", true},
                         {"count", normals.count}, {"type", "VEC3"}});
    accessors.push_back({{"bufferView", indexView}, {"componentType", test::kUnsignedInt}, {"count", indices.count},
                         {"type", "SCALAR"}});
    const int n = int(accessors.size());
    builder.addPrimitiveNode({{"attributes", {{"POSITION", n - 3}, {"NORMAL", n - 2}}}, {"indices", n - 1}});
    json& document = builder.document();
    document["buffers"] = {{{"byteLength", 0}},
                           {{"byteLength", fallback}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}}};
    document["extensionsUsed"] = {"EXT_meshopt_compression", "KHR_mesh_quantization"};
    document["extensionsRequired"] = {"EXT_meshopt_compression", "KHR_mesh_quantization"};
    if (edit) edit(document);
    const std::filesystem::path file = dir / "compressed.glb";
    builder.write(file, GltfBuilder::Storage::Glb);
    return file;
  }
};

TEST_F(GltfMeshopt, CompressedSphereLoadsAsItsUncompressedTwin) {
  const GltfContents contents = loadGltf(write());
  ASSERT_EQ(contents.meshes.size(), 1u);
  const Mesh& m = contents.meshes[0];
  EXPECT_EQ(m.positions, sphere.positions);  // lossless
  // The index codec may rotate a triangle's corners (never its winding): compare each triangle
  // turned to start at its smallest index.
  const auto canonical = [](std::vector<std::uint32_t> indices) {
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3)
      while (indices[t] > indices[t + 1] || indices[t] > indices[t + 2])
        std::rotate(indices.begin() + std::ptrdiff_t(t), indices.begin() + std::ptrdiff_t(t + 1),
                    indices.begin() + std::ptrdiff_t(t + 3));
    return indices;
  };
  EXPECT_EQ(canonical(m.indices), canonical(sphere.indices));
  ASSERT_EQ(m.normals.size(), sphere.normals.size());
  float worst = 0.0f;
  for (std::size_t i = 0; i < m.normals.size(); ++i) worst = std::max(worst, glm::distance(m.normals[i], sphere.normals[i]));
  EXPECT_LT(worst, 0.02f);  // 8-bit octahedral normals
  EXPECT_GT(worst, 0.0f);   // and they were really quantised: the filter ran
}

std::string errorOf(const std::filesystem::path& file) {
  try {
    loadGltf(file);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST_F(GltfMeshopt, BrokenCompressedViewsAreOneLineErrors) {
  const auto name = [&](const std::string& message) { return (dir / "compressed.glb").string() + ": " + message; };
  EXPECT_EQ(errorOf(write([](json& d) { d["bufferViews"][3]["extensions"]["EXT_meshopt_compression"]["mode"] = "MAGIC"; })),
            name("buffer view 3 EXT_meshopt_compression: unknown mode 'MAGIC' (expected ATTRIBUTES, TRIANGLES or INDICES)"));
  // The compressed range cut short: the decoder refuses it.
  EXPECT_EQ(errorOf(write([](json& d) {
              json& e = d["bufferViews"][3]["extensions"]["EXT_meshopt_compression"];
              e["byteLength"] = e["byteLength"].get<int>() / 2;
            })),
            name("buffer view 3 EXT_meshopt_compression: compressed data does not decode (meshoptimizer error -2)"));
  EXPECT_EQ(errorOf(write([](json& d) { d["bufferViews"][5]["extensions"]["EXT_meshopt_compression"]["filter"] = "OCTAHEDRAL"; })),
            name("buffer view 5 EXT_meshopt_compression: filter OCTAHEDRAL needs mode ATTRIBUTES"));
  EXPECT_EQ(errorOf(write([](json& d) { d["bufferViews"][1]["extensions"]["EXT_meshopt_compression"]["count"] = 1e12; })),
            name("buffer view 1 EXT_meshopt_compression decodes to 1000000000000 x 12 bytes, beyond the limit of 256 MiB"));
  // A view on the fallback buffer without the extension reads its 3-byte placeholder.
  const std::string placeholder = errorOf(write([](json& d) { d["bufferViews"][3].erase("extensions"); }));
  EXPECT_NE(placeholder.find("reads past the end of buffer 1"), std::string::npos) << placeholder;
}

}  // namespace
}  // namespace iblkit
