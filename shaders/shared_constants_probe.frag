#version 450 core
// Writes the generated shared_constants.glsl's values, one per texel, for tests
// (tests/gl/shared_constants_test.cpp compares them with the C++ constants they come from).

#include "shared_constants.glsl"

layout(location = 0) out vec4 fragColor;

const float kValues[] = float[](
    kShadingModeUnlit, kShadingModeMirror, kShadingModeSh, kShadingModeShAo, kShadingModeShAoBent, kShadingModePrt,
    kShadingModeFull, kShadingModeFullGltfAo, kShadingModeFullBothAo, kFrameLayerRadiance, kFrameLayerNormal, kFrameLayerDepth, kToneCurveClamp,
    kToneCurveAcesFitted, kToneCurveReinhard, kAttributePosition, kAttributeNormal, kAttributeAo,
    kAttributeBentNormal, kAttributeTransfer012, kAttributeTransfer345, kAttributeTransfer678,
    kTextureUnitLatLong, kTextureUnitSpecular, kTextureUnitBrdfLut, kTextureUnitPresent, kTextureUnitLive,
    kTextureUnitReference, kTextureUnitColorMap, kRelMseEpsilon, kAttributeTexcoord0, kAttributeTexcoord1,
    kAttributeTangent, kTextureUnitBaseColor, kTextureUnitMetallicRoughness, kTextureUnitNormal,
    kTextureUnitOcclusion, kTextureUnitEmissive, kSlotBaseColor, kSlotMetallicRoughness, kSlotNormal, kSlotOcclusion,
    kSlotEmissive, kAllTextureSlots, kAlphaModeOpaque, kAlphaModeMask, kAlphaModeBlend, kShadingModeIrradiance,
    kShadingModeIrradianceAoBent, kTextureUnitIrradiance, kShadingModeLights, kShadingModeLightsShadowed,
    kTextureUnitResidualSpecular, kTextureUnitShadowDepth, kMaxEngineLights,
    kShadowMapSize, kShadowExponent, kDeltaAlpha, kTextureUnitResidualIrradiance, kAttributeColor);

void main() {
  int i = int(gl_FragCoord.x);
  fragColor = vec4(i < kValues.length() ? kValues[i] : -1.0, 0.0, 0.0, 1.0);
}
