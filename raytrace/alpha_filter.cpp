#include "raytrace/alpha_filter.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "core/surface_material.h"
#include "raytrace/ray_scene.h"

namespace iblkit {

namespace {

// SplitMix64's finaliser (Steele, Lea and Flood 2014): every input bit affects every output bit.
std::uint64_t mixBits(std::uint64_t x) {
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

std::uint64_t mixIn(std::uint64_t h, float value) { return mixBits(h ^ std::bit_cast<std::uint32_t>(value)); }

}  // namespace

float textureFootprint(float width, float uvPerWorldArea, float cosine) {
  return textureFootprintFromLength(width, std::sqrt(uvPerWorldArea), cosine);
}

float textureFootprintFromLength(float width, float uvPerWorldLength, float cosine) {
  const float c = std::max(std::abs(cosine), 1.0f / kMaxTextureAnisotropy);
  return width * uvPerWorldLength / c;
}

UvGradient uvGradient(const Mesh& mesh, std::size_t triangle, int set) {
  const std::vector<glm::vec2>& uvs = set == 0 ? mesh.texcoords : mesh.texcoords1;
  if (uvs.size() != mesh.positions.size()) return {};
  const std::uint32_t* corner = &mesh.indices[3 * triangle];
  const glm::vec3 p0 = mesh.positions[corner[0]];
  const glm::vec3 e1 = mesh.positions[corner[1]] - p0, e2 = mesh.positions[corner[2]] - p0;
  const glm::vec2 a = uvs[corner[1]] - uvs[corner[0]], b = uvs[corner[2]] - uvs[corner[0]];
  // dP = beta1 e1 + beta2 e2 in the plane; the normal equations of the Gram matrix give
  // beta1 = w1 . dP and beta2 = w2 . dP, and uv changes by beta1 a + beta2 b.
  const float g11 = glm::dot(e1, e1), g12 = glm::dot(e1, e2), g22 = glm::dot(e2, e2);
  const float det = g11 * g22 - g12 * g12;
  if (!(det > 0.0f)) return {};
  const glm::vec3 w1 = (g22 * e1 - g12 * e2) / det, w2 = (g11 * e2 - g12 * e1) / det;
  const UvGradient gradient{w1 * a.x + w2 * b.x, w1 * a.y + w2 * b.y};
  const float check = glm::dot(gradient.du, gradient.du) + glm::dot(gradient.dv, gradient.dv);
  return std::isfinite(check) ? gradient : UvGradient{};
}

float textureFootprintFromDifferentials(const PixelDifferentials& pixel, const glm::vec3& direction, float t,
                                        const glm::vec3& geometricNormal, const UvGradient& gradient) {
  const float scale = t * glm::dot(direction, pixel.forward);
  const float dn = glm::dot(direction, geometricNormal);
  // The squared uv step; one sqrt of the larger (sqrt is monotone and correctly rounded, so
  // this is max(|step x|, |step y|) exactly).
  const auto uvStepSquared = [&](const glm::vec3& dd) {
    const glm::vec3 dp = scale * (dd - (glm::dot(dd, geometricNormal) / dn) * direction);
    const glm::vec2 step(glm::dot(gradient.du, dp), glm::dot(gradient.dv, dp));
    return glm::dot(step, step);
  };
  const float footprint = std::sqrt(std::max(uvStepSquared(pixel.dx), uvStepSquared(pixel.dy)));
  if (std::isfinite(footprint)) return footprint;
  return gradient.du == glm::vec3(0.0f) && gradient.dv == glm::vec3(0.0f) ? 0.0f
                                                                          : std::numeric_limits<float>::max();
}

float uvPerWorldArea(const Mesh& mesh, std::size_t triangle, int set) {
  const std::vector<glm::vec2>& uvs = set == 0 ? mesh.texcoords : mesh.texcoords1;
  if (uvs.size() != mesh.positions.size()) return 0.0f;
  const std::uint32_t* corner = &mesh.indices[3 * triangle];
  const glm::vec3 p0 = mesh.positions[corner[0]];
  const float world = glm::length(glm::cross(mesh.positions[corner[1]] - p0, mesh.positions[corner[2]] - p0));
  const glm::vec2 a = uvs[corner[1]] - uvs[corner[0]], b = uvs[corner[2]] - uvs[corner[0]];
  const float uv = std::abs(a.x * b.y - a.y * b.x);
  return world > 0.0f && std::isfinite(uv / world) ? uv / world : 0.0f;
}

AlphaFilter::AlphaFilter(std::vector<const Mesh*> geometryMeshes, const std::vector<Material>& materials,
                         std::shared_ptr<const SceneTextures> textures, unsigned slots, bool cameraRays)
    : textures_(std::move(textures)), slots_(slots) {
  if (!textures_) textures_ = std::make_shared<SceneTextures>();
  geometries_.resize(geometryMeshes.size());
  for (std::size_t g = 0; g < geometryMeshes.size(); ++g) {
    Geometry& geometry = geometries_[g];
    geometry.mesh = geometryMeshes[g];
    if (!geometry.mesh || geometry.mesh->material < 0 ||
        static_cast<std::size_t>(geometry.mesh->material) >= materials.size())
      continue;
    geometry.material = materials[static_cast<std::size_t>(geometry.mesh->material)];
    const Material& material = geometry.material;
    const TextureRef& base = material.baseColorTexture;
    // A texture whose alpha is 255 everywhere filters to exactly 1 (MipChain::alphaAllOne): the
    // factor alone decides, as without the texture (RGB images load with alpha 255).
    const MipChain* baseChain =
        textures_->empty() ? nullptr : textures_->chain(base.texture, ColorSpace::Srgb);
    geometry.alphaFromTexture =
        (slots & kSlotBaseColor) && base.present() && baseChain != nullptr && !baseChain->alphaAllOne;
    // A constant alpha decides once for the whole geometry: present everywhere needs no test.
    geometry.alphaFromVertices = geometry.mesh->colors.size() == geometry.mesh->positions.size() &&
                                 geometry.mesh->hasVertexAlpha();
    bool partial = geometry.alphaFromTexture || geometry.alphaFromVertices;
    if (material.alphaMode == AlphaMode::Mask) partial = partial || !(material.alpha >= material.alphaCutoff);
    if (material.alphaMode == AlphaMode::Blend) partial = partial || material.alpha < 1.0f;
    if (material.alphaMode != AlphaMode::Opaque && partial) geometry.needs |= kAlphaTest;
    if (!material.doubleSided && cameraRays) geometry.needs |= kCullCameraBackFaces;
  }
}

float AlphaFilter::coverageHash(const glm::vec3& origin, const glm::vec3& direction, unsigned geometry,
                                unsigned primitive) {
  std::uint64_t h = mixBits((std::uint64_t(geometry) << 32) | primitive);
  for (int i = 0; i < 3; ++i) h = mixIn(mixIn(h, origin[i]), direction[i]);
  return float(h >> 40) * 0x1p-24f;
}

bool AlphaFilter::accept(unsigned geometry, unsigned primitive, glm::vec2 barycentrics, float t,
                         const glm::vec3& origin, const glm::vec3& direction,
                         const glm::vec3& geometricNormal, const RayQuery& query) const {
  const Geometry& g = geometries_[geometry];
  if ((g.needs & kCullCameraBackFaces) && query.kind == RayKind::Camera &&
      glm::dot(direction, geometricNormal) > 0.0f)
    return false;
  if (!(g.needs & kAlphaTest)) return true;

  const Material& material = g.material;
  const Mesh& mesh = *g.mesh;
  const std::uint32_t* corner = &mesh.indices[3 * std::size_t(primitive)];
  // The vertex colour's alpha multiplies the base colour's (surfaceAlpha, in the same order).
  const float vertexAlpha = g.alphaFromVertices ? interpolateAtHit(mesh.colors, corner, barycentrics).a : 1.0f;
  float alpha = material.alpha * vertexAlpha;
  if (g.alphaFromTexture) {
    const TextureRef& ref = material.baseColorTexture;
    const std::vector<glm::vec2>& uvs = ref.texCoord == 1 ? mesh.texcoords1 : mesh.texcoords;
    SurfaceInputs inputs;
    inputs.slots = slots_;
    inputs.vertexColor.a = vertexAlpha;
    if (uvs.size() == mesh.positions.size())
      inputs.texcoords[ref.texCoord == 1 ? 1 : 0] = interpolateAtHit(uvs, corner, barycentrics);
    const float width = query.cone.widthAt(t * glm::length(direction));
    if (query.cone.pixel.present()) {
      const float length = glm::length(direction);
      const int set = ref.texCoord == 1 ? 1 : 0;
      inputs.footprintUv[set] = textureFootprintFromDifferentials(query.cone.pixel, direction / length, t * length,
                                                                  geometricNormal, uvGradient(mesh, primitive, set));
    } else if (width > 0.0f) {
      const float cosine = glm::dot(glm::normalize(direction), glm::normalize(geometricNormal));
      const int set = ref.texCoord == 1 ? 1 : 0;
      inputs.footprintUv[set] = textureFootprint(width, uvPerWorldArea(mesh, primitive, set), cosine);
    }
    alpha = surfaceAlpha(material, *textures_, inputs);
  }
  const float u = material.alphaMode == AlphaMode::Blend ? coverageHash(origin, direction, geometry, primitive)
                                                          : 0.0f;
  return surfacePresent(material, alpha, u);
}

}  // namespace iblkit
