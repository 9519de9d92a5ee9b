#include "baker/visibility_attributes.h"

#include <string>

#include "core/error.h"

namespace iblkit {

namespace {

constexpr const char* kSubject = "vertex visibility attributes";

}  // namespace

void attachVisibilityAttributes(std::vector<Mesh>& meshes, const std::vector<MeshVisibility>& visibility) {
  if (meshes.size() != visibility.size())
    fail(kSubject,
         std::to_string(visibility.size()) + " results for " + std::to_string(meshes.size()) + " meshes");
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    Mesh& mesh = meshes[m];
    const MeshVisibility& v = visibility[m];
    const std::size_t n = mesh.vertexCount();
    if (v.ambientOcclusion.size() != n || v.bentNormals.size() != n || v.bentNormalLengths.size() != n ||
        v.transfer.size() != n)
      fail(kSubject, "mesh " + std::to_string(m) + " has " + std::to_string(n) +
                         " vertices but its results have a different count");
    VertexAttribute bent{3, std::vector<float>(3 * n)};
    VertexAttribute transfer[3] = {
        {3, std::vector<float>(3 * n)}, {3, std::vector<float>(3 * n)}, {3, std::vector<float>(3 * n)}};
    for (std::size_t i = 0; i < n; ++i) {
      for (int c = 0; c < 3; ++c) bent.data[3 * i + c] = v.bentNormals[i][c];
      for (int k = 0; k < kShCoefficients; ++k) transfer[k / 3].data[3 * i + k % 3] = v.transfer[i][k];
    }
    mesh.attributes[kAmbientOcclusionAttribute] = {1, v.ambientOcclusion};
    mesh.attributes[kBentNormalAttribute] = std::move(bent);
    mesh.attributes[kBentLengthAttribute] = {1, v.bentNormalLengths};
    for (int a = 0; a < 3; ++a) mesh.attributes[kTransferAttributes[a]] = std::move(transfer[a]);
  }
}

std::vector<glm::vec3> sunBounceDirections(const EnvironmentLights& lights) {
  std::vector<glm::vec3> directions;
  for (const EnvironmentLight& sun : lights.suns)
    if (directions.size() < std::size_t(kMaxSunBounceLights)) directions.push_back(sun.direction);
  return directions;
}

void attachSunBounceAttribute(std::vector<Mesh>& meshes, const std::vector<std::vector<glm::vec4>>& bounce) {
  if (meshes.size() != bounce.size())
    fail(kSubject, std::to_string(bounce.size()) + " sun bounce results for " + std::to_string(meshes.size()) +
                       " meshes");
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const std::size_t n = meshes[m].vertexCount();
    if (bounce[m].size() != n)
      fail(kSubject, "mesh " + std::to_string(m) + " has " + std::to_string(n) +
                         " vertices but its sun bounce has " + std::to_string(bounce[m].size()));
    VertexAttribute attribute{4, std::vector<float>(4 * n)};
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < 4; ++c) attribute.data[4 * i + std::size_t(c)] = bounce[m][i][c];
    meshes[m].attributes[kSunBounceAttribute] = std::move(attribute);
  }
}

void attachSunBounce(std::vector<Mesh>& meshes, const EnvironmentLights& lights, VisibilitySettings settings,
                     VisibilityStatistics* statistics) {
  if (lights.suns.empty()) return;
  settings.progress = nullptr;
  attachSunBounceAttribute(meshes, bakeSunBounce(meshes, sunBounceDirections(lights), settings, statistics));
}

}  // namespace iblkit
