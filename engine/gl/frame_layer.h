#pragma once
// What a frame writes into the colour target (FrameSettings::layer). The shaders read the ids
// through the generated shared_constants.glsl (embed_shaders_tool.cpp), so this enum is their one
// source.

namespace iblkit {

enum class FrameLayer {
  Radiance,  // linear radiance; alpha = 1 on non-ground objects, 0 on the ground and the sky
  Normal,    // world shading normal turned towards the viewer (iblkit-trace --normal); 0 on the sky
  Depth,     // distance from the camera position along the ray (iblkit-trace --depth); 0 on the sky
};

}  // namespace iblkit
