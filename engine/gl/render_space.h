#pragma once
// The engine's render space: world space moved by -origin, the origin a point of the scene (the
// centre of its objects' bounds), so that every position the GPU sees is relative to the scene.
// Vertex positions are floats: 36,000 units from the world's origin a float's step is 0.004, and
// a vertex shader that multiplies world positions by a view-projection matrix, or a fragment shader
// that takes dFdx of them, loses that much again in every product of large terms that cancel. The
// bunny placed 36,000 units out drew within FLIP 0.03 (`full`) and 0.05 (`lights-shadowed`) of the
// same bunny at the origin; the reference, whose ray origins carry their own error bounds
// (raytrace/ray_offset.h), does not move. In render space the positions are exact differences of
// nearby floats (rounded only where a coordinate is more than twice the origin's), and the
// camera's view matrix is built from its position relative to the origin in double
// (Camera::viewMatrix(origin)): the frame depends on the scene's size, not on where it stands
// (docs/engine.md "Render space"). Directions (normals, lights, the environment) do not change.
#include <glm/glm.hpp>

#include "core/mesh.h"
#include "core/scene.h"

namespace iblkit {

struct RenderSpace {
  glm::dvec3 origin{0.0};

  // The centre of the scene's objects' bounds (every mesh's where it has no object; the world's
  // origin for an empty scene), rounded to float.
  static RenderSpace of(const Scene& scene);

  glm::vec3 fromWorld(const glm::vec3& world) const { return glm::vec3(glm::dvec3(world) - origin); }
  // The mesh's positions in render space, its triangles and whether it is the ground (no other
  // attribute): what the renderer uploads as positions and fits the shadow maps to.
  Mesh shape(const Mesh& mesh) const;
};

}  // namespace iblkit
