#include "core/gltf_load.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <numbers>

#include "core/brdf.h"
#include "core/error.h"
#include "support/gltf_builder.h"
#include "support/texture_files.h"
#include "support/test_paths.h"
#include "support/warning_capture.h"

namespace iblkit {
namespace {

using nlohmann::json;
using test::GltfBuilder;

const std::vector<glm::vec3> kTriangle = {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)};

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance = 1e-5f) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

// The test's scratch folder, emptied once per test (test::scratchDir empties it on every call), so
// that image files a test writes stay beside the model it loads.
std::filesystem::path testDir() {
  static std::string test;
  static std::filesystem::path dir;
  const testing::TestInfo* info = testing::UnitTest::GetInstance()->current_test_info();
  const std::string name = std::string(info->test_suite_name()) + "." + info->name();
  if (name != test) {
    dir = test::scratchDir();
    test = name;
  }
  return dir;
}

// Writes the builder's document to the test's scratch folder and loads it.
GltfContents load(const GltfBuilder& builder, GltfBuilder::Storage storage = GltfBuilder::Storage::BinFile) {
  const std::filesystem::path path =
      testDir() / (storage == GltfBuilder::Storage::Glb ? "model.glb" : "model.gltf");
  builder.write(path, storage);
  return loadGltf(path);
}

// The message loadGltf throws for the builder's document.
std::string loadError(const GltfBuilder& builder) {
  try {
    load(builder);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

// Warnings are captured (and checked where they matter) rather than printed.
class GltfLoad : public ::testing::Test {
protected:
  test::WarningCapture warnings;
};

TEST_F(GltfLoad, SameGeometryFromBinFileDataUriAndGlb) {
  GltfBuilder builder;
  builder.addPrimitiveNode({{"attributes", {{"POSITION", builder.addFloats(kTriangle)}}}});
  for (const auto storage :
       {GltfBuilder::Storage::BinFile, GltfBuilder::Storage::DataUri, GltfBuilder::Storage::Glb}) {
    const GltfContents contents = load(builder, storage);
    ASSERT_EQ(contents.meshes.size(), 1u);
    EXPECT_EQ(contents.meshes[0].positions, kTriangle);
    EXPECT_EQ(contents.meshes[0].indices, (std::vector<std::uint32_t>{0, 1, 2}));
    EXPECT_FALSE(contents.camera.has_value());
  }
}

TEST_F(GltfLoad, FlattensNodeTransforms) {
  GltfBuilder builder;
  const std::vector<glm::vec3> normals(3, glm::vec3(0, 0, 1));
  const int mesh = builder.addMesh(json::array(
      {{{"attributes",
         {{"POSITION", builder.addFloats(kTriangle)}, {"NORMAL", builder.addFloats(normals)}}}}}));
  // Child: translate (0, 2, 0), rotate 90 degrees about +Z, scale (2, 1, 1); parent: translate (10, 0, 0).
  const float s = std::sqrt(0.5f);
  const int child = builder.addNode(
      {{"mesh", mesh}, {"translation", {0, 2, 0}}, {"rotation", {0, 0, s, s}}, {"scale", {2, 1, 1}}}, false);
  builder.addNode({{"translation", {10, 0, 0}}, {"children", {child}}});
  const GltfContents contents = load(builder);
  ASSERT_EQ(contents.meshes.size(), 1u);
  const Mesh& m = contents.meshes[0];
  // (x, y, z) -> scale (2x, y, z) -> rotate (-y, 2x, z) -> translate (10 - y, 2 + 2x, z).
  expectNear(m.positions[0], glm::vec3(10, 2, 0));
  expectNear(m.positions[1], glm::vec3(10, 4, 0));
  expectNear(m.positions[2], glm::vec3(9, 2, 0));
  expectNear(m.normals[0], glm::vec3(0, 0, 1));
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_EQ(m.source.node, child);
  EXPECT_EQ(m.source.mesh, mesh);
}

TEST_F(GltfLoad, MatrixTransformAndNegativeScaleFlipWinding) {
  GltfBuilder builder;
  const int mesh =
      builder.addMesh(json::array({{{"attributes", {{"POSITION", builder.addFloats(kTriangle)}}}}}));
  // Column-major matrix mirroring x and translating by (0, 0, 5).
  builder.addNode({{"mesh", mesh}, {"matrix", {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 5, 1}}});
  const GltfContents contents = load(builder);
  const Mesh& m = contents.meshes[0];
  expectNear(m.positions[1], glm::vec3(-1, 0, 5));
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 2, 1}));
  // Generated normals face the same way as the (flipped) front face: +Z.
  expectNear(m.normals[0], glm::vec3(0, 0, 1));
}

TEST_F(GltfLoad, InstancedMeshYieldsOneMeshPerNode) {
  GltfBuilder builder;
  const int mesh =
      builder.addMesh(json::array({{{"attributes", {{"POSITION", builder.addFloats(kTriangle)}}}}}));
  builder.addNode({{"mesh", mesh}});
  builder.addNode({{"mesh", mesh}, {"translation", {0, 0, 3}}});
  const GltfContents contents = load(builder);
  ASSERT_EQ(contents.meshes.size(), 2u);
  EXPECT_EQ(contents.meshes[0].source.node, 0);
  EXPECT_EQ(contents.meshes[1].source.node, 1);
  EXPECT_EQ(contents.meshes[1].source.mesh, mesh);
  EXPECT_EQ(contents.meshes[1].positions[0], glm::vec3(0, 0, 3));
}

TEST_F(GltfLoad, StripsAndFansBecomeTriangleLists) {
  // Five vertices on a zig-zag (strip) or around a centre (fan), all counter-clockwise.
  const std::vector<glm::vec3> strip = {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0),
                                        glm::vec3(1, 1, 0), glm::vec3(0, 2, 0)};
  const std::vector<glm::vec3> fan = {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(1, 1, 0),
                                      glm::vec3(0, 1, 0), glm::vec3(-1, 1, 0)};
  GltfBuilder builder;
  builder.addPrimitiveNode({{"attributes", {{"POSITION", builder.addFloats(strip)}}}, {"mode", 5}});
  builder.addPrimitiveNode({{"attributes", {{"POSITION", builder.addFloats(fan)}}}, {"mode", 6}});
  const GltfContents contents = load(builder);
  ASSERT_EQ(contents.meshes.size(), 2u);
  // glTF 2.0 section 3.7.2.1: strip {v_i, v_i+(1+i%2), v_i+(2-i%2)}, fan {v_i+1, v_i+2, v_0}.
  EXPECT_EQ(contents.meshes[0].indices, (std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2, 2, 3, 4}));
  EXPECT_EQ(contents.meshes[1].indices, (std::vector<std::uint32_t>{1, 2, 0, 2, 3, 0, 3, 4, 0}));
  for (const Mesh& m : contents.meshes)
    for (const glm::vec3& n : m.normals) expectNear(n, glm::vec3(0, 0, 1));
}

TEST_F(GltfLoad, ReadsAllIndexTypes) {
  const test::CubeGeometry cube = test::unitCube();
  for (const int type : {test::kUnsignedByte, test::kUnsignedShort, test::kUnsignedInt}) {
    GltfBuilder builder;
    builder.addPrimitiveNode({{"attributes", {{"POSITION", builder.addFloats(cube.positions)}}},
                              {"indices", builder.addIndices(cube.indices, type)}});
    const GltfContents contents = load(builder);
    EXPECT_EQ(contents.meshes[0].indices, cube.indices) << "component type " << type;
  }
}

TEST_F(GltfLoad, NonIndexedPrimitiveUsesVerticesInOrder) {
  std::vector<glm::vec3> positions = kTriangle;
  for (const glm::vec3& p : kTriangle) positions.push_back(p + glm::vec3(0, 0, 1));
  GltfBuilder builder;
  builder.addPrimitiveNode({{"attributes", {{"POSITION", builder.addFloats(positions)}}}});
  const GltfContents contents = load(builder);
  EXPECT_EQ(contents.meshes[0].indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
}

TEST_F(GltfLoad, GeneratesMissingNormalsWithAWarning) {
  const test::CubeGeometry cube = test::unitCube();
  GltfBuilder builder;
  builder.addPrimitiveNode({{"attributes", {{"POSITION", builder.addFloats(cube.positions)}}},
                            {"indices", builder.addIndices(cube.indices)}});
  const GltfContents contents = load(builder);
  const Mesh& m = contents.meshes[0];
  ASSERT_EQ(m.normals.size(), 8u);
  expectNear(m.normals[7], glm::normalize(glm::vec3(1, 1, 1)), 1e-6f);
  expectNear(m.normals[0], glm::normalize(glm::vec3(-1, -1, -1)), 1e-6f);
  ASSERT_EQ(warnings.lines().size(), 1u);
  EXPECT_TRUE(warnings.contains(
      "model.gltf: warning: mesh 0 primitive 0 has no normals; generated angle-weighted normals"));
}

TEST_F(GltfLoad, RepairsBadNormalsAndDropsZeroAreaTriangles) {
  const std::vector<glm::vec3> positions = {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0),
                                            glm::vec3(2, 0, 0)};
  const std::vector<glm::vec3> normals = {glm::vec3(0, 0, 1), glm::vec3(0.0f),
                                          glm::vec3(std::numeric_limits<float>::quiet_NaN()),
                                          glm::vec3(0, 0, 1)};
  GltfBuilder builder;
  builder.addPrimitiveNode(
      {{"attributes", {{"POSITION", builder.addFloats(positions)}, {"NORMAL", builder.addFloats(normals)}}},
       {"indices", builder.addIndices({0, 1, 2, 0, 1, 3, 2, 2, 1})}});
  const GltfContents contents = load(builder);
  const Mesh& m = contents.meshes[0];
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_EQ(m.positions.size(), 4u);  // vertices are never removed
  expectNear(m.normals[1], glm::vec3(0, 0, 1));
  expectNear(m.normals[2], glm::vec3(0, 0, 1));
  EXPECT_TRUE(warnings.contains("model.gltf: warning: mesh 0 primitive 0: dropped 2 zero-area triangles"));
  EXPECT_TRUE(
      warnings.contains("model.gltf: warning: mesh 0 primitive 0: replaced 2 zero-length or NaN normals with "
                        "angle-weighted normals"));
}

