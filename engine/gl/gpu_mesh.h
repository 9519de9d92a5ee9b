#pragma once
// A mesh on the GPU: one vertex array with the attributes mesh.vert reads (position, normal and
// the baked _AO, _BENTNORMAL, _SHT0.._SHT2; TEXCOORD_0, TEXCOORD_1 and TANGENT where the mesh has
// them), and its triangle indices.
#include <epoxy/gl.h>

#include "core/mesh.h"
#include "engine/gl/gpu_mesh_attribute.h"

namespace iblkit {

class GpuMesh {
 public:
  // Uploads `mesh`; every baked attribute must be present (readBakeFolder checks), else
  // Error("<mesh name>: missing baked attribute <name>").
  explicit GpuMesh(const Mesh& mesh);
  GpuMesh(GpuMesh&& other) noexcept;
  GpuMesh& operator=(GpuMesh&& other) noexcept;
  GpuMesh(const GpuMesh&) = delete;
  GpuMesh& operator=(const GpuMesh&) = delete;
  ~GpuMesh();

  // Draws the triangles with the currently bound program.
  void draw() const;

 private:
  GLuint vertexArray_ = 0, buffer_ = 0;
  GLsizei indexCount_ = 0;
  GLintptr indexOffset_ = 0;
};

}  // namespace iblkit
