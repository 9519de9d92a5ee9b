#include "core/procedural_mesh.h"

#include <cmath>
#include <glm/gtc/constants.hpp>
#include <sstream>
#include <string>
#include <utility>

#include "core/error.h"

namespace iblkit {

namespace {

void requireFinite(const char* shape, const char* what, glm::vec3 v) {
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
    fail(shape, std::string(what) + " is not finite");
}

void requirePositive(const char* shape, const char* what, float value) {
  if (value > 0.0f && std::isfinite(value)) return;
  std::ostringstream message;
  message << what << " must be positive and finite (got " << value << ")";
  fail(shape, message.str());
}

}  // namespace

ProceduralMesh uvSphere(glm::vec3 center, float radius, int rings, int segments) {
  requireFinite("uvSphere", "center", center);
  requirePositive("uvSphere", "radius", radius);
  if (rings < 2) fail("uvSphere", "rings must be at least 2 (got " + std::to_string(rings) + ")");
  if (segments < 3) fail("uvSphere", "segments must be at least 3 (got " + std::to_string(segments) + ")");

  // Direction at polar angle theta (from +Y) and azimuth phi. The sign of z makes
  // cross(d/dtheta, d/dphi) point outward, so (ring i, ring i + 1, next segment) is counter-clockwise
  // seen from outside.
  const auto direction = [](float theta, float phi) {
    return glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
  };
  ProceduralMesh mesh;
  const auto addVertex = [&](glm::vec3 d) {
    mesh.positions.push_back(center + radius * d);
    mesh.normals.push_back(d);
  };
  addVertex(glm::vec3(0.0f, 1.0f, 0.0f));
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < segments; ++j)
      addVertex(direction(glm::pi<float>() * float(i) / float(rings),
                          glm::two_pi<float>() * float(j) / float(segments)));
  addVertex(glm::vec3(0.0f, -1.0f, 0.0f));

  const uint32_t north = 0, south = static_cast<uint32_t>(mesh.positions.size() - 1);
  // Vertex of ring i (1 .. rings - 1) and segment j (wrapping around).
  const auto ringVertex = [&](int i, int j) {
    return static_cast<uint32_t>(1 + (i - 1) * segments + j % segments);
  };
  const auto addTriangle = [&](uint32_t a, uint32_t b, uint32_t c) {
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
  };
  for (int j = 0; j < segments; ++j) {
    addTriangle(north, ringVertex(1, j), ringVertex(1, j + 1));
    for (int i = 1; i + 1 < rings; ++i) {
      addTriangle(ringVertex(i, j), ringVertex(i + 1, j), ringVertex(i, j + 1));
      addTriangle(ringVertex(i, j + 1), ringVertex(i + 1, j), ringVertex(i + 1, j + 1));
    }
    addTriangle(ringVertex(rings - 1, j), south, ringVertex(rings - 1, j + 1));
  }
  return mesh;
}

ProceduralMesh plane(glm::vec3 center, float size) {
  requireFinite("plane", "center", center);
  requirePositive("plane", "size", size);
  const float h = 0.5f * size;
  ProceduralMesh mesh;
  mesh.positions = {center + glm::vec3(-h, 0.0f, h), center + glm::vec3(h, 0.0f, h),
                    center + glm::vec3(h, 0.0f, -h), center + glm::vec3(-h, 0.0f, -h)};
  mesh.normals.assign(4, glm::vec3(0.0f, 1.0f, 0.0f));
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

ProceduralMesh gridPlane(glm::vec3 center, float size, int cells) {
  requireFinite("gridPlane", "center", center);
  requirePositive("gridPlane", "size", size);
  if (cells < 1) fail("gridPlane", "cells must be >= 1");
  const float h = 0.5f * size, step = size / static_cast<float>(cells);
  ProceduralMesh mesh;
  for (int i = 0; i <= cells; ++i)
    for (int j = 0; j <= cells; ++j)
      mesh.positions.push_back(
          center + glm::vec3(-h + step * static_cast<float>(j), 0.0f, -h + step * static_cast<float>(i)));
  mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0f, 1.0f, 0.0f));
  const auto vertex = [cells](int i, int j) { return static_cast<uint32_t>(i * (cells + 1) + j); };
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j)  // counter-clockwise seen from +Y (x right, z towards the viewer)
      mesh.indices.insert(mesh.indices.end(), {vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1),
                                               vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1)});
  return mesh;
}

ProceduralMesh box(glm::vec3 center, glm::vec3 size) {
  requireFinite("box", "center", center);
  requirePositive("box", "size.x", size.x);
  requirePositive("box", "size.y", size.y);
  requirePositive("box", "size.z", size.z);
  const glm::vec3 half = 0.5f * size;
  ProceduralMesh mesh;
  for (int axis = 0; axis < 3; ++axis) {
    for (float sign : {1.0f, -1.0f}) {
      // Tangents t, b with cross(t, b) = n: the cyclic successors of the axis, swapped on the
      // negative face. The quad (-t-b, t-b, t+b, -t+b) is then counter-clockwise seen along -n.
      glm::vec3 n(0.0f), t(0.0f), b(0.0f);
      n[axis] = sign;
      t[(axis + 1) % 3] = 1.0f;
      b[(axis + 2) % 3] = 1.0f;
      if (sign < 0.0f) std::swap(t, b);
      const auto base = static_cast<uint32_t>(mesh.positions.size());
      for (glm::vec2 corner : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
        mesh.positions.push_back(center + half * (n + corner.x * t + corner.y * b));
        mesh.normals.push_back(n);
      }
      mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
  }
  return mesh;
}

Mesh toMesh(const ProceduralMesh& shape, const std::string& name, int material) {
  Mesh mesh;
  mesh.name = name;
  mesh.positions = shape.positions;
  mesh.normals = shape.normals;
  mesh.indices = shape.indices;
  mesh.material = material;
  return mesh;
}

}  // namespace iblkit
