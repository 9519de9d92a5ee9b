#include "core/tangent_frames.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <vector>

#include "core/frame.h"

namespace iblkit {

namespace {

// MikkTSpace (Mikkelsen 2008, section 4.2) identifies vertices by their attribute values, not
// their indices: corners whose position, normal and uv are bit-identical are one vertex even when
// the file repeats it. This key is those eight floats.
struct VertexKey {
  std::uint32_t bits[8];
  bool operator==(const VertexKey& other) const { return std::memcmp(bits, other.bits, sizeof bits) == 0; }
};
struct VertexKeyHash {
  std::size_t operator()(const VertexKey& key) const {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the words
    for (std::uint32_t word : key.bits) h = (h ^ word) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

glm::vec3 projectOntoPlane(const glm::vec3& v, const glm::vec3& n) { return v - n * glm::dot(n, v); }

bool normalizeInPlace(glm::vec3& v) {
  const float length = glm::length(v);
  if (!(length > 0.0f) || !std::isfinite(length)) return false;
  v /= length;
  return true;
}

// Per welded vertex, the two handedness groups: angle-weighted sums of the corners' tangents.
struct Accumulator {
  glm::vec3 tangent[2]{glm::vec3(0.0f), glm::vec3(0.0f)};  // [0]: w = +1, [1]: w = -1
  float angle[2]{0.0f, 0.0f};
};

}  // namespace

std::size_t generateTangents(Mesh& mesh, int texCoord) {
  const std::size_t count = mesh.positions.size();
  if (!mesh.tangents.empty()) return 0;
  const std::vector<glm::vec2>& uvs = texCoord == 1 ? mesh.texcoords1 : mesh.texcoords;
  if (count == 0 || uvs.size() != count || mesh.normals.size() != count) return 0;

  std::vector<std::uint32_t> representative(count);
  {
    std::unordered_map<VertexKey, std::uint32_t, VertexKeyHash> first;
    first.reserve(count);
    for (std::size_t v = 0; v < count; ++v) {
      VertexKey key;
      const float values[8] = {mesh.positions[v].x, mesh.positions[v].y, mesh.positions[v].z, mesh.normals[v].x,
                               mesh.normals[v].y,   mesh.normals[v].z,   uvs[v].x,            uvs[v].y};
      for (int i = 0; i < 8; ++i) key.bits[i] = std::bit_cast<std::uint32_t>(values[i]);
      representative[v] = first.emplace(key, static_cast<std::uint32_t>(v)).first->second;
    }
  }

  std::vector<Accumulator> sums(count);
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t corner[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
    if (corner[0] >= count || corner[1] >= count || corner[2] >= count) continue;
    const glm::vec3 dp1 = mesh.positions[corner[1]] - mesh.positions[corner[0]];
    const glm::vec3 dp2 = mesh.positions[corner[2]] - mesh.positions[corner[0]];
    const glm::vec2 duv1 = uvs[corner[1]] - uvs[corner[0]];
    const glm::vec2 duv2 = uvs[corner[2]] - uvs[corner[0]];
    // Twice the signed uv area; the triangle's dp/du is (dp1 dv2 - dp2 dv1) / det (thesis eq. 4.1).
    const float det = duv1.x * duv2.y - duv2.x * duv1.y;
    if (!(std::abs(det) > 0.0f) || !std::isfinite(det)) continue;  // degenerate uvs: no contribution
    glm::vec3 dpdu = (dp1 * duv2.y - dp2 * duv1.y) * (det > 0.0f ? 1.0f : -1.0f);
    if (!normalizeInPlace(dpdu)) continue;
    // Handedness. MikkTSpace's sign is +1 for a positive uv area with v pointing up the image (GL);
    // glTF's v points down the image (uv (0, 0) is its top-left), so glTF's +1 is a negative area
    // in glTF uvs: the bitangent w cross(n, t) then points up the image, the +Y of glTF's normal
    // textures (section 3.9.3; three.js negates MikkTSpace's sign for glTF for this reason).
    const int group = det < 0.0f ? 0 : 1;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = corner[k];
      const glm::vec3& n = mesh.normals[v];
      glm::vec3 tangent = projectOntoPlane(dpdu, n);
      if (!normalizeInPlace(tangent)) continue;
      // The corner's angle between its two edges projected onto the normal's plane (as MikkTSpace).
      glm::vec3 toNext = projectOntoPlane(mesh.positions[corner[(k + 1) % 3]] - mesh.positions[v], n);
      glm::vec3 toPrevious = projectOntoPlane(mesh.positions[corner[(k + 2) % 3]] - mesh.positions[v], n);
      if (!normalizeInPlace(toNext) || !normalizeInPlace(toPrevious)) continue;
      const float angle = std::acos(std::clamp(glm::dot(toNext, toPrevious), -1.0f, 1.0f));
      Accumulator& sum = sums[representative[v]];
      sum.tangent[group] += angle * tangent;
      sum.angle[group] += angle;
    }
  }

  mesh.tangents.resize(count);
  for (std::size_t v = 0; v < count; ++v) {
    const Accumulator& sum = sums[representative[v]];
    const int group = sum.angle[0] >= sum.angle[1] ? 0 : 1;
    const glm::vec3& n = mesh.normals[v];
    glm::vec3 tangent = projectOntoPlane(sum.tangent[group], n);
    if (sum.angle[group] > 0.0f && normalizeInPlace(tangent)) {
      mesh.tangents[v] = glm::vec4(tangent, group == 0 ? 1.0f : -1.0f);
    } else {
      glm::vec3 unitNormal = n;
      if (!normalizeInPlace(unitNormal)) unitNormal = glm::vec3(0.0f, 0.0f, 1.0f);
      mesh.tangents[v] = glm::vec4(Frame::fromZ(unitNormal).x, 1.0f);
    }
  }
  return count;
}

}  // namespace iblkit
