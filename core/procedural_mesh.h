#pragma once
// Procedural triangle meshes (UV sphere, ground plane, box) for tests and benchmarks of the path
// tracer and the baker: analytic shapes whose areas, volumes and visibility are known in closed
// form. Y is up. Triangles are listed counter-clockwise seen from outside, so the right-hand
// geometric normal cross(v1 - v0, v2 - v0) points out of the shape, the same side as the vertex
// normals.

#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "core/mesh.h"

namespace iblkit {

struct ProceduralMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  // unit length, one per position
  std::vector<uint32_t> indices;   // triangle list, three per triangle
};

// Sphere tessellated along latitude and longitude. `rings` latitude bands (>= 2) between the poles
// at center +- radius * Y, `segments` longitude slices (>= 3). Each pole is one vertex, so no
// triangle is degenerate: 2 + (rings - 1) * segments vertices and 2 * segments * (rings - 1)
// triangles. Normals are the exact sphere normals (position - center) / radius.
ProceduralMesh uvSphere(glm::vec3 center, float radius, int rings, int segments);

// Square of side `size` in the plane y = center.y, centred on `center`, facing up (+Y): 4
// vertices, 2 triangles.
ProceduralMesh plane(glm::vec3 center, float size);

// The same square cut into cells x cells squares of two triangles each (cells >= 1), for
// per-vertex tests that need vertices inside the square: (cells + 1)^2 vertices, row by row from
// -Z to +Z, each row from -X to +X.
ProceduralMesh gridPlane(glm::vec3 center, float size, int cells);

// Axis-aligned box with edge lengths `size`, centred on `center`. Each face has its own 4
// vertices so the normals are the flat face normals: 24 vertices, 12 triangles.
ProceduralMesh box(glm::vec3 center, glm::vec3 size);

// The shape as a scene mesh (positions, normals, indices; no texture coordinates) called `name`
// with material index `material`.
Mesh toMesh(const ProceduralMesh& shape, const std::string& name, int material = 0);

}  // namespace iblkit
