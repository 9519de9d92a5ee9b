#include "bakefile/vertex_attributes.h"

#include <sstream>
#include <string>
#include <utility>

#include "core/error.h"

namespace iblkit {

ShBasis9 transferFromAttributes(const Mesh& mesh, std::size_t vertex) {
  ShBasis9 t{};
  for (int a = 0; a < 3; ++a) {
    const auto found = mesh.attributes.find(kTransferAttributes[a]);
    if (found == mesh.attributes.end())
      fail("vertex visibility attributes", std::string("mesh '") + mesh.name + "' has no " + kTransferAttributes[a]);
    const VertexAttribute& attribute = found->second;
    if (attribute.componentCount != 3 || attribute.data.size() < 3 * (vertex + 1))
      fail("vertex visibility attributes", std::string(kTransferAttributes[a]) + " of mesh '" + mesh.name +
                         "' is not VEC3 or has no vertex " + std::to_string(vertex));
    for (int c = 0; c < 3; ++c) t[3 * a + c] = attribute.data[3 * vertex + c];
  }
  return t;
}

void requireBakedAttributes(const Scene& scene, const std::filesystem::path& file) {
  const std::pair<const char*, int> expected[] = {
      {kAmbientOcclusionAttribute, 1}, {kBentNormalAttribute, 3},   {kBentLengthAttribute, 1},
      {kTransferAttributes[0], 3},     {kTransferAttributes[1], 3}, {kTransferAttributes[2], 3}};
  for (const Mesh& mesh : scene.meshes)
    for (const auto& [name, components] : expected) {
      const auto found = mesh.attributes.find(name);
      if (found == mesh.attributes.end() || found->second.componentCount != components ||
          found->second.data.size() != std::size_t(components) * mesh.vertexCount())
        fail(file,
             "mesh '" + mesh.name + "' has no baked " + name + " attribute (not an iblkit-bake scene?)");
    }
  for (const Mesh& mesh : scene.meshes) {
    const auto found = mesh.attributes.find(kSunBounceAttribute);
    if (found == mesh.attributes.end()) continue;
    const std::string what = "mesh '" + mesh.name + "': " + kSunBounceAttribute;
    if (found->second.componentCount != 4 || found->second.data.size() != 4 * mesh.vertexCount())
      fail(file, what + " is not four values per vertex");
    for (const float value : found->second.data)
      if (!(value >= 0.0f && value <= kMaxSunBounceValue)) {
        std::ostringstream message;
        message << what << " holds " << value << ", outside [0, " << kMaxSunBounceValue << "]";
        fail(file, message.str());
      }
  }
}

}  // namespace iblkit
