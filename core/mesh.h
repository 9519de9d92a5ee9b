#pragma once
// Mesh: one triangle list in world space, as every program consumes it after a scene is loaded
// (glTF node hierarchy flattened, strips and fans converted to lists). The vertices keep the order
// of the glTF primitive they came from (no welding, no reordering), so per-vertex results such
// as baked occlusion can be written back to that primitive (gltf_write.h).

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <limits>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace iblkit {

// Axis-aligned bounding box. A default-constructed box is empty (min > max) and absorbs any point.
struct Bounds {
  glm::vec3 min{std::numeric_limits<float>::infinity()};
  glm::vec3 max{-std::numeric_limits<float>::infinity()};

  bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
  void extend(const glm::vec3& point);
  void extend(const Bounds& other);
  // Centre of the box; the origin for an empty box.
  glm::vec3 center() const;
  // Radius of the bounding sphere around center(): half the diagonal; 0 for an empty box.
  float radius() const;
  // The eight corners, bit i of the index choosing max over min on axis i.
  std::array<glm::vec3, 8> corners() const;
};

// A custom per-vertex attribute (glTF attributes whose names start with '_'), componentCount
// floats per vertex, interleaved: data.size() == componentCount * vertexCount.
struct VertexAttribute {
  int componentCount = 1;  // 1..4 (glTF SCALAR, VEC2, VEC3, VEC4)
  std::vector<float> data;
};

// Where a mesh came from, for writing per-vertex data back. Indices are glTF indices in the file
// Scene::modelFiles[model]; a glTF mesh instanced by several nodes yields one Mesh per node, all
// with the same mesh/primitive. The ground of a .json scene has model == -1.
struct MeshSource {
  int model = 0;
  int node = -1;
  int mesh = -1;
  int primitive = -1;
};

struct Mesh {
  std::string name;
  std::vector<glm::vec3> positions;    // world space
  std::vector<glm::vec3> normals;      // world space, unit length, one per position
  std::vector<glm::vec2> texcoords;    // TEXCOORD_0; empty when the primitive has none
  std::vector<std::uint32_t> indices;  // triangle list, counter-clockwise = front face
  int material = 0;                    // index into Scene::materials
  bool isGround = false;
  std::map<std::string, VertexAttribute> attributes;  // custom '_' attributes, not transformed
  MeshSource source;

  std::size_t vertexCount() const { return positions.size(); }
  std::size_t triangleCount() const { return indices.size() / 3; }
  Bounds bounds() const;
};

// Angle-weighted vertex normals (G. Thürmer and C. A. Wüthrich, "Computing vertex normals from
// polygonal facets", Journal of Graphics Tools 3(1), 1998): each triangle adds its unit normal
// weighted by its interior angle at the vertex, which makes the result independent of how a
// surface is tessellated. Triangles are counter-clockwise; zero-area triangles contribute
// nothing. A vertex that no triangle contributes to gets +Y, so the result is always finite.
std::vector<glm::vec3> angleWeightedNormals(std::span<const glm::vec3> positions,
                                            std::span<const std::uint32_t> indices);

// Fills mesh.normals when empty, and replaces NaN, infinite or zero-length normals, with
// angle-weighted normals. Returns how many normals were generated or replaced.
std::size_t repairNormals(Mesh& mesh);

// Removes triangles whose area is exactly zero (repeated corners, collinear or coincident
// positions), which have no normal and cannot be hit. Vertices are kept, so the vertex order is
// unchanged. Returns how many triangles were removed.
std::size_t removeZeroAreaTriangles(Mesh& mesh);

// The largest coordinate (in metres, absolute) a scene's vertices may have: the ray tracer's
// offsets, distances and Embree's ray checks (origins below ~1.8e18) stay finite and meaningful
// well inside it. Loaders refuse a vertex beyond it (or NaN) naming the file, model and node.
inline constexpr float kMaxSceneCoordinate = 1e9f;

// The index of the first position that is NaN, infinite or beyond kMaxSceneCoordinate in any
// coordinate; -1 when there is none.
long long firstVertexOutOfRange(const Mesh& mesh);

// Applies an affine transform: positions by the matrix; normals by the cofactor matrix of its
// upper 3x3 (det(M) M^-T, which is defined even for singular M) times the sign of the
// determinant, i.e. along M^-T n, then re-normalised (zero normals stay zero for repairNormals to
// catch). A negative determinant mirrors the mesh, so the winding is flipped to keep
// counter-clockwise front faces.
void transformMesh(Mesh& mesh, const glm::mat4& transform);

}  // namespace iblkit
