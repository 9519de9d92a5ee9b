#include "core/gltf_write.h"

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>

#include "core/error.h"
#include "core/gltf_load.h"
#include "support/gltf_builder.h"
#include "support/test_paths.h"
#include "support/warning_capture.h"

namespace iblkit {
namespace {

using nlohmann::json;
using test::GltfBuilder;

// The JSON of a .gltf, or the JSON chunk of a .glb.
json readDocument(const std::filesystem::path& path) {
  std::ifstream stream(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(stream)), std::istreambuf_iterator<char>());
  if (bytes.rfind("glTF", 0) != 0) return json::parse(bytes);
  std::uint32_t length = 0;
  std::memcpy(&length, bytes.data() + 12, 4);
  return json::parse(bytes.substr(20, length));
}

std::string writeError(const std::filesystem::path& input, const std::filesystem::path& output,
                       const std::vector<PrimitiveAttributes>& attributes) {
  try {
    writeGltfWithAttributes(input, output, attributes);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

class GltfWrite : public ::testing::Test {
 protected:
  test::WarningCapture warnings;  // generated normals etc. are expected here
  std::filesystem::path scratch = test::scratchDir();
};

TEST_F(GltfWrite, DracoRoundTripKeepsGeometryAndAddsTheAttribute) {
  const std::filesystem::path bunny = test::assetsDir() / "models" / "bunny.glb";
  if (!std::filesystem::exists(bunny)) GTEST_SKIP() << "assets not fetched: " << bunny;
  const GltfContents before = loadGltf(bunny);
  const Mesh& original = before.meshes.at(0);
  PrimitiveAttributes ao{original.source.mesh, original.source.primitive, "_AO", 1, {}};
  for (const glm::vec3& p : original.positions) ao.data.push_back(0.5f + 0.25f * p.y);

  const std::filesystem::path output = scratch / "bunny_ao.glb";
  writeGltfWithAttributes(bunny, output, {ao});
  const GltfContents after = loadGltf(output);
  ASSERT_EQ(after.meshes.size(), 1u);
  const Mesh& written = after.meshes[0];
  EXPECT_EQ(written.positions, original.positions);
  EXPECT_EQ(written.normals, original.normals);
  EXPECT_EQ(written.indices, original.indices);
  ASSERT_EQ(written.attributes.count("_AO"), 1u);
  EXPECT_EQ(written.attributes.at("_AO").componentCount, 1);
  EXPECT_EQ(written.attributes.at("_AO").data, ao.data);
  EXPECT_EQ(after.materials.at(0).roughness, before.materials.at(0).roughness);

  const json document = readDocument(output);
  EXPECT_FALSE(document.contains("extensionsUsed")) << document["extensionsUsed"];
  EXPECT_FALSE(document.contains("extensionsRequired"));
  EXPECT_FALSE(document["meshes"][0]["primitives"][0].contains("extensions"));
  EXPECT_EQ(document["buffers"].size(), 1u);
  EXPECT_EQ(document["bufferViews"].size(), 4u);  // indices, position, normal, _AO; no Draco stream
  EXPECT_FALSE(std::filesystem::exists(scratch / "bunny_ao.glb.tmp"));
}

// A small model with a hierarchy, a material and a camera, its buffer in a .bin file.
std::filesystem::path writeSmallModel(const std::filesystem::path& folder) {
  GltfBuilder builder;
  const std::vector<glm::vec3> strip = {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0),
                                        glm::vec3(1, 1, 0), glm::vec3(0, 2, 0)};
  builder.document()["materials"] = {
      {{"name", "red"},
       {"pbrMetallicRoughness", {{"baseColorFactor", {1, 0, 0, 1}}}},
       {"extensions", {{"KHR_materials_specular", {{"specularFactor", 0.5}}}}}}};
  builder.document()["extensionsUsed"] = {"KHR_materials_specular"};
  builder.document()["cameras"] = {
      {{"type", "perspective"}, {"perspective", {{"yfov", 0.7}, {"znear", 0.1}}}}};
  const int mesh = builder.addMesh(
      json::array({{{"attributes", {{"POSITION", builder.addFloats(strip)}}},
                    {"indices", builder.addIndices({4, 3, 2, 1, 0}, test::kUnsignedShort)},
                    {"mode", 5},
                    {"material", 0}},
                   {{"attributes",
                     {{"POSITION", builder.addFloats(std::vector<glm::vec3>{
                                       glm::vec3(5, 0, 0), glm::vec3(6, 0, 0), glm::vec3(5, 1, 0)})}}}}}));
  const int child = builder.addNode({{"mesh", mesh}, {"translation", {0, 0, -2}}}, false);
  builder.addNode({{"children", {child}}, {"scale", {2, 2, 2}}, {"extras", {{"tag", "kept"}}}});
  builder.addNode({{"camera", 0}, {"translation", {0, 1, 10}}});
  const std::filesystem::path path = folder / "small.gltf";
  builder.write(path, GltfBuilder::Storage::BinFile);
  return path;
}

TEST_F(GltfWrite, VertexOrderIsThePrimitivesOwn) {
  const std::filesystem::path input = writeSmallModel(scratch);
  const GltfContents before = loadGltf(input);
  ASSERT_EQ(before.meshes.size(), 2u);
  std::vector<PrimitiveAttributes> attributes;
  for (const Mesh& mesh : before.meshes) {
    PrimitiveAttributes id{mesh.source.mesh, mesh.source.primitive, "_VERTEX", 2, {}};
    for (std::size_t i = 0; i < mesh.vertexCount(); ++i) id.data.insert(id.data.end(), {float(i), -float(i)});
    attributes.push_back(id);
  }
  const std::filesystem::path output = scratch / "out" / "small_ids.gltf";
  std::filesystem::create_directories(output.parent_path());
  writeGltfWithAttributes(input, output, attributes);

  // The .gltf is self-contained (data URI) and keeps the hierarchy, material and camera.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(output.parent_path()),
                          std::filesystem::directory_iterator()),
            1);
  const GltfContents after = loadGltf(output);
  ASSERT_EQ(after.meshes.size(), 2u);
  for (std::size_t m = 0; m < 2; ++m) {
    EXPECT_EQ(after.meshes[m].positions, before.meshes[m].positions);
    EXPECT_EQ(after.meshes[m].indices, before.meshes[m].indices);
    const VertexAttribute& id = after.meshes[m].attributes.at("_VERTEX");
    EXPECT_EQ(id.componentCount, 2);
    for (std::size_t i = 0; i < after.meshes[m].vertexCount(); ++i) {
      EXPECT_EQ(id.data[2 * i], float(i));  // vertex i of the Mesh is vertex i of the primitive
      EXPECT_EQ(id.data[2 * i + 1], -float(i));
    }
  }
  EXPECT_EQ(after.materials.at(0).baseColor, glm::vec3(1, 0, 0));
  EXPECT_EQ(after.materials.at(0).specular, 0.5f);
  const json document = readDocument(output);
  EXPECT_EQ(document["extensionsUsed"], json({"KHR_materials_specular"}));
  EXPECT_EQ(document["nodes"][1]["extras"]["tag"], "kept");
  ASSERT_TRUE(after.camera.has_value());
  EXPECT_EQ(after.camera->position, before.camera->position);
  EXPECT_EQ(document["buffers"][0]["uri"].get<std::string>().rfind("data:", 0), 0u);
}

