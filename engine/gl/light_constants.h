#pragma once
// Limits of the engine's dominant lights (docs/dominant-lights.md, engine section), shared with the
// shaders through the generated shared_constants.glsl (embed_shaders_tool.cpp). No GL header: the
// build-time tool includes it.

namespace iblkit {

// The most disk lights mesh.frag draws (uniform arrays of this size, one shadow map layer each).
inline constexpr int kMaxEngineLights = 4;

// Side of each light's square shadow map, in texels (docs/engine.md "Shadows").
inline constexpr int kShadowMapSize = 2048;

// Taps of the shadow lookups (shaders/shadow.glsl): PCSS's blocker search and its PCF.
inline constexpr int kBlockerSearchTaps = 6;
inline constexpr int kPcfTaps = 8;

}  // namespace iblkit
