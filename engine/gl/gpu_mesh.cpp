#include "engine/gl/gpu_mesh.h"

#include <cstring>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "bakefile/vertex_attributes.h"
#include "core/error.h"

namespace iblkit {
namespace {

struct Stream {
  GLuint location;
  int components;
  std::span<const float> data;
};

// The mesh's attribute `name` with `components` floats per vertex; nullptr when it has none such.
const VertexAttribute* findBakedAttribute(const Mesh& mesh, const char* name, int components) {
  const auto found = mesh.attributes.find(name);
  if (found == mesh.attributes.end() || found->second.componentCount != components ||
      found->second.data.size() != std::size_t(components) * mesh.vertexCount())
    return nullptr;
  return &found->second;
}

std::span<const float> bakedAttribute(const Mesh& mesh, const char* name, int components) {
  const VertexAttribute* attribute = findBakedAttribute(mesh, name, components);
  if (!attribute) fail(mesh.name, std::string("missing baked attribute ") + name);
  return attribute->data;
}

}  // namespace

GpuMesh::GpuMesh(const Mesh& mesh, std::span<const glm::vec3> positions) : indexCount_(GLsizei(mesh.indices.size())) {
  const std::size_t n = mesh.vertexCount();
  if (positions.empty()) positions = mesh.positions;
  if (positions.size() != n)
    fail(mesh.name, std::to_string(positions.size()) + " positions given for " + std::to_string(n) + " vertices");
  std::vector<Stream> streams = {
      {kAttributePosition, 3, {reinterpret_cast<const float*>(positions.data()), 3 * n}},
      {kAttributeNormal, 3, {reinterpret_cast<const float*>(mesh.normals.data()), 3 * n}},
      {kAttributeAo, 1, bakedAttribute(mesh, kAmbientOcclusionAttribute, 1)},
      {kAttributeBentNormal, 3, bakedAttribute(mesh, kBentNormalAttribute, 3)},
      {kAttributeTransfer012, 3, bakedAttribute(mesh, kTransferAttributes[0], 3)},
      {kAttributeTransfer345, 3, bakedAttribute(mesh, kTransferAttributes[1], 3)},
      {kAttributeTransfer678, 3, bakedAttribute(mesh, kTransferAttributes[2], 3)},
  };
  // The texture coordinates and tangents the mesh has; an absent one stays a disabled attribute.
  auto optional = [&](GLuint location, int components, const auto& values) {
    if (values.size() == n)
      streams.push_back({location, components, {reinterpret_cast<const float*>(values.data()), std::size_t(components) * n}});
  };
  optional(kAttributeTexcoord0, 2, mesh.texcoords);
  optional(kAttributeTexcoord1, 2, mesh.texcoords1);
  optional(kAttributeTangent, 4, mesh.tangents);
  optional(kAttributeColor, 4, mesh.colors);
  // The suns' bounce is optional (bakes of maps with suns only).
  const VertexAttribute* sunBounce = findBakedAttribute(mesh, kSunBounceAttribute, 4);
  hasSunBounce_ = sunBounce != nullptr;
  if (sunBounce) streams.push_back({kAttributeSunBounce, 4, sunBounce->data});
  hasColors_ = mesh.colors.size() == n;
  vertexAlpha_ = hasColors_ && mesh.hasVertexAlpha();
  // One buffer: each attribute's array in turn (4-byte aligned), then the indices.
  std::size_t bytes = 0;
  for (const Stream& stream : streams) bytes += stream.data.size_bytes();
  indexOffset_ = GLintptr(bytes);
  bytes += mesh.indices.size() * sizeof(std::uint32_t);
  std::vector<std::byte> contents(bytes);
  std::vector<std::size_t> offsets;
  std::size_t offset = 0;
  for (const Stream& stream : streams) {
    std::memcpy(contents.data() + offset, stream.data.data(), stream.data.size_bytes());
    offsets.push_back(offset);
    offset += stream.data.size_bytes();
  }
  std::memcpy(contents.data() + offset, mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t));
  glCreateBuffers(1, &buffer_);
  glNamedBufferStorage(buffer_, GLsizeiptr(bytes), contents.data(), 0);
  // One binding point per attribute (numbered as its location), each reading its own array.
  glCreateVertexArrays(1, &vertexArray_);
  for (std::size_t i = 0; i < streams.size(); ++i) {
    const Stream& stream = streams[i];
    glEnableVertexArrayAttrib(vertexArray_, stream.location);
    glVertexArrayAttribFormat(vertexArray_, stream.location, stream.components, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vertexArray_, stream.location, stream.location);
    glVertexArrayVertexBuffer(vertexArray_, stream.location, buffer_, GLintptr(offsets[i]),
                              GLsizei(stream.components * sizeof(float)));
  }
  glVertexArrayElementBuffer(vertexArray_, buffer_);
}

GpuMesh::GpuMesh(GpuMesh&& other) noexcept
    : vertexArray_(std::exchange(other.vertexArray_, 0)),
      buffer_(std::exchange(other.buffer_, 0)),
      indexCount_(other.indexCount_),
      indexOffset_(other.indexOffset_),
      hasColors_(other.hasColors_),
      vertexAlpha_(other.vertexAlpha_),
      hasSunBounce_(other.hasSunBounce_) {}

GpuMesh& GpuMesh::operator=(GpuMesh&& other) noexcept {
  std::swap(vertexArray_, other.vertexArray_);
  std::swap(buffer_, other.buffer_);
  std::swap(indexCount_, other.indexCount_);
  std::swap(indexOffset_, other.indexOffset_);
  std::swap(hasColors_, other.hasColors_);
  std::swap(vertexAlpha_, other.vertexAlpha_);
  std::swap(hasSunBounce_, other.hasSunBounce_);
  return *this;
}

GpuMesh::~GpuMesh() {
  if (vertexArray_) glDeleteVertexArrays(1, &vertexArray_);
  if (buffer_) glDeleteBuffers(1, &buffer_);
}

// A disabled attribute reads the context's generic value, which other draws may have changed: a
// mesh without colours sets white, opaque, before each draw.
void GpuMesh::setGenericColor() const {
  if (!hasColors_) glVertexAttrib4f(kAttributeColor, 1.0f, 1.0f, 1.0f, 1.0f);
}

void GpuMesh::draw() const {
  setGenericColor();
  glBindVertexArray(vertexArray_);
  glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, reinterpret_cast<const void*>(indexOffset_));
  glBindVertexArray(0);
}

void GpuMesh::draw(const std::vector<TriangleRun>& runs) const {
  if (runs.empty()) return;
  std::vector<GLsizei> counts;
  std::vector<const void*> offsets;
  for (const TriangleRun& run : runs) {
    counts.push_back(GLsizei(3 * run.count));
    offsets.push_back(reinterpret_cast<const void*>(indexOffset_ + GLintptr(3 * run.first * sizeof(GLuint))));
  }
  setGenericColor();
  glBindVertexArray(vertexArray_);
  glMultiDrawElements(GL_TRIANGLES, counts.data(), GL_UNSIGNED_INT, offsets.data(), GLsizei(runs.size()));
  glBindVertexArray(0);
}

}  // namespace iblkit