TEST_F(GltfWrite, ReplacingAnAttributeReusesItsAccessor) {
  const std::filesystem::path input = writeSmallModel(scratch);
  const std::filesystem::path first = scratch / "first.glb", second = scratch / "second.glb";
  writeGltfWithAttributes(input, first, {{0, 1, "_AO", 1, {0.1f, 0.2f, 0.3f}}});
  writeGltfWithAttributes(first, second, {{0, 1, "_AO", 1, {0.7f, 0.8f, 0.9f}}});
  EXPECT_EQ(readDocument(second)["accessors"].size(), readDocument(first)["accessors"].size());
  EXPECT_EQ(readDocument(second)["bufferViews"].size(), readDocument(first)["bufferViews"].size());
  const GltfContents contents = loadGltf(second);
  EXPECT_EQ(contents.meshes.at(1).attributes.at("_AO").data, (std::vector<float>{0.7f, 0.8f, 0.9f}));
  // Writing over the input itself works too (the file is read before the rename).
  writeGltfWithAttributes(second, second, {{0, 1, "_AO", 1, {1.0f, 1.0f, 1.0f}}});
  EXPECT_EQ(loadGltf(second).meshes.at(1).attributes.at("_AO").data, (std::vector<float>{1.0f, 1.0f, 1.0f}));
}

TEST_F(GltfWrite, RejectsBadAttributes) {
  const std::filesystem::path input = writeSmallModel(scratch);
  const std::filesystem::path output = scratch / "out.glb";
  const std::string prefix = output.string() + ": ";
  EXPECT_EQ(writeError(input, output, {{0, 1, "AO", 1, {0, 0, 0}}}),
            prefix + "attribute name 'AO' must start with '_' (glTF custom attribute)");
  EXPECT_EQ(writeError(input, output, {{0, 1, "_AO", 5, std::vector<float>(15)}}),
            prefix + "attribute _AO: componentCount 5 is not in 1..4");
  EXPECT_EQ(writeError(input, output, {{0, 2, "_AO", 1, {0, 0, 0}}}),
            prefix + "attribute _AO: mesh 0 primitive 2 does not exist");
  EXPECT_EQ(writeError(input, output, {{0, 0, "_AO", 1, {0, 0, 0}}}),
            prefix + "attribute _AO has 3 values; mesh 0 primitive 0 needs 5 (5 vertices x 1 components)");
  EXPECT_EQ(writeError(input, output, {{0, 1, "_AO", 1, {0, std::numeric_limits<float>::quiet_NaN(), 0}}}),
            prefix + "attribute _AO: non-finite value at vertex 1 of mesh 0 primitive 1");
  EXPECT_EQ(writeError(input, scratch / "out.obj", {}),
            (scratch / "out.obj").string() + ": unknown glTF extension '.obj' (expected .gltf or .glb)");
  EXPECT_FALSE(std::filesystem::exists(output));
}

TEST_F(GltfWrite, UnwritableOutputLeavesNothingBehind) {
  const std::filesystem::path input = writeSmallModel(scratch);
  const std::filesystem::path output = scratch / "missing-folder" / "out.glb";
  EXPECT_NE(writeError(input, output, {}).find("cannot create"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(scratch / "missing-folder"));
}

TEST_F(GltfWrite, BadInputsNeverCrashTheWriter) {
  for (const auto& entry : std::filesystem::directory_iterator(test::dataDir() / "bad")) {
    const std::string extension = entry.path().extension().string();
    if (extension != ".gltf" && extension != ".glb") continue;
    const std::filesystem::path output = scratch / ("out" + extension);
    // The writer only needs a readable file; those it accepts must load back like the input.
    try {
      writeGltfWithAttributes(entry.path(), output, {});
    } catch (const Error&) {
      continue;
    }
    EXPECT_THROW(loadGltf(output), Error) << entry.path();
  }
}

}  // namespace
}  // namespace iblkit
