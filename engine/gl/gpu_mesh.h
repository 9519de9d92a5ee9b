#pragma once
// A mesh on the GPU: one vertex array with the attributes mesh.vert reads (position, normal and
// the baked _AO, _BENTNORMAL, _SHT0.._SHT2), and its triangle indices.
#include <epoxy/gl.h>

#include "core/mesh.h"

namespace iblkit {

// Attribute locations of shaders/mesh.vert.
enum GpuMeshAttribute : GLuint {
  kAttributePosition = 0,
  kAttributeNormal = 1,
  kAttributeAo = 2,
  kAttributeBentNormal = 3,
  kAttributeTransfer012 = 4,
  kAttributeTransfer345 = 5,
  kAttributeTransfer678 = 6,
};

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
