#pragma once
// Limits of the engine's dominant lights (docs/dominant-lights.md, engine section), shared with the
// shaders through the generated shared_constants.glsl (embed_shaders_tool.cpp). No GL header: the
// build-time tool includes it.

namespace iblkit {

// The most disk lights mesh.frag draws (uniform arrays of this size, one shadow map layer each).
inline constexpr int kMaxEngineLights = 4;

// Side of each light's square shadow map, in texels (docs/engine.md "Shadows").
inline constexpr int kShadowMapSize = 1024;

// The exponent c of the shadow maps' exponential moments exp(c (d - 1)) (d the depth in [0, 1]):
// exp(-c) must stay a normal 32-bit float (c < 87); the larger c, the closer to a blocker a
// receiver may be before the filtered test leaks light (Annen et al. 2008, "Exponential Shadow
// Maps").
inline constexpr float kShadowExponent = 80.0f;

// A planar ground sets the maps' depth (engine/gl/shadow_maps.h, fitShadowFrame) where the light
// is further than this from its plane's edge-on direction (cosine to the ground's normal; 0.02:
// about 1.1 degrees above the horizon).
inline constexpr float kShadowGroundShearMinCos = 0.02f;

}  // namespace iblkit
