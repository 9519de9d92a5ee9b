#pragma once
// A mesh on the GPU: one vertex array with the attributes mesh.vert reads (position, normal and
// the baked _AO, _BENTNORMAL, _SHT0.._SHT2; TEXCOORD_0, TEXCOORD_1, TANGENT and COLOR_0 where the
// mesh has them), and its triangle indices.
#include <epoxy/gl.h>

#include <cstddef>
#include <span>
#include <vector>

#include "core/mesh.h"
#include "engine/gl/gpu_mesh_attribute.h"

namespace iblkit {

// Triangles first .. first + count - 1 of a mesh's index list.
struct TriangleRun {
  std::size_t first = 0, count = 0;
  bool operator==(const TriangleRun&) const = default;
};

class GpuMesh {
 public:
  // Uploads `mesh`, with `positions` in place of mesh.positions where given (one per vertex: the
  // renderer's render space, render_space.h); every baked attribute must be present
  // (readBakeFolder checks), else Error("<mesh name>: missing baked attribute <name>").
  explicit GpuMesh(const Mesh& mesh, std::span<const glm::vec3> positions = {});
  GpuMesh(GpuMesh&& other) noexcept;
  GpuMesh& operator=(GpuMesh&& other) noexcept;
  GpuMesh(const GpuMesh&) = delete;
  GpuMesh& operator=(const GpuMesh&) = delete;
  ~GpuMesh();

  // Whether some vertex colour's alpha is below 1 (Mesh::hasVertexAlpha, kept from the upload).
  bool hasVertexAlpha() const { return vertexAlpha_; }
  // Whether the mesh carries the baked suns' bounce (_SUNBOUNCE, kAttributeSunBounce).
  bool hasSunBounce() const { return hasSunBounce_; }

  // Draws the triangles with the currently bound program.
  void draw() const;
  // Draws only these runs of triangles (one glMultiDrawElements); none: nothing.
  void draw(const std::vector<TriangleRun>& runs) const;

 private:
  GLuint vertexArray_ = 0, buffer_ = 0;
  GLsizei indexCount_ = 0;
  GLintptr indexOffset_ = 0;
  bool hasColors_ = false;
  bool vertexAlpha_ = false;  // COLOR_0 uploaded; else the generic value (1, 1, 1, 1) at each draw
  bool hasSunBounce_ = false;
  void setGenericColor() const;
};

}  // namespace iblkit
