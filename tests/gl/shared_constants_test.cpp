// The constants GLSL shares with C++ (the generated shared_constants.glsl, embed_shaders_tool.cpp):
// their values on the GPU equal the C++ ones, and the programs bind their attributes and samplers
// where the C++ side puts the data.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/brdf.h"
#include "core/image.h"
#include "core/material.h"
#include "core/relative_squared_error.h"
#include "core/tone_curve.h"
#include "engine/gl/frame_layer.h"
#include "engine/gl/gpu_mesh_attribute.h"
#include "engine/gl/light_constants.h"
#include "engine/gl/shader_program.h"
#include "engine/gl/shading_mode.h"
#include "engine/gl/texture_unit.h"
#include "gl/fragment_probe.h"

namespace iblkit {
namespace {

// In the order of shared_constants_probe.frag's table.
const std::vector<float> kCppValues = {
    float(ShadingMode::Unlit),    float(ShadingMode::Mirror),   float(ShadingMode::Sh),
    float(ShadingMode::ShAo),     float(ShadingMode::ShAoBent), float(ShadingMode::Prt),
    float(ShadingMode::Full),     float(ShadingMode::FullGltfAo), float(ShadingMode::FullBothAo),
    float(FrameLayer::Radiance),  float(FrameLayer::Normal),
    float(FrameLayer::Depth),     float(ToneCurve::Clamp),      float(ToneCurve::AcesFitted),
    float(ToneCurve::Reinhard),   float(kAttributePosition),    float(kAttributeNormal),
    float(kAttributeAo),          float(kAttributeBentNormal),  float(kAttributeTransfer012),
    float(kAttributeTransfer345), float(kAttributeTransfer678), float(kTextureUnitLatLong),
    float(kTextureUnitSpecular),  float(kTextureUnitBrdfLut),   float(kTextureUnitPresent),
    float(kTextureUnitLive),      float(kTextureUnitReference), float(kTextureUnitColorMap),
    float(kRelMseEpsilon),        float(kAttributeTexcoord0),   float(kAttributeTexcoord1),
    float(kAttributeTangent),     float(kTextureUnitBaseColor), float(kTextureUnitMetallicRoughness),
    float(kTextureUnitNormal),    float(kTextureUnitOcclusion), float(kTextureUnitEmissive),
    float(kSlotBaseColor),        float(kSlotMetallicRoughness), float(kSlotNormal),
    float(kSlotOcclusion),        float(kSlotEmissive),         float(kAllTextureSlots),
    float(AlphaMode::Opaque),     float(AlphaMode::Mask),       float(AlphaMode::Blend),
    float(ShadingMode::Irradiance), float(ShadingMode::IrradianceAoBent), float(kTextureUnitIrradiance),
    float(ShadingMode::Lights),   float(ShadingMode::LightsShadowed), float(kTextureUnitResidualSpecular),
    float(kTextureUnitShadowDepth), float(kMaxEngineLights),
    float(kShadowMapSize),        kShadowExponent,              kDeltaAlpha,
    float(kTextureUnitResidualIrradiance), float(kAttributeColor)};

TEST(SharedConstants, GlslValuesEqualTheCppOnes) {
  const int n = int(kCppValues.size()) + 1;  // one texel past the table: the probe's -1
  const Image unused(n, 1);
  const std::vector<glm::vec4> gpu =
      test::runFragmentProbe("shared_constants_probe.frag", {{"unused", &unused}});
  for (std::size_t i = 0; i < kCppValues.size(); ++i) EXPECT_EQ(gpu[i].r, kCppValues[i]) << "constant " << i;
  EXPECT_EQ(gpu.back().r, -1.0f) << "the probe has more constants than the test";
}

GLint attributeLocation(const ShaderProgram& program, const char* name) {
  return glGetAttribLocation(program.id(), name);
}

GLint samplerUnit(const ShaderProgram& program, const char* name) {
  const GLint location = glGetUniformLocation(program.id(), name);
  EXPECT_GE(location, 0) << name;
  GLint unit = -1;
  glGetUniformiv(program.id(), location, &unit);
  return unit;
}

TEST(SharedConstants, MeshAttributesAreAtTheGpuMeshLocations) {
  test::glContext();
  const ShaderProgram mesh("mesh.vert", "mesh.frag");
  EXPECT_EQ(attributeLocation(mesh, "inPosition"), GLint(kAttributePosition));
  EXPECT_EQ(attributeLocation(mesh, "inNormal"), GLint(kAttributeNormal));
  EXPECT_EQ(attributeLocation(mesh, "inAo"), GLint(kAttributeAo));
  EXPECT_EQ(attributeLocation(mesh, "inBentNormal"), GLint(kAttributeBentNormal));
  EXPECT_EQ(attributeLocation(mesh, "inTransfer012"), GLint(kAttributeTransfer012));
  EXPECT_EQ(attributeLocation(mesh, "inTransfer345"), GLint(kAttributeTransfer345));
  EXPECT_EQ(attributeLocation(mesh, "inTransfer678"), GLint(kAttributeTransfer678));
  // Texture coordinates and tangents are read by the textured variant (material.glsl's TEXTURED).
  const ShaderProgram textured("mesh.vert", "mesh.frag", "#define TEXTURED " + std::to_string(int(kAllTextureSlots)));
  EXPECT_EQ(attributeLocation(textured, "inTexcoord0"), GLint(kAttributeTexcoord0));
  EXPECT_EQ(attributeLocation(textured, "inTexcoord1"), GLint(kAttributeTexcoord1));
  EXPECT_EQ(attributeLocation(textured, "inTangent"), GLint(kAttributeTangent));
  // Vertex colours multiply the base colour in every variant.
  EXPECT_EQ(attributeLocation(mesh, "inColor"), GLint(kAttributeColor));
  checkGlErrors("attribute locations");
}

TEST(SharedConstants, SamplersReadTheTextureUnitsTheCppBinds) {
  test::glContext();
  // Samplers a mode does not read are compiled out: the lat-long map is the mirror mode's.
  const ShaderProgram mirror("mesh.vert", "mesh.frag",
                             "#define SHADING_MODE " + std::to_string(int(ShadingMode::Mirror)));
  EXPECT_EQ(samplerUnit(mirror, "latLongMap"), GLint(kTextureUnitLatLong));
  const ShaderProgram mesh("mesh.vert", "mesh.frag");
  EXPECT_EQ(samplerUnit(mesh, "specularCube"), GLint(kTextureUnitSpecular));
  EXPECT_EQ(samplerUnit(mesh, "brdfLut"), GLint(kTextureUnitBrdfLut));
  const ShaderProgram irradiance("mesh.vert", "mesh.frag",
                                 "#define SHADING_MODE " + std::to_string(int(ShadingMode::Irradiance)));
  EXPECT_EQ(samplerUnit(irradiance, "irradianceCube"), GLint(kTextureUnitIrradiance));
  // The material's slots are read in the textured variant (renderer.cpp's TEXTURED 1); the glTF
  // occlusion by the modes that use it.
  const ShaderProgram textured("mesh.vert", "mesh.frag",
                               "#define TEXTURED " + std::to_string(int(kAllTextureSlots)) + "\n#define SHADING_MODE " + std::to_string(int(ShadingMode::FullBothAo)));
  EXPECT_EQ(samplerUnit(textured, "baseColorTexture"), GLint(kTextureUnitBaseColor));
  EXPECT_EQ(samplerUnit(textured, "metallicRoughnessTexture"), GLint(kTextureUnitMetallicRoughness));
  EXPECT_EQ(samplerUnit(textured, "normalTexture"), GLint(kTextureUnitNormal));
  EXPECT_EQ(samplerUnit(textured, "occlusionTexture"), GLint(kTextureUnitOcclusion));
  EXPECT_EQ(samplerUnit(textured, "emissiveTexture"), GLint(kTextureUnitEmissive));
  // The lights modes' residual chain and shadow maps (lights-shadowed reads them all).
  const ShaderProgram shadowed("mesh.vert", "mesh.frag",
                               "#define SHADING_MODE " + std::to_string(int(ShadingMode::LightsShadowed)));
  EXPECT_EQ(samplerUnit(shadowed, "residualSpecularCube"), GLint(kTextureUnitResidualSpecular));
  EXPECT_EQ(samplerUnit(shadowed, "shadowMoments"), GLint(kTextureUnitShadowDepth));
  EXPECT_EQ(samplerUnit(shadowed, "residualTruncationCube"), GLint(kTextureUnitResidualIrradiance));
  const ShaderProgram sky("fullscreen.vert", "sky.frag");
  EXPECT_EQ(samplerUnit(sky, "latLongMap"), GLint(kTextureUnitLatLong));
  const ShaderProgram present("fullscreen.vert", "present.frag");
  EXPECT_EQ(samplerUnit(present, "radianceTexture"), GLint(kTextureUnitPresent));
  const ShaderProgram heatMap("fullscreen.vert", "difference_heatmap.frag");
  EXPECT_EQ(samplerUnit(heatMap, "liveTexture"), GLint(kTextureUnitLive));
  EXPECT_EQ(samplerUnit(heatMap, "referenceTexture"), GLint(kTextureUnitReference));
  EXPECT_EQ(samplerUnit(heatMap, "colorMap"), GLint(kTextureUnitColorMap));
  checkGlErrors("sampler units");
}

// The generated include is embedded with the stages that read it, under its own name.
TEST(SharedConstants, StagesIncludeTheGeneratedFile) {
  for (const char* stage :
       {"mesh.vert", "mesh.frag", "sky.frag", "present.frag", "difference_heatmap.frag"}) {
    const std::string source = expandedShaderSource(stage);
    EXPECT_NE(source.find("const int kShadingModeFull = " + std::to_string(int(ShadingMode::Full)) + ";"),
              std::string::npos)
        << stage;
  }
}

}  // namespace
}  // namespace iblkit