TEST_F(GltfLoad, InterleavedStrideAndQuantizedAttributes) {
  // Interleaved position + normal (byteStride 24), then KHR_mesh_quantization-style integers:
  // normalised unsigned byte texcoords, and plain short positions padded to an 8-byte stride.
  struct Vertex {
    glm::vec3 position, normal;
  };
  const std::vector<Vertex> vertices = {{kTriangle[0], glm::vec3(0, 0, 1)},
                                        {kTriangle[1], glm::vec3(0, 0, 1)},
                                        {kTriangle[2], glm::vec3(0, 0, 1)}};
  GltfBuilder builder;
  const int view = builder.addBufferView(vertices.data(), vertices.size() * sizeof(Vertex), sizeof(Vertex));
  json& accessors = builder.document()["accessors"];
  accessors.push_back(
      {{"bufferView", view}, {"componentType", test::kFloat}, {"count", 3}, {"type", "VEC3"}});
  accessors.push_back({{"bufferView", view},
                       {"byteOffset", 12},
                       {"componentType", test::kFloat},
                       {"count", 3},
                       {"type", "VEC3"}});
  const std::uint8_t uv[] = {0, 255, 255, 0, 0, 0, 0, 0};
  const int texcoords = builder.addAccessor(uv, 6, test::kUnsignedByte, 3, "VEC2", /*normalized=*/true);
  builder.addPrimitiveNode({{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", texcoords}}}});

  const std::int16_t shorts[] = {0, 0, 0, 0, 100, 0, 0, 0, 0, 0, 100, 0};  // padded to 4-byte elements
  builder.addNode({{"mesh", builder.addMesh(json::array(
                                {{{"attributes",
                                   {{"POSITION", builder.addAccessor(shorts, sizeof(shorts), test::kShort, 3,
                                                                     "VEC3", false, 8)}}}}}))}});
  const GltfContents contents = load(builder);
  ASSERT_EQ(contents.meshes.size(), 2u);
  EXPECT_EQ(contents.meshes[0].positions, kTriangle);
  EXPECT_EQ(contents.meshes[0].normals[2], glm::vec3(0, 0, 1));
  EXPECT_EQ(contents.meshes[0].texcoords,
            (std::vector<glm::vec2>{glm::vec2(0, 1), glm::vec2(1, 0), glm::vec2(0, 0)}));
  EXPECT_EQ(contents.meshes[1].positions[1], glm::vec3(100, 0, 0));
  EXPECT_EQ(contents.meshes[1].positions[2], glm::vec3(0, 0, 100));
}

TEST_F(GltfLoad, ReadsCustomAttributesInVertexOrder) {
  GltfBuilder builder;
  const std::vector<float> occlusion = {0.25f, 0.5f, 0.75f};
  const std::vector<glm::vec3> bent = {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)};
  builder.addPrimitiveNode({{"attributes",
                             {{"POSITION", builder.addFloats(kTriangle)},
                              {"_AO", builder.addFloats(occlusion)},
                              {"_BENT", builder.addFloats(bent)},
                              {"COLOR_0", builder.addFloats(bent)}}}});
  const GltfContents contents = load(builder);
  const Mesh& m = contents.meshes[0];
  ASSERT_EQ(m.attributes.size(), 2u);
  EXPECT_EQ(m.attributes.at("_AO").componentCount, 1);
  EXPECT_EQ(m.attributes.at("_AO").data, occlusion);
  EXPECT_EQ(m.attributes.at("_BENT").componentCount, 3);
  EXPECT_EQ(m.attributes.at("_BENT").data, (std::vector<float>{1, 0, 0, 0, 1, 0, 0, 0, 1}));
}

// COLOR_0 (glTF 2.0 section 3.7.2.1): VEC3 float reads alpha 1; normalised unsigned bytes and
// shorts divide by 255 and 65535; floats outside [0, 1] are clamped with a warning.
TEST_F(GltfLoad, ReadsVertexColours) {
  GltfBuilder builder;
  const std::vector<glm::vec3> rgb = {glm::vec3(1, 0, 0), glm::vec3(0, 0.5f, 0), glm::vec3(0, 0, 0.25f)};
  const std::uint8_t bytes[12] = {255, 0, 0, 51, 0, 255, 0, 102, 0, 0, 255, 255};
  const std::uint16_t shorts[12] = {65535, 0, 0, 0, 0, 65535, 0, 65535, 0, 0, 65535, 13107};
  const std::vector<glm::vec4> outside = {glm::vec4(1.5f, -0.25f, 0.5f, 1), glm::vec4(0.5f), glm::vec4(2.0f)};
  builder.addPrimitiveNode(
      {{"attributes", {{"POSITION", builder.addFloats(kTriangle)}, {"COLOR_0", builder.addFloats(rgb)}}}});
  builder.addPrimitiveNode({{"attributes",
                             {{"POSITION", builder.addFloats(kTriangle)},
                              {"COLOR_0", builder.addAccessor(bytes, sizeof(bytes), test::kUnsignedByte, 3,
                                                              "VEC4", true)}}}});
  builder.addPrimitiveNode({{"attributes",
                             {{"POSITION", builder.addFloats(kTriangle)},
                              {"COLOR_0", builder.addAccessor(shorts, sizeof(shorts), test::kUnsignedShort, 3,
                                                              "VEC4", true)}}}});
  builder.addPrimitiveNode(
      {{"attributes", {{"POSITION", builder.addFloats(kTriangle)}, {"COLOR_0", builder.addFloats(outside)}}}});
  const GltfContents contents = load(builder);
  ASSERT_EQ(contents.meshes.size(), 4u);
  EXPECT_EQ(contents.meshes[0].colors,
            (std::vector<glm::vec4>{glm::vec4(1, 0, 0, 1), glm::vec4(0, 0.5f, 0, 1), glm::vec4(0, 0, 0.25f, 1)}));
  EXPECT_FALSE(contents.meshes[0].hasVertexAlpha());
  EXPECT_EQ(contents.meshes[1].colors[0], glm::vec4(1, 0, 0, 0.2f));
  EXPECT_EQ(contents.meshes[1].colors[2], glm::vec4(0, 0, 1, 1));
  EXPECT_TRUE(contents.meshes[1].hasVertexAlpha());
  EXPECT_EQ(contents.meshes[2].colors[1], glm::vec4(0, 1, 0, 1));
  EXPECT_EQ(contents.meshes[2].colors[2], glm::vec4(0, 0, 1, 0.2f));
  EXPECT_EQ(contents.meshes[3].colors[0], glm::vec4(1, 0, 0.5f, 1));
  EXPECT_EQ(contents.meshes[3].colors[2], glm::vec4(1));
  EXPECT_TRUE(warnings.contains("model.gltf: warning: mesh 3 primitive 0: COLOR_0 has 6 components outside [0, 1]; clamped"));
  // A primitive without COLOR_0 has none (white in every program).
  builder = GltfBuilder();
  builder.addPrimitiveNode({{"attributes", {{"POSITION", builder.addFloats(kTriangle)}}}});
  EXPECT_TRUE(load(builder).meshes[0].colors.empty());
}

TEST_F(GltfLoad, RefusesVertexColoursGltfDoesNotAllow) {
  const std::uint8_t bytes[12] = {255, 0, 0, 51, 0, 255, 0, 102, 0, 0, 255, 255};
  {  // integers must be normalised
    GltfBuilder builder;
    builder.addPrimitiveNode({{"attributes",
                               {{"POSITION", builder.addFloats(kTriangle)},
                                {"COLOR_0", builder.addAccessor(bytes, sizeof(bytes), test::kUnsignedByte, 3,
                                                                "VEC4", false)}}}});
    EXPECT_NE(loadError(builder).find("model.gltf: mesh 0 primitive 0: COLOR_0 must be float, normalized unsigned "
                                      "byte or normalized unsigned short"),
              std::string::npos)
        << loadError(builder);
  }
  {  // VEC2 is not a colour
    GltfBuilder builder;
    const std::vector<glm::vec2> uv = {glm::vec2(0), glm::vec2(1), glm::vec2(0.5f)};
    builder.addPrimitiveNode(
        {{"attributes", {{"POSITION", builder.addFloats(kTriangle)}, {"COLOR_0", builder.addFloats(uv)}}}});
    EXPECT_NE(loadError(builder).find("model.gltf: mesh 0 primitive 0: COLOR_0 must be VEC3 or VEC4"),
              std::string::npos)
        << loadError(builder);
  }
  {  // NaN
    GltfBuilder builder;
    const std::vector<glm::vec3> rgb = {glm::vec3(1), glm::vec3(std::nanf("")), glm::vec3(1)};
    builder.addPrimitiveNode(
        {{"attributes", {{"POSITION", builder.addFloats(kTriangle)}, {"COLOR_0", builder.addFloats(rgb)}}}});
    EXPECT_NE(loadError(builder).find("model.gltf: mesh 0 primitive 0: COLOR_0: non-finite value"),
              std::string::npos)
        << loadError(builder);
  }
  {  // a count that is not POSITION's
    GltfBuilder builder;
    const std::vector<glm::vec3> rgb = {glm::vec3(1), glm::vec3(1)};
    builder.addPrimitiveNode(
        {{"attributes", {{"POSITION", builder.addFloats(kTriangle)}, {"COLOR_0", builder.addFloats(rgb)}}}});
    EXPECT_NE(loadError(builder).find("model.gltf: mesh 0 primitive 0: COLOR_0 has 2 elements but POSITION has 3"),
              std::string::npos)
        << loadError(builder);
  }
}

// A sparse accessor (glTF 2.0 section 3.6.2.3): the listed elements of the base replace, and an
// accessor without a buffer view is zeros before them.
TEST_F(GltfLoad, ReadsSparseAccessors) {
  GltfBuilder builder;
  const int positions = builder.addFloats(kTriangle);
  const std::uint16_t moved[1] = {1};
  const float to[3] = {5, 0, 0};
  builder.document()["accessors"][positions]["sparse"] = {
      {"count", 1},
      {"indices", {{"bufferView", builder.addBufferView(moved, sizeof(moved))}, {"componentType", test::kUnsignedShort}}},
      {"values", {{"bufferView", builder.addBufferView(to, sizeof(to))}}}};
  builder.document()["accessors"][positions]["max"] = {5, 1, 0};
  const std::uint8_t at[2] = {0, 2};
  const float weights[2] = {0.25f, 0.75f};
  json& accessors = builder.document()["accessors"];
  accessors.push_back({{"componentType", test::kFloat},
                       {"count", 3},
                       {"type", "SCALAR"},
                       {"sparse",
                        {{"count", 2},
                         {"indices", {{"bufferView", builder.addBufferView(at, sizeof(at))},
                                      {"componentType", test::kUnsignedByte}}},
                         {"values", {{"bufferView", builder.addBufferView(weights, sizeof(weights))}}}}}});
  builder.addPrimitiveNode({{"attributes", {{"POSITION", positions}, {"_W", int(accessors.size()) - 1}}}});
  const GltfContents contents = load(builder);
  const Mesh& m = contents.meshes[0];
  EXPECT_EQ(m.positions, (std::vector<glm::vec3>{glm::vec3(0, 0, 0), glm::vec3(5, 0, 0), glm::vec3(0, 1, 0)}));
  EXPECT_EQ(m.attributes.at("_W").data, (std::vector<float>{0.25f, 0.0f, 0.75f}));
}

TEST_F(GltfLoad, RefusesBrokenSparseAccessors) {
  // One sparse POSITION over kTriangle, with `indices` (unsigned bytes) and `count` as given.
  const auto sparseTriangle = [](std::vector<std::uint8_t> indices, int count, std::size_t elements = 3,
                                 bool withView = true) {
    GltfBuilder builder;
    const int positions = builder.addFloats(kTriangle);
    const std::vector<float> values(3 * indices.size(), 1.0f);
    json& accessor = builder.document()["accessors"][positions];
    accessor["count"] = elements;
    if (!withView) accessor.erase("bufferView");
    accessor["sparse"] = {
        {"count", count},
        {"indices", {{"bufferView", builder.addBufferView(indices.data(), indices.size())},
                     {"componentType", test::kUnsignedByte}}},
        {"values", {{"bufferView", builder.addBufferView(values.data(), values.size() * sizeof(float))}}}};
    builder.addPrimitiveNode({{"attributes", {{"POSITION", positions}}}});
    return loadError(builder);
  };
  EXPECT_NE(sparseTriangle({3}, 1).find("model.gltf: accessor 0 (POSITION): sparse index 3 out of range (3 elements)"),
            std::string::npos)
      << sparseTriangle({3}, 1);
  EXPECT_NE(sparseTriangle({2, 1}, 2).find("model.gltf: accessor 0 (POSITION): sparse indices do not strictly increase"),
            std::string::npos)
      << sparseTriangle({2, 1}, 2);
  EXPECT_NE(sparseTriangle({0}, 2).find("model.gltf: accessor 0 (POSITION) sparse indices reads past the end of buffer "
                                        "view"),
            std::string::npos)
      << sparseTriangle({0}, 2);
  EXPECT_NE(sparseTriangle({0}, 0).find("model.gltf: accessor 0 (POSITION): sparse count 0 is not in 1..3"),
            std::string::npos)
      << sparseTriangle({0}, 0);
  // Zeros without a buffer view, so the count is bounded by the limit alone.
  EXPECT_NE(sparseTriangle({0}, 1, std::size_t(1) << 40, false)
                .find("model.gltf: accessor 0 (POSITION) is sparse with 1099511627776 elements, beyond the limit of 256 MiB"),
            std::string::npos)
      << sparseTriangle({0}, 1, std::size_t(1) << 40, false);
}

// Material extensions iblkit does not render are named once each, with their materials.
TEST_F(GltfLoad, NamesTheMaterialExtensionsItDoesNotRender) {
  GltfBuilder builder;
  builder.addPrimitiveNode({{"attributes", {{"POSITION", builder.addFloats(kTriangle)}}}, {"material", 0}});
  json& materials = builder.document()["materials"];
  materials.push_back({{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
                                       {"KHR_materials_ior", {{"ior", 1.33}}}}}});
  materials.push_back({{"extensions", {{"KHR_materials_specular", {{"specularFactor", 0.5}}},
                                       {"KHR_materials_ior", {{"ior", 1.5}}}}}});
  materials.push_back({{"extensions", {{"KHR_materials_transmission", json::object()}}}});
  const GltfContents contents = load(builder);
  EXPECT_EQ(contents.materials.size(), 3u);
  EXPECT_TRUE(warnings.contains(
      "model.gltf: warning: KHR_materials_transmission is not rendered: materials 0, 2 are drawn without it"))
      << warnings.lines().size();
  // The read ones (specular, ior) are not named; the other warning: the triangle's generated normals.
  EXPECT_EQ(warnings.lines().size(), 2u);
  EXPECT_FLOAT_EQ(contents.materials[0].ior, 1.33f);
  EXPECT_EQ(contents.materials[1].ior, 1.5f);
  EXPECT_EQ(contents.materials[2].ior, 1.5f);
  // KHR_materials_ior allows 0 and [1, inf); iblkit [1, 1000].
  materials[2]["extensions"]["KHR_materials_ior"] = {{"ior", 0.5}};
  EXPECT_NE(loadError(builder).find("model.gltf: material 2 KHR_materials_ior.ior must be 0 or in [1, 1000]"),
            std::string::npos)
      << loadError(builder);
  materials[2]["extensions"]["KHR_materials_ior"] = {{"ior", 0}};
  EXPECT_EQ(load(builder).materials[2].ior, 0.0f);
}

// A skinned triangle (glTF 2.0 section 3.7.3) in its static pose: joint 0 moved by +5 in z, joint 1
// turned 90 degrees about +Y (x -> -z) with an inverse bind matrix that undoes its +2 in y, so it
// only turns. Vertex 0 follows joint 0, vertex 2 joint 1, vertex 1 half each (weights 2 and 2:
// divided by their sum). The mesh node's own transform (scale 100) is not applied.
TEST_F(GltfLoad, SkinnedMeshTakesItsJointsPose) {
  GltfBuilder builder;
  const std::uint8_t joints[12] = {0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0};
  const std::vector<glm::vec4> weights = {glm::vec4(1, 0, 0, 0), glm::vec4(2, 2, 0, 0), glm::vec4(1, 0, 0, 0)};
  const std::vector<glm::vec3> positions = {glm::vec3(1, 0, 0), glm::vec3(1, 1, 0), glm::vec3(1, 0, 0)};
  const int mesh = builder.addMesh(json::array(
      {{{"attributes",
         {{"POSITION", builder.addFloats(positions)},
          {"JOINTS_0", builder.addAccessor(joints, sizeof(joints), test::kUnsignedByte, 3, "VEC4")},
          {"WEIGHTS_0", builder.addFloats(weights)}}}}}));
  const float s = std::sqrt(0.5f);
  const int joint0 = builder.addNode({{"translation", {0, 0, 5}}}, false);
  const int joint1 = builder.addNode({{"translation", {0, 2, 0}}, {"rotation", {0, s, 0, s}}}, false);
  const glm::mat4 inverseBind1 = glm::translate(glm::mat4(1.0f), glm::vec3(0, -2, 0));
  std::vector<float> matrices(32, 0.0f);
  for (int i = 0; i < 4; ++i) matrices[std::size_t(5 * i)] = 1.0f;
  std::memcpy(matrices.data() + 16, &inverseBind1[0][0], 16 * sizeof(float));
  builder.document()["accessors"].push_back(
      {{"bufferView", builder.addBufferView(matrices.data(), matrices.size() * sizeof(float))},
       {"componentType", test::kFloat},
       {"count", 2},
       {"type", "MAT4"}});
  builder.document()["skins"] = {
      {{"joints", {joint0, joint1}}, {"inverseBindMatrices", int(builder.document()["accessors"].size()) - 1}}};
  builder.addNode({{"children", {joint0, joint1}}});
  builder.addNode({{"mesh", mesh}, {"skin", 0}, {"scale", {100, 100, 100}}});
  const GltfContents contents = load(builder);
  ASSERT_EQ(contents.meshes.size(), 1u);
  const std::vector<glm::vec3>& p = contents.meshes[0].positions;
  EXPECT_LT(glm::distance(p[0], glm::vec3(1, 0, 5)), 1e-5f) << p[0].x << " " << p[0].y << " " << p[0].z;
  // Half of (1, 1, 5) and half of the turned (0, 1, -1).
  EXPECT_LT(glm::distance(p[1], glm::vec3(0.5f, 1.0f, 2.0f)), 1e-5f) << p[1].x << " " << p[1].y << " " << p[1].z;
  EXPECT_LT(glm::distance(p[2], glm::vec3(0, 0, -1)), 1e-5f) << p[2].x << " " << p[2].y << " " << p[2].z;

  // A joint index past the skin's joints is an error naming both.
  const std::uint8_t far[12] = {0, 0, 0, 0, 7, 0, 0, 0, 1, 0, 0, 0};
  builder.document()["meshes"][mesh]["primitives"][0]["attributes"]["JOINTS_0"] =
      builder.addAccessor(far, sizeof(far), test::kUnsignedByte, 3, "VEC4");
  EXPECT_NE(loadError(builder).find("model.gltf: mesh 0 primitive 0: JOINTS refer to joint 7 of skin 0, which has 2"),
            std::string::npos)
      << loadError(builder);
  // So is a non-finite inverse bind matrix.
  matrices[21] = std::numeric_limits<float>::quiet_NaN();
  builder.document()["accessors"].push_back(
      {{"bufferView", builder.addBufferView(matrices.data(), matrices.size() * sizeof(float))},
       {"componentType", test::kFloat},
       {"count", 2},
       {"type", "MAT4"}});
  builder.document()["skins"][0]["inverseBindMatrices"] = int(builder.document()["accessors"].size()) - 1;
  EXPECT_NE(loadError(builder).find("model.gltf: skin 0: non-finite inverse bind matrix"), std::string::npos)
      << loadError(builder);
}

// Morph targets at their default weights (section 3.7.2.2): the mesh's weights, or the node's,
// which override them.
TEST_F(GltfLoad, MorphTargetsAtTheirDefaultWeights) {
  GltfBuilder builder;
  const std::vector<glm::vec3> lift = {glm::vec3(0), glm::vec3(0), glm::vec3(0, 0, 2)};
  const int mesh = builder.addMesh(json::array({{{"attributes", {{"POSITION", builder.addFloats(kTriangle)}}},
                                                 {"targets", {{{"POSITION", builder.addFloats(lift)}}}}}}));
  builder.document()["meshes"][mesh]["weights"] = {0.5};
  builder.addNode({{"mesh", mesh}});
  builder.addNode({{"mesh", mesh}, {"weights", {1.0}}});
  const GltfContents contents = load(builder);
  ASSERT_EQ(contents.meshes.size(), 2u);
  EXPECT_EQ(contents.meshes[0].positions[2], glm::vec3(0, 1, 1));
  EXPECT_EQ(contents.meshes[1].positions[2], glm::vec3(0, 1, 2));
  EXPECT_EQ(contents.meshes[0].positions[1], kTriangle[1]);
}

// EXT_mesh_gpu_instancing: one mesh per instance, each instance's TRS in the node's space; a
// file that requires the extension loads.
TEST_F(GltfLoad, InstancingDrawsTheMeshOncePerInstance) {
  GltfBuilder builder;
  const int mesh = builder.addMesh(json::array({{{"attributes", {{"POSITION", builder.addFloats(kTriangle)}}}}}));
  const std::vector<glm::vec3> translations = {glm::vec3(1, 0, 0), glm::vec3(2, 0, 0)};
  const std::vector<glm::vec3> scales = {glm::vec3(1), glm::vec3(2)};
  const int t = builder.addFloats(translations), sc = builder.addFloats(scales);
  builder.addNode({{"mesh", mesh},
                   {"translation", {0, 10, 0}},
                   {"extensions", {{"EXT_mesh_gpu_instancing", {{"attributes", {{"TRANSLATION", t}, {"SCALE", sc}}}}}}}});
  builder.document()["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
  builder.document()["extensionsRequired"] = {"EXT_mesh_gpu_instancing"};
  const GltfContents contents = load(builder);
  ASSERT_EQ(contents.meshes.size(), 2u);
  EXPECT_EQ(contents.meshes[0].positions[1], glm::vec3(2, 10, 0));  // (1, 0, 0) + (1, 0, 0) + (0, 10, 0)
  EXPECT_EQ(contents.meshes[1].positions[1], glm::vec3(4, 10, 0));  // 2 (1, 0, 0) + (2, 0, 0) + (0, 10, 0)
  EXPECT_EQ(contents.meshes[1].positions[2], glm::vec3(2, 12, 0));
  // Mismatched counts are an error.
  const std::vector<glm::vec3> one = {glm::vec3(1)};
  builder.document()["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["SCALE"] = builder.addFloats(one);
  EXPECT_NE(loadError(builder).find("model.gltf: node 0 EXT_mesh_gpu_instancing: TRANSLATION, ROTATION and SCALE have "
                                    "different counts"),
            std::string::npos)
      << loadError(builder);
}

// KHR_lights_punctual's lights are not rendered: the user is told.
TEST_F(GltfLoad, PunctualLightsAreNamedAsNotRendered) {
  GltfBuilder builder;
  builder.addPrimitiveNode({{"attributes", {{"POSITION", builder.addFloats(kTriangle)}}}});
  builder.document()["extensions"]["KHR_lights_punctual"] = {
      {"lights", {{{"type", "point"}, {"intensity", 10}}, {{"type", "directional"}}}}};
  builder.document()["extensionsUsed"] = {"KHR_lights_punctual"};
  load(builder);
  EXPECT_TRUE(warnings.contains(
      "model.gltf: warning: KHR_lights_punctual: 2 light(s) not rendered (iblkit lights a scene with its environment "
      "map only)"));
}

// KHR_materials_pbrSpecularGlossiness becomes metallic-roughness with KHR_materials_specular:
// diffuse is the base colour (factor and texture), F0 the specular factor, roughness 1 - glossiness.
TEST_F(GltfLoad, ConvertsSpecularGlossinessMaterials) {
  GltfBuilder builder;
  builder.addPrimitiveNode({{"attributes", {{"POSITION", builder.addFloats(kTriangle)}}}, {"material", 0}});
  json& document = builder.document();
  builder.addImage(test::encodePng(2, 2, std::vector<std::uint8_t>(16, 200)), "image/png");
  document["textures"] = {{{"source", 0}}};
  document["materials"] = {
      {{"extensions",
        {{"KHR_materials_pbrSpecularGlossiness",
          {{"diffuseFactor", {0.5, 0.25, 1.0, 0.8}},
           {"specularFactor", {0.04, 0.02, 0.5}},
           {"glossinessFactor", 0.75},
           {"diffuseTexture", {{"index", 0}, {"texCoord", 1}}},
           {"specularGlossinessTexture", {{"index", 0}}}}}}}}};
  document["extensionsUsed"] = {"KHR_materials_pbrSpecularGlossiness"};
  const GltfContents contents = load(builder);
  const Material& m = contents.materials[0];
  EXPECT_EQ(m.baseColor, glm::vec3(0.5f, 0.25f, 1.0f));
  EXPECT_EQ(m.alpha, 0.8f);
  EXPECT_EQ(m.metallic, 0.0f);
  EXPECT_EQ(m.roughness, 0.25f);
  EXPECT_EQ(m.specular, 1.0f);
  EXPECT_TRUE(m.baseColorTexture.present());
  EXPECT_EQ(m.baseColorTexture.texCoord, 1);
  EXPECT_FALSE(m.metallicRoughnessTexture.present());
  const BrdfLobes lobes = brdfLobes(m);
  EXPECT_LT(glm::distance(lobes.f0, glm::vec3(0.04f, 0.02f, 0.5f)), 1e-6f);
  EXPECT_TRUE(warnings.contains("model.gltf: warning: material 0 KHR_materials_pbrSpecularGlossiness: "
                                "specularGlossinessTexture is not read (its specular and glossiness factors are)"));
  for (const std::string& line : warnings.lines()) EXPECT_EQ(line.find("is not rendered"), std::string::npos) << line;
}

// A small file may not ask for unbounded memory: a mesh of 65,535 vertices (a sparse accessor
// without a view: zeros) instanced 1,025 times, or carrying 1,025 morph targets, passes the 2^26
// vertices a scene (and the target vertices a primitive) may have; each is refused before the
// copies are made.
TEST_F(GltfLoad, ExpansionBeyondTheVertexBudgetIsRefused) {
  const auto zerosMesh = [](GltfBuilder& builder) {
    const std::uint8_t at[1] = {0};
    const float value[3] = {0, 0, 0};
    json& accessors = builder.document()["accessors"];
    accessors.push_back(
        {{"componentType", test::kFloat},
         {"count", 65535},
         {"type", "VEC3"},
         {"sparse",
          {{"count", 1},
           {"indices", {{"bufferView", builder.addBufferView(at, 1)}, {"componentType", test::kUnsignedByte}}},
           {"values", {{"bufferView", builder.addBufferView(value, sizeof(value))}}}}}});
    return int(accessors.size()) - 1;
  };
  {
    GltfBuilder builder;
    const int positions = zerosMesh(builder);
    const int mesh = builder.addMesh(json::array({{{"attributes", {{"POSITION", positions}}}}}));
    const std::vector<glm::vec3> translations(1025, glm::vec3(0.0f));
    builder.addNode({{"mesh", mesh},
                     {"extensions",
                      {{"EXT_mesh_gpu_instancing", {{"attributes", {{"TRANSLATION", builder.addFloats(translations)}}}}}}}});
    EXPECT_NE(loadError(builder).find("model.gltf: node 0: the scene's meshes exceed 67108864 vertices (instances and "
                                      "reused meshes included)"),
              std::string::npos)
        << loadError(builder);
  }
  {
    GltfBuilder builder;
    const int positions = zerosMesh(builder);
    const json targets(1025, json{{"POSITION", positions}});
    builder.addPrimitiveNode({{"attributes", {{"POSITION", positions}}}, {"targets", targets}});
    EXPECT_NE(loadError(builder).find("model.gltf: mesh 0 primitive 0: 1025 morph targets of 65535 vertices, beyond the "
                                      "limit of 67108864 target vertices"),
              std::string::npos)
        << loadError(builder);
  }
}

TEST_F(GltfLoad, ConvertsMaterials) {
  GltfBuilder builder;
  json& materials = builder.document()["materials"];
  materials.push_back(
      {{"name", "gold"},
       {"pbrMetallicRoughness",
        {{"baseColorFactor", {0.9, 0.6, 0.2, 1.0}},
         {"metallicFactor", 1.0},
         {"roughnessFactor", 0.3}}},
       {"emissiveFactor", {0.5, 0.25, 0.0}},
       {"extensions",
        {{"KHR_materials_specular", {{"specularFactor", 0.4}, {"specularColorFactor", {1.0, 0.5, 0.25}}}},
         {"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}}}}});
  materials.push_back({{"name", "plastic"}, {"pbrMetallicRoughness", {{"metallicFactor", 0.0}}}});
  const int positions = builder.addFloats(kTriangle);
  builder.addPrimitiveNode({{"attributes", {{"POSITION", positions}}}, {"material", 0}});
  builder.addPrimitiveNode({{"attributes", {{"POSITION", positions}}}, {"material", 1}});
  builder.addPrimitiveNode({{"attributes", {{"POSITION", positions}}}});
  const GltfContents contents = load(builder);

  ASSERT_EQ(contents.materials.size(), 3u);  // two from the file, the default last
  const Material& gold = contents.materials[0];
  EXPECT_EQ(gold.name, "gold");
  EXPECT_EQ(gold.baseColor, glm::vec3(0.9f, 0.6f, 0.2f));
  EXPECT_EQ(gold.metallic, 1.0f);
  EXPECT_EQ(gold.roughness, 0.3f);
  EXPECT_EQ(gold.specular, 0.4f);
  EXPECT_EQ(gold.specularColor, glm::vec3(1.0f, 0.5f, 0.25f));
  EXPECT_EQ(gold.emissive, glm::vec3(2.0f, 1.0f, 0.0f));
  const Material& plastic = contents.materials[1];
  EXPECT_EQ(plastic.baseColor, glm::vec3(1.0f));
  EXPECT_EQ(plastic.metallic, 0.0f);
  EXPECT_EQ(plastic.roughness, 1.0f);
  EXPECT_EQ(plastic.specular, 1.0f);
  EXPECT_EQ(contents.materials[2].name, "default");
  EXPECT_EQ(contents.meshes[0].material, 0);
  EXPECT_EQ(contents.meshes[1].material, 1);
  EXPECT_EQ(contents.meshes[2].material, 2);
  ASSERT_EQ(warnings.lines().size(), 3u);  // normals generated for 3 meshes
  EXPECT_TRUE(contents.textures.empty());
  EXPECT_TRUE(contents.images.empty());
}

TEST_F(GltfLoad, FirstPerspectiveCameraWithItsNodeTransform) {
  GltfBuilder builder;
  json& cameras = builder.document()["cameras"];
  cameras.push_back(
      {{"type", "orthographic"}, {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}});
  cameras.push_back(
      {{"type", "perspective"},
       {"perspective", {{"yfov", 0.8}, {"aspectRatio", 1.5}, {"znear", 0.05}, {"zfar", 50.0}}}});
  cameras.push_back({{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}});
  builder.addPrimitiveNode({{"attributes", {{"POSITION", builder.addFloats(kTriangle)}}}});
  builder.addNode({{"camera", 0}});
  // Turned 90 degrees about +Y (looks down -X), standing at (5, 1, 0).
  const float s = std::sqrt(0.5f);
  builder.addNode({{"camera", 1}, {"translation", {5, 1, 0}}, {"rotation", {0, s, 0, s}}});
  builder.addNode({{"camera", 2}});
  const GltfContents contents = load(builder);
  ASSERT_TRUE(contents.camera.has_value());
  const Camera& camera = *contents.camera;
  expectNear(camera.position, glm::vec3(5, 1, 0));
  expectNear(camera.forward, glm::vec3(-1, 0, 0));
  expectNear(camera.up, glm::vec3(0, 1, 0));
  EXPECT_FLOAT_EQ(camera.yfovRadians, 0.8f);
  EXPECT_FLOAT_EQ(camera.znear, 0.05f);
  EXPECT_FLOAT_EQ(camera.zfar, 50.0f);
  EXPECT_TRUE(warnings.contains("model.gltf: warning: camera 0 is not a perspective camera; ignored"));
}

TEST_F(GltfLoad, CameraWithoutZfarGetsOneFromTheBounds) {
  GltfBuilder builder;
  builder.document()["cameras"].push_back(
      {{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}});
  builder.addPrimitiveNode({{"attributes", {{"POSITION", builder.addFloats(kTriangle)}}}});
  builder.addNode({{"camera", 0}, {"translation", {0.5f, 0.5f, 10.0f}}});
  const GltfContents contents = load(builder);
  ASSERT_TRUE(contents.camera.has_value());
  Bounds bounds;
  for (const glm::vec3& p : kTriangle) bounds.extend(p);
  EXPECT_FLOAT_EQ(contents.camera->zfar, clipPlanesFor(contents.camera->position, bounds).zfar);
  EXPECT_FLOAT_EQ(contents.camera->znear, 0.1f);
}

TEST_F(GltfLoad, ScenesDecideWhatIsLoaded) {
  GltfBuilder builder;
  const int mesh =
      builder.addMesh(json::array({{{"attributes", {{"POSITION", builder.addFloats(kTriangle)}}}}}));
  builder.addNode({{"mesh", mesh}});                                     // node 0, in scene 0
  builder.addNode({{"mesh", mesh}, {"translation", {0, 0, 7}}}, false);  // node 1, in scene 1
  builder.document()["scenes"].push_back({{"nodes", {1}}});
  builder.document()["scene"] = 1;
  EXPECT_EQ(load(builder).meshes.at(0).source.node, 1);
  builder.document().erase("scene");  // no default scene: scene 0
  EXPECT_EQ(load(builder).meshes.at(0).source.node, 0);
  builder.document().erase("scenes");  // no scenes: all root nodes
  EXPECT_EQ(load(builder).meshes.size(), 2u);
}

TEST_F(GltfLoad, SkipsPointsAndLinesWithAWarning) {
  GltfBuilder builder;
  const int positions = builder.addFloats(kTriangle);
  builder.addPrimitiveNode({{"attributes", {{"POSITION", positions}}}, {"mode", 1}});
  builder.addPrimitiveNode({{"attributes", {{"POSITION", positions}}}});
  const GltfContents contents = load(builder);
  ASSERT_EQ(contents.meshes.size(), 1u);
  EXPECT_EQ(contents.meshes[0].source.mesh, 1);
  EXPECT_TRUE(
      warnings.contains("model.gltf: warning: mesh 0 primitive 0 is points or lines (mode 1); skipped"));
}

TEST_F(GltfLoad, RejectsBadReferencesWithClearMessages) {
  {
    GltfBuilder builder;
    builder.addPrimitiveNode({{"attributes", {{"NORMAL", builder.addFloats(kTriangle)}}}});
    EXPECT_NE(loadError(builder).find("model.gltf: mesh 0 primitive 0 has no POSITION attribute"),
              std::string::npos);
  }
  {
    GltfBuilder builder;
    builder.addPrimitiveNode({{"attributes", {{"POSITION", 7}}}});
    EXPECT_NE(loadError(builder).find("model.gltf: accessor 7 (POSITION) does not exist"), std::string::npos);
  }
  {
    GltfBuilder builder;
    const int positions = builder.addFloats(kTriangle);
    builder.addPrimitiveNode({{"attributes", {{"POSITION", positions}, {"TEXCOORD_0", positions}}}});
    EXPECT_NE(loadError(builder).find(
                  "model.gltf: accessor 0 (TEXCOORD_0) has 3 components per element, expected 2"),
              std::string::npos);
  }
  {
    GltfBuilder builder;
    const int positions = builder.addFloats(kTriangle);
    const int normals = builder.addFloats(std::vector<glm::vec3>(2, glm::vec3(0, 0, 1)));
    builder.addPrimitiveNode({{"attributes", {{"POSITION", positions}, {"NORMAL", normals}}}});
    EXPECT_NE(
        loadError(builder).find("model.gltf: mesh 0 primitive 0: NORMAL has 2 elements but POSITION has 3"),
        std::string::npos);
  }
  {
    GltfBuilder builder;
    builder.addPrimitiveNode({{"attributes", {{"POSITION", builder.addFloats(kTriangle)}}},
                              {"indices", builder.addIndices({0, 1, 2, 0})}});
    EXPECT_NE(
        loadError(builder).find("model.gltf: mesh 0 primitive 0: 4 indices do not make whole triangles"),
        std::string::npos);
  }
  {
    GltfBuilder builder;
    builder.addPrimitiveNode({{"attributes", {{"POSITION", builder.addFloats(kTriangle)}}}, {"material", 3}});
    EXPECT_NE(loadError(builder).find("model.gltf: mesh 0 primitive 0: material 3 does not exist"),
              std::string::npos);
  }
  {
    GltfBuilder builder;
    builder.addPrimitiveNode({{"attributes", {{"POSITION", builder.addFloats(kTriangle)}}}});
    builder.document()["scenes"][0]["nodes"].push_back(9);
    EXPECT_NE(loadError(builder).find("model.gltf: node 9 does not exist"), std::string::npos);
  }
  {
    GltfBuilder builder;
    const std::vector<glm::vec3> huge = {glm::vec3(0), glm::vec3(3e38f, 0, 0), glm::vec3(0, 1, 0)};
    const int mesh =
        builder.addMesh(json::array({{{"attributes", {{"POSITION", builder.addFloats(huge)}}}}}));
    builder.addNode({{"mesh", mesh}, {"scale", {10, 1, 1}}});  // overflows to infinity in world space
    EXPECT_NE(loadError(builder).find("model.gltf: mesh 0 primitive 0: non-finite vertex position"),
              std::string::npos);
  }
  {
    // Finite but beyond kMaxSceneCoordinate: named with its node, not later by the ray scene.
    GltfBuilder builder;
    const int mesh =
        builder.addMesh(json::array({{{"attributes", {{"POSITION", builder.addFloats(kTriangle)}}}}}));
    builder.addNode({{"mesh", mesh}, {"scale", {1e25, 1, 1}}});
    EXPECT_NE(loadError(builder).find("model.gltf: mesh 0 primitive 0: vertex position beyond 1e+09 (vertex 1 in "
                                      "node 0, after its transforms"),
              std::string::npos)
        << loadError(builder);
  }
}

// A .glb whose BIN chunk claims more bytes than follow it (the file's total length field agreeing
// with the file): tinygltf 2.7.0 read up to 8 bytes past the end of such a file (fuzz_gltf's
// finding, fuzz/corpus/gltf/finding_bin_chunk_past_end.glb); it is refused before tinygltf sees it.
TEST_F(GltfLoad, BinChunkPastTheEndOfTheFileIsRefused) {
  GltfBuilder builder;
  builder.addPrimitiveNode({{"attributes", {{"POSITION", builder.addFloats(kTriangle)}}}});
  const std::filesystem::path file = test::scratchDir() / "model.glb";
  builder.write(file, GltfBuilder::Storage::Glb);
  std::vector<char> bytes(std::filesystem::file_size(file));
  std::ifstream(file, std::ios::binary).read(bytes.data(), std::streamsize(bytes.size()));
  std::uint32_t jsonLength = 0, binLength = 0;
  std::memcpy(&jsonLength, bytes.data() + 12, 4);
  const std::size_t binAt = 20 + jsonLength;
  std::memcpy(&binLength, bytes.data() + binAt, 4);
  ASSERT_EQ(binAt + 8 + binLength, bytes.size());
  binLength += 4;  // within the 8 bytes tinygltf left unchecked
  std::memcpy(bytes.data() + binAt, &binLength, 4);
  std::ofstream(file, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
  std::string message = "(no error)";
  try {
    loadGltf(file);
  } catch (const Error& e) {
    message = e.what();
  }
  EXPECT_EQ(message,
            file.string() + ": BIN chunk of " + std::to_string(binLength) +
                " bytes runs past the end of the file (" + std::to_string(binLength - 4) +
                " bytes left; truncated file?)");
}

// The committed bad-input corpus (tests/data/bad, generated by make_bad_gltf.py).
struct BadFile {
  const char* name;
  const char* message;  // the whole message after "<path>: "
};

const BadFile kBadFiles[] = {
    {"truncated.glb", "Invalid glTF binary."},
    {"accessor_past_buffer.gltf", "accessor 0 (POSITION) reads past the end of buffer view 0"},
    {"buffer_view_past_buffer.gltf", "buffer view 0 reads past the end of buffer 0"},
    {"index_out_of_range.gltf", "mesh 0 primitive 0: index 57 out of range (3 vertices)"},
    {"uri_outside_folder.gltf", "buffer 0 uri '../secret.bin' points outside the scene folder"},
    {"nan_position.gltf",
     "mesh 0 primitive 0: non-finite vertex position (vertex 1 in node 0, after its transforms: scale, "
     "translation or matrix)"},
    {"points_only.gltf", "no triangle meshes"},
    {"node_cycle.gltf", "node 0 is reached twice in the scene graph (a cycle or two parents)"},
    {"unsupported_extension.gltf", "requires unsupported extension EXT_texture_avif"},
};

TEST_F(GltfLoad, BadFilesGiveExactMessages) {
  for (const BadFile& bad : kBadFiles) {
    const std::filesystem::path path = test::dataDir() / "bad" / bad.name;
    try {
      loadGltf(path);
      ADD_FAILURE() << bad.name << " loaded";
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()), path.string() + ": " + bad.message);
    }
  }
}

TEST_F(GltfLoad, BadFilesWhoseMessagesComeFromLibraries) {
  const std::filesystem::path bad = test::dataDir() / "bad";
  const auto message = [](const std::filesystem::path& path) -> std::string {
    try {
      loadGltf(path);
    } catch (const Error& e) {
      return e.what();
    }
    return "(no error)";
  };
  // tinygltf's JSON parser (nlohmann) and file lookup, Draco's decoder: one line each.
  const std::string garbage = message(bad / "garbage.gltf");
  EXPECT_EQ(garbage.rfind((bad / "garbage.gltf").string() + ": ", 0), 0u) << garbage;
  EXPECT_NE(garbage.find("parse error"), std::string::npos) << garbage;
  const std::string missing = message(bad / "missing_bin.gltf");
  EXPECT_NE(missing.find("File not found : missing.bin"), std::string::npos) << missing;
  const std::string draco = message(bad / "bad_draco.glb");
  EXPECT_NE(draco.find("bad_draco.glb: mesh 0 primitive 0: Draco stream does not decode ("),
            std::string::npos)
      << draco;
  for (const std::string& text : {garbage, missing, draco})
    EXPECT_EQ(text.find('\n'), std::string::npos) << text;
}

TEST_F(GltfLoad, EveryFileInTheBadCorpusIsRejected) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::dataDir() / "bad")) {
    const std::string extension = entry.path().extension().string();
    if (extension != ".gltf" && extension != ".glb") continue;
    ++files;
    EXPECT_THROW(loadGltf(entry.path()), Error) << entry.path();
  }
  EXPECT_GE(files, 12);
}

TEST_F(GltfLoad, RealDracoAssets) {
  const std::filesystem::path models = test::assetsDir() / "models";
  if (!std::filesystem::exists(models / "bunny.glb")) GTEST_SKIP() << "assets not fetched: " << models;
  struct Expected {
    const char* name;
    std::size_t vertices, triangles;
  };
  for (const Expected& expected : {Expected{"bunny.glb", 2826, 5648}, Expected{"suzi.glb", 7503, 14842}}) {
    const GltfContents contents = loadGltf(models / expected.name);
    ASSERT_EQ(contents.meshes.size(), 1u) << expected.name;
    const Mesh& m = contents.meshes[0];
    EXPECT_EQ(m.vertexCount(), expected.vertices) << expected.name;
    EXPECT_EQ(m.triangleCount(), expected.triangles) << expected.name;
    EXPECT_EQ(m.normals.size(), m.vertexCount());
    const Bounds b = m.bounds();
    EXPECT_GT(b.radius(), 0.5f) << expected.name;  // both models span about [-0.93, 0.94]
    EXPECT_LT(b.radius(), 2.0f) << expected.name;
    for (const glm::vec3& n : m.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-4f);
  }
  const GltfContents bunny = loadGltf(models / "bunny.glb");
  EXPECT_EQ(bunny.materials.at(0).baseColor, glm::vec3(0.8f));
  EXPECT_EQ(bunny.materials.at(0).metallic, 0.0f);
  EXPECT_EQ(bunny.materials.at(0).roughness, 0.5f);
  // The accessor min/max of the file bound the decoded positions.
  expectNear(bunny.meshes[0].bounds().min, glm::vec3(-0.9137708f, -0.8910416f, -0.6963724f), 1e-4f);
  expectNear(bunny.meshes[0].bounds().max, glm::vec3(0.9172143f, 0.9398829f, 0.6988643f), 1e-4f);
}

// ---------------------------------------------------------------------------------------------
// Textures

const std::vector<glm::vec2> kTriangleUvs = {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(0, 1)};

// A triangle with TEXCOORD_0 whose material 0 has baseColorTexture texture 0 (source image 0);
// the test adds the image.
GltfBuilder texturedTriangle() {
  GltfBuilder builder;
  builder.addPrimitiveNode({{"attributes",
                             {{"POSITION", builder.addFloats(kTriangle)}, {"TEXCOORD_0", builder.addFloats(kTriangleUvs)}}},
                            {"material", 0}});
  builder.document()["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  builder.document()["textures"] = {{{"source", 0}}};
  return builder;
}

void expectQuadImage(const TextureImage& image) {
  EXPECT_EQ(image.width, 2);
  EXPECT_EQ(image.height, 2);
  EXPECT_EQ(image.channels, 4);
  EXPECT_EQ(image.rgba, test::quadPixels());
}

TEST_F(GltfLoad, ImagesFromBufferViewDataUriAndFile) {
  const std::vector<std::uint8_t> png = test::encodePng(2, 2, test::quadPixels());
  {
    GltfBuilder builder = texturedTriangle();
    builder.addImage(png, "image/png");
    builder.document()["images"][0]["name"] = "albedo";
    const GltfContents contents = load(builder, GltfBuilder::Storage::Glb);
    ASSERT_EQ(contents.textures.size(), 1u);
    ASSERT_EQ(contents.images.size(), 1u);
    EXPECT_EQ(contents.textures[0].image, 0);
    EXPECT_EQ(contents.materials[0].baseColorTexture.texture, 0);
    EXPECT_EQ(contents.materials[0].baseColorTexture.texCoord, 0);
    EXPECT_TRUE(contents.materials[0].baseColorTexture.transform.identity());
    const TextureImage& image = contents.images[0];
    expectQuadImage(image);
    EXPECT_EQ(image.name, "albedo");
    EXPECT_EQ(image.mimeType, "image/png");
    EXPECT_EQ(image.encoded, png);  // the bytes as stored, for the baker to copy
    EXPECT_EQ(image.file, testDir() / "model.glb");
    EXPECT_EQ(image.uri, "");
  }
  {
    GltfBuilder builder = texturedTriangle();
    builder.document()["images"] = {{{"uri", "data:image/png;base64," + test::base64(png)}}};
    const GltfContents contents = load(builder);
    ASSERT_EQ(contents.images.size(), 1u);
    expectQuadImage(contents.images[0]);
    EXPECT_EQ(contents.images[0].encoded, png);
    EXPECT_EQ(contents.images[0].uri, "data:image/png;base64,");
  }
  {
    // A file in a subfolder, its name percent-encoded as URIs are.
    std::filesystem::create_directories(testDir() / "maps");
    test::writeFileBytes(testDir() / "maps" / "my albedo.png", png);
    GltfBuilder builder = texturedTriangle();
    builder.document()["images"] = {{{"uri", "maps/my%20albedo.png"}}};
    const GltfContents contents = load(builder);
    ASSERT_EQ(contents.images.size(), 1u);
    expectQuadImage(contents.images[0]);
    EXPECT_EQ(contents.images[0].file, testDir() / "maps" / "my albedo.png");
    EXPECT_EQ(contents.images[0].uri, "maps/my%20albedo.png");
  }
  for (const std::string& line : warnings.lines())  // the triangle has no normals; nothing else
    EXPECT_NE(line.find("generated angle-weighted normals"), std::string::npos) << line;
}

TEST_F(GltfLoad, WebpThroughExtTextureWebpAndJpeg) {
  const std::vector<std::uint8_t> webp = test::encodeWebp(2, 2, test::quadPixels());
  {
    // EXT_texture_webp's source wins over the PNG fallback, which no texture then uses: only the
    // WebP is loaded, renumbered as image 0.
    GltfBuilder builder = texturedTriangle();
    builder.addImage(test::encodePng(2, 2, std::vector<std::uint8_t>(16, 7)), "image/png");
    builder.addImage(webp, "image/webp");
    builder.document()["textures"][0]["extensions"] = {{"EXT_texture_webp", {{"source", 1}}}};
    builder.document()["extensionsUsed"] = {"EXT_texture_webp"};
    builder.document()["extensionsRequired"] = {"EXT_texture_webp"};
    const GltfContents contents = load(builder, GltfBuilder::Storage::Glb);
    ASSERT_EQ(contents.images.size(), 1u);
    EXPECT_EQ(contents.textures[0].image, 0);
    expectQuadImage(contents.images[0]);  // lossless: exact, alpha too
    EXPECT_EQ(contents.images[0].mimeType, "image/webp");
  }
  {
    // A WebP data URI, whose media type tinygltf does not know.
    GltfBuilder builder = texturedTriangle();
    builder.document()["images"] = {{{"uri", "data:image/webp;base64," + test::base64(webp)}}};
    builder.document()["textures"][0] = {{"extensions", {{"EXT_texture_webp", {{"source", 0}}}}}};
    const GltfContents contents = load(builder);
    ASSERT_EQ(contents.images.size(), 1u);
    expectQuadImage(contents.images[0]);
  }
  {
    std::vector<std::uint8_t> grey(8 * 8 * 4, 200);
    GltfBuilder builder = texturedTriangle();
    builder.addImage(test::encodeJpeg(8, 8, grey), "image/jpeg");
    const GltfContents contents = load(builder);
    ASSERT_EQ(contents.images.size(), 1u);
    EXPECT_EQ(contents.images[0].mimeType, "image/jpeg");
    EXPECT_EQ(contents.images[0].channels, 3);
    ASSERT_EQ(contents.images[0].rgba.size(), 8u * 8u * 4u);
    for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(int(contents.images[0].rgba[i]), i == 3 ? 255 : 200, 2);
  }
}

TEST_F(GltfLoad, SamplersMapToTextureSampler) {
  GltfBuilder builder = texturedTriangle();
  builder.addImage(test::encodePng(2, 2, test::quadPixels()), "image/png");
  // NEAREST 9728, LINEAR 9729, *_MIPMAP_* 9984..9987; REPEAT 10497, CLAMP 33071, MIRRORED 33648.
  builder.document()["samplers"] = {
      {{"magFilter", 9728}, {"minFilter", 9984}, {"wrapS", 33071}, {"wrapT", 33648}},
      {{"magFilter", 9729}, {"minFilter", 9729}},
      {{"minFilter", 9985}, {"wrapS", 33648}},
      {{"minFilter", 9986}},
      {{"minFilter", 9728}},
      json::object()};
  json& textures = builder.document()["textures"];
  textures = json::array();
  for (int i = 0; i < 6; ++i) textures.push_back({{"source", 0}, {"sampler", i}});
  textures.push_back({{"source", 0}});  // no sampler: the defaults
  json& materials = builder.document()["materials"];
  materials = json::array();
  for (int i = 0; i < 7; ++i) materials.push_back({{"emissiveTexture", {{"index", i}}}});

  const GltfContents contents = load(builder);
  ASSERT_EQ(contents.textures.size(), 7u);
  ASSERT_EQ(contents.images.size(), 1u);  // seven textures share the image
  using F = TextureFilter;
  using W = TextureWrap;
  struct Expected {
    W s, t;
    F mag, min;
    bool mipmaps;
    F mip;
  };
  const Expected expected[] = {{W::ClampToEdge, W::MirroredRepeat, F::Nearest, F::Nearest, true, F::Nearest},
                               {W::Repeat, W::Repeat, F::Linear, F::Linear, false, F::Linear},
                               {W::MirroredRepeat, W::Repeat, F::Linear, F::Linear, true, F::Nearest},
                               {W::Repeat, W::Repeat, F::Linear, F::Nearest, true, F::Linear},
                               {W::Repeat, W::Repeat, F::Linear, F::Nearest, false, F::Linear},
                               {W::Repeat, W::Repeat, F::Linear, F::Linear, true, F::Linear},
                               {W::Repeat, W::Repeat, F::Linear, F::Linear, true, F::Linear}};
  for (int i = 0; i < 7; ++i) {
    const TextureSampler& sampler = contents.textures[i].sampler;
    EXPECT_EQ(sampler.wrapS, expected[i].s) << i;
    EXPECT_EQ(sampler.wrapT, expected[i].t) << i;
    EXPECT_EQ(sampler.magFilter, expected[i].mag) << i;
    EXPECT_EQ(sampler.minFilter, expected[i].min) << i;
    EXPECT_EQ(sampler.mipmaps, expected[i].mipmaps) << i;
    EXPECT_EQ(sampler.mipFilter, expected[i].mip) << i;
    EXPECT_EQ(contents.textures[i].image, 0);
    EXPECT_EQ(contents.materials[i].emissiveTexture.texture, i);
  }
  // 9987 is LINEAR_MIPMAP_LINEAR: trilinear, the default.
  builder.document()["samplers"][5] = {{"minFilter", 9987}};
  EXPECT_EQ(load(builder).textures[5].sampler.mipmaps, true);

  builder.document()["samplers"][2]["wrapT"] = 12345;
  EXPECT_NE(loadError(builder).find("model.gltf: sampler 2 wrapT: unknown wrap mode 12345"), std::string::npos)
      << loadError(builder);
  builder.document()["samplers"][2] = {{"magFilter", 9984}};  // a mipmap filter is no magFilter
  EXPECT_NE(loadError(builder).find("model.gltf: sampler 2: unknown magFilter 9984"), std::string::npos);
  builder.document()["samplers"][2] = {{"minFilter", 1}};
  EXPECT_NE(loadError(builder).find("model.gltf: sampler 2: unknown minFilter 1"), std::string::npos);
}

TEST_F(GltfLoad, SlotsTexCoordsAndKhrTextureTransform) {
  GltfBuilder builder;
  const std::vector<glm::vec2> uvs1 = {glm::vec2(0.5f, 0.5f), glm::vec2(1, 0.5f), glm::vec2(0.5f, 1)};
  builder.addPrimitiveNode({{"attributes",
                             {{"POSITION", builder.addFloats(kTriangle)},
                              {"TEXCOORD_0", builder.addFloats(kTriangleUvs)},
                              {"TEXCOORD_1", builder.addFloats(uvs1)}}},
                            {"material", 0}});
  builder.addImage(test::encodePng(2, 2, test::quadPixels()), "image/png");
  builder.addImage(test::encodePng(2, 2, std::vector<std::uint8_t>(16, 9)), "image/png");
  builder.document()["textures"] = {{{"source", 0}}, {{"source", 1}}, {{"source", 0}}};
  builder.document()["extensionsUsed"] = {"KHR_texture_transform"};
  builder.document()["extensionsRequired"] = {"KHR_texture_transform"};
  const json baseTransform = {
      {"offset", {0.5, -0.25}}, {"rotation", 1.5707963}, {"scale", {2.0, 3.0}}, {"texCoord", 1}};
  json material;
  material["pbrMetallicRoughness"]["baseColorFactor"] = {1.0, 1.0, 1.0, 0.25};
  material["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 2}};
  material["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]["KHR_texture_transform"] = baseTransform;
  material["pbrMetallicRoughness"]["metallicRoughnessTexture"] = {{"index", 1}, {"texCoord", 1}};
  material["normalTexture"] = {{"index", 0}, {"scale", 0.75}};
  material["occlusionTexture"] = {{"index", 1}, {"strength", 0.5}};
  material["emissiveTexture"] = {{"index", 0}};
  material["emissiveTexture"]["extensions"]["KHR_texture_transform"]["scale"] = {4.0, 4.0};
  builder.document()["materials"] = json::array({material});
  const GltfContents contents = load(builder);

  ASSERT_EQ(contents.meshes.size(), 1u);
  EXPECT_EQ(contents.meshes[0].texcoords, kTriangleUvs);
  EXPECT_EQ(contents.meshes[0].texcoords1, uvs1);
  ASSERT_EQ(contents.textures.size(), 3u);
  EXPECT_EQ(contents.textures[2].image, 0);
  const Material& m = contents.materials[0];
  EXPECT_EQ(m.alpha, 0.25f);
  const TextureRef& base = m.baseColorTexture;
  EXPECT_EQ(base.texture, 2);
  EXPECT_EQ(base.texCoord, 1);  // the extension's texCoord overrides the textureInfo's 0
  EXPECT_EQ(base.transform.offset, glm::vec2(0.5f, -0.25f));
  EXPECT_EQ(base.transform.rotation, 1.5707963f);
  EXPECT_EQ(base.transform.scale, glm::vec2(2.0f, 3.0f));
  // Hand-computed with the extension's matrices: scale (2, 3) gives (2, 0) for uv (1, 0); the
  // rotation by pi/2 maps (x, y) to (cos x + sin y, -sin x + cos y) = (0, -2); the offset adds (0.5, -0.25).
  const glm::vec2 transformed = base.transform.apply(glm::vec2(1.0f, 0.0f));
  EXPECT_NEAR(transformed.x, 0.5f, 1e-5f);
  EXPECT_NEAR(transformed.y, -2.25f, 1e-5f);
  EXPECT_EQ(m.metallicRoughnessTexture.texture, 1);
  EXPECT_EQ(m.metallicRoughnessTexture.texCoord, 1);
  EXPECT_TRUE(m.metallicRoughnessTexture.transform.identity());
  EXPECT_EQ(m.normalTexture.texture, 0);
  EXPECT_EQ(m.normalScale, 0.75f);
  EXPECT_EQ(m.occlusionTexture.texture, 1);
  EXPECT_EQ(m.occlusionStrength, 0.5f);
  EXPECT_EQ(m.emissiveTexture.transform.scale, glm::vec2(4.0f));
  EXPECT_EQ(m.emissiveTexture.texCoord, 0);

  json& edited = builder.document()["materials"][0];
  edited["occlusionTexture"]["texCoord"] = 2;
  EXPECT_NE(loadError(builder).find(
                "model.gltf: material 0 occlusionTexture: texCoord 2 is not supported (TEXCOORD_0 and TEXCOORD_1 only)"),
            std::string::npos)
      << loadError(builder);
  edited["occlusionTexture"]["texCoord"] = 0;
  edited["emissiveTexture"]["extensions"]["KHR_texture_transform"]["offset"] = {1.0};
  EXPECT_NE(loadError(builder).find(
                "model.gltf: material 0 emissiveTexture KHR_texture_transform.offset must be 2 finite numbers"),
            std::string::npos)
      << loadError(builder);
  // Finite doubles that are infinite floats.
  edited["emissiveTexture"]["extensions"]["KHR_texture_transform"]["offset"] = {0.0, 0.0};
  edited["emissiveTexture"]["extensions"]["KHR_texture_transform"]["scale"] = {1e39, 1.0};
  EXPECT_NE(loadError(builder).find(
                "model.gltf: material 0 emissiveTexture KHR_texture_transform.scale must lie within +-1e6"),
            std::string::npos)
      << loadError(builder);
  edited["emissiveTexture"]["extensions"]["KHR_texture_transform"]["scale"] = {1.0, 1.0};
  edited["emissiveTexture"]["extensions"]["KHR_texture_transform"]["rotation"] = 1e39;
  EXPECT_NE(loadError(builder).find("model.gltf: material 0 emissiveTexture KHR_texture_transform.rotation must be a "
                                    "finite number within +-1e6"),
            std::string::npos)
      << loadError(builder);
  edited["emissiveTexture"]["extensions"]["KHR_texture_transform"].erase("rotation");
  edited["normalTexture"]["scale"] = 1e39;
  EXPECT_NE(loadError(builder).find("model.gltf: material 0 normalTexture.scale must be a finite number within +-1e6"),
            std::string::npos)
      << loadError(builder);
}

TEST_F(GltfLoad, AlphaModesAndDoubleSided) {
  GltfBuilder builder;
  const int positions = builder.addFloats(kTriangle);
  builder.addPrimitiveNode({{"attributes", {{"POSITION", positions}}}, {"material", 0}});
  builder.document()["materials"] = {
      {{"alphaMode", "MASK"}, {"alphaCutoff", 0.3}, {"doubleSided", true}},
      {{"alphaMode", "BLEND"}, {"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 0.5}}}}},
      {{"alphaMode", "OPAQUE"}},
      json::object()};
  const GltfContents contents = load(builder);
  ASSERT_EQ(contents.materials.size(), 4u);
  EXPECT_EQ(contents.materials[0].alphaMode, AlphaMode::Mask);
  EXPECT_EQ(contents.materials[0].alphaCutoff, 0.3f);
  EXPECT_TRUE(contents.materials[0].doubleSided);
  EXPECT_EQ(contents.materials[1].alphaMode, AlphaMode::Blend);
  EXPECT_EQ(contents.materials[1].alpha, 0.5f);
  EXPECT_FALSE(contents.materials[1].doubleSided);
  EXPECT_EQ(contents.materials[2].alphaMode, AlphaMode::Opaque);
  EXPECT_EQ(contents.materials[3].alphaMode, AlphaMode::Opaque);
  EXPECT_EQ(contents.materials[3].alphaCutoff, 0.5f);
  EXPECT_EQ(contents.materials[3].alpha, 1.0f);

  builder.document()["materials"][2]["alphaMode"] = "CLIP";
  EXPECT_NE(loadError(builder).find(
                "model.gltf: material 2: unknown alphaMode 'CLIP' (expected OPAQUE, MASK or BLEND)"),
            std::string::npos);
  builder.document()["materials"][2] = {{"alphaCutoff", -1}};
  EXPECT_NE(loadError(builder).find("model.gltf: material 2: alphaCutoff must be a number >= 0"),
            std::string::npos);
}

TEST_F(GltfLoad, ReadsTangents) {
  GltfBuilder builder;
  const std::vector<glm::vec4> tangents = {glm::vec4(1, 0, 0, 1), glm::vec4(1, 0, 0, -1), glm::vec4(0, 1, 0, -0.5f)};
  builder.addPrimitiveNode({{"attributes",
                             {{"POSITION", builder.addFloats(kTriangle)},
                              {"NORMAL", builder.addFloats(std::vector<glm::vec3>(3, glm::vec3(0, 0, 1)))},
                              {"TANGENT", builder.addFloats(tangents)}}}});
  GltfContents contents = load(builder);
  ASSERT_EQ(contents.meshes.size(), 1u);
  // w snapped to +-1 (the spec's values).
  EXPECT_EQ(contents.meshes[0].tangents,
            (std::vector<glm::vec4>{glm::vec4(1, 0, 0, 1), glm::vec4(1, 0, 0, -1), glm::vec4(0, 1, 0, -1)}));

  // The node's transform turns tangents as it turns the surface (transformMesh): 90 degrees about +Z
  // takes +X to +Y; w stays.
  builder.document()["nodes"][0]["rotation"] = {0, 0, std::sqrt(0.5), std::sqrt(0.5)};
  contents = load(builder);
  ASSERT_EQ(contents.meshes[0].tangents.size(), 3u);
  expectNear(glm::vec3(contents.meshes[0].tangents[0]), glm::vec3(0, 1, 0));
  expectNear(glm::vec3(contents.meshes[0].tangents[2]), glm::vec3(-1, 0, 0));
  EXPECT_EQ(contents.meshes[0].tangents[2].w, -1.0f);

  // A zero tangent cannot make a frame: the file's tangents are dropped with a warning.
  const std::vector<glm::vec4> broken = {glm::vec4(1, 0, 0, 1), glm::vec4(0, 0, 0, 1), glm::vec4(0, 1, 0, 1)};
  GltfBuilder second;
  second.addPrimitiveNode({{"attributes",
                            {{"POSITION", second.addFloats(kTriangle)},
                             {"NORMAL", second.addFloats(std::vector<glm::vec3>(3, glm::vec3(0, 0, 1)))},
                             {"TANGENT", second.addFloats(broken)}}}});
  contents = load(second);
  EXPECT_TRUE(contents.meshes[0].tangents.empty());
  EXPECT_TRUE(warnings.contains(
      "model.gltf: warning: mesh 0 primitive 0: TANGENT has 1 zero-length or non-finite tangents; ignored"));

  GltfBuilder wrong;
  const int positions = wrong.addFloats(kTriangle);
  wrong.addPrimitiveNode({{"attributes", {{"POSITION", positions}, {"TANGENT", positions}}}});
  EXPECT_NE(loadError(wrong).find("model.gltf: accessor 0 (TANGENT) has 3 components per element, expected 4"),
            std::string::npos);
}

TEST_F(GltfLoad, TexturesNoMaterialUsesAreNotLoaded) {
  GltfBuilder builder = texturedTriangle();
  builder.document()["materials"][0] = json::object();
  builder.document()["images"] = {{{"uri", "missing.png"}}};
  const GltfContents contents = load(builder);
  EXPECT_TRUE(contents.textures.empty());
  EXPECT_TRUE(contents.images.empty());
}

// Each bad texture reference or image: one line naming the file, the texture and the image.
TEST_F(GltfLoad, BadTexturesAndImagesAreNamed) {
  const std::vector<std::uint8_t> png = test::encodePng(2, 2, test::quadPixels());
  const auto error = [&](const std::function<void(GltfBuilder&)>& edit) {
    GltfBuilder builder = texturedTriangle();
    edit(builder);
    const std::string message = loadError(builder);
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    return message;
  };
  const auto expectError = [&](const std::function<void(GltfBuilder&)>& edit, const std::string& expected) {
    const std::string message = error(edit);
    EXPECT_NE(message.find(expected), std::string::npos) << "expected '" << expected << "' in: " << message;
  };
  const std::string prefix = (testDir() / "model.gltf").string() + ": ";

  expectError([](GltfBuilder& b) { b.document()["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["index"] = 4; },
              prefix + "material 0 baseColorTexture: texture 4 does not exist");
  expectError([](GltfBuilder& b) { b.document()["textures"][0]["source"] = 3; },
              prefix + "texture 0: image 3 does not exist");
  expectError([&](GltfBuilder& b) {
    b.addImage(png, "image/png");
    b.document()["textures"][0]["sampler"] = 1;
  }, prefix + "texture 0: sampler 1 does not exist");
  expectError([&](GltfBuilder& b) {
    b.addImage(png, "image/png");
    b.document()["textures"][0]["extensions"] = {{"EXT_texture_webp", {{"source", 5}}}};
  }, prefix + "texture 0: image 5 does not exist");
  expectError([](GltfBuilder& b) { b.document()["images"] = {{{"uri", "missing.png"}}}; },
              prefix + "texture 0 image 0 'missing.png': " + (testDir() / "missing.png").string() +
                  ": cannot open: No such file or directory");
  for (const std::string uri : {"../outside.png", "/etc/passwd", "file:///etc/passwd", "maps/../../outside.png"})
    expectError([&](GltfBuilder& b) { b.document()["images"] = {{{"uri", uri}}}; },
                prefix + "texture 0 image 0 '" + uri + "': uri '" + uri + "' points outside the scene folder");
  expectError([](GltfBuilder& b) {
    b.addImage({0xAB, 'K', 'T', 'X', ' ', '2', '0', 0xBB, '\r', '\n', 0x1A, '\n', 0, 0, 0, 0}, "image/ktx2");
  }, prefix + "texture 0 image 0: mime type image/ktx2 is not supported (image/png, image/jpeg and image/webp are)");
  expectError([](GltfBuilder& b) {
    test::writeFileBytes(testDir() / "basis.ktx2",
                         {0xAB, 'K', 'T', 'X', ' ', '2', '0', 0xBB, '\r', '\n', 0x1A, '\n', 0, 0, 0, 0});
    b.document()["images"] = {{{"uri", "basis.ktx2"}}};
  }, prefix + "texture 0 image 0 'basis.ktx2': KTX2 images (KHR_texture_basisu) are not supported");
  expectError([](GltfBuilder& b) {
    b.document()["textures"][0] = {{"extensions", {{"KHR_texture_basisu", {{"source", 0}}}}}};
    b.document()["images"] = {{{"uri", "basis.ktx2"}}};
  }, prefix + "texture 0 has only a KHR_texture_basisu (KTX2) image, which is not supported");
  expectError([](GltfBuilder& b) { b.document()["extensionsRequired"] = {"KHR_texture_basisu"}; },
              prefix + "requires unsupported extension KHR_texture_basisu (KTX2 textures");
  expectError([](GltfBuilder& b) { b.addImage({'G', 'I', 'F', '8', '9', 'a', 0, 0}, "image/gif"); },
              prefix + "texture 0 image 0: mime type image/gif is not supported");
  expectError([](GltfBuilder& b) { b.addImage({'n', 'o', 't', ' ', 'a', 'n', ' ', 'i', 'm', 'a', 'g', 'e'}, ""); },
              prefix + "texture 0 image 0: not a PNG, JPEG or WebP image (unknown signature)");
  expectError([&](GltfBuilder& b) {
    std::vector<std::uint8_t> cut(png.begin(), png.begin() + std::ptrdiff_t(png.size() / 2));
    b.addImage(cut, "image/png");
  }, prefix + "texture 0 image 0: PNG does not decode (");
  expectError([](GltfBuilder& b) { b.addImage(test::pngHeaderClaiming(0, 0), "image/png"); },
              prefix + "texture 0 image 0: image is 0 x 0 pixels");
  expectError([](GltfBuilder& b) { b.addImage(test::pngHeaderClaiming(65536, 65536), "image/png"); },
              prefix + "texture 0 image 0: image is 65536 x 65536 pixels, beyond the limit of 16384 on a side");
  expectError([](GltfBuilder& b) { b.addImage(test::webpHeaderClaiming(40000, 40000), "image/webp"); },
              prefix + "texture 0 image 0: image is 40000 x 40000 pixels, beyond the limit of 16384 on a side");
  expectError([](GltfBuilder& b) { b.document()["images"] = {{{"uri", "data:image/png;base64,!!!!"}}}; },
              prefix + "Failed to decode 'uri' for image[0]");
  expectError([](GltfBuilder& b) { b.document()["images"] = {{{"uri", "data:image/webp;base64,@@"}}}; },
              prefix + "texture 0 image 0 'data:image/webp;base64,': data URI is not valid base64");
  expectError([](GltfBuilder& b) { b.document()["textures"][0] = json::object(); },
              prefix + "texture 0 has no image source");
}

TEST_F(GltfLoad, KtxTextureWithAFallbackUsesItWithAWarning) {
  GltfBuilder builder = texturedTriangle();
  builder.addImage(test::encodePng(2, 2, test::quadPixels()), "image/png");
  builder.document()["images"].push_back({{"uri", "never-read.ktx2"}});
  builder.document()["textures"][0]["extensions"] = {{"KHR_texture_basisu", {{"source", 1}}}};
  const GltfContents contents = load(builder);
  ASSERT_EQ(contents.images.size(), 1u);
  expectQuadImage(contents.images[0]);
  EXPECT_TRUE(warnings.contains("model.gltf: warning: texture 0: KHR_texture_basisu (KTX2) is not supported; using "
                                "its fallback source, image 0"));
}

TEST_F(GltfLoad, MismatchedMimeTypeIsReadAsWhatTheBytesAre) {
  GltfBuilder builder = texturedTriangle();
  builder.addImage(test::encodePng(2, 2, test::quadPixels()), "image/jpeg");
  const GltfContents contents = load(builder);
  expectQuadImage(contents.images.at(0));
  EXPECT_TRUE(warnings.contains(
      "model.gltf: warning: texture 0 image 0: declared image/jpeg but holds image/png; read as image/png"));
}

}  // namespace
}  // namespace iblkit
