#pragma once
// RenderScene: a core Scene (every mesh, the ground included) made traceable. The meshes go into
// an Embree RayScene in scene order (meshes without triangles skipped), a table maps each
// geometry id back to its mesh, and a hit is turned into the shading data the integrators need:
// the material with its textures read at the hit (core evaluateSurfaceMaterial), the perturbed
// normal, the BRDF lobes. The alpha and doubleSided rules are the RayScene's AlphaFilter
// (raytrace/alpha_filter.h), attached here; docs/reference-tracer.md "Textures and alpha".

#include <array>
#include <memory>
#include <vector>

#include "core/brdf.h"
#include "core/material.h"
#include "core/scene.h"
#include "core/surface_material.h"
#include "core/texture_sampling.h"
#include "raytrace/alpha_filter.h"
#include "raytrace/ray_scene.h"

namespace iblkit {

// What an integrator needs to know about a hit point.
struct SurfacePoint {
  glm::vec3 position{0.0f};  // from the triangle's corners and barycentrics (for offsetRayOrigin)
  glm::vec3 positionError{0.0f};  // a bound on its rounding (RayScene::surfacePosition)
  // Unit normal of the triangle's plane, flipped towards the side the ray came from (wo).
  glm::vec3 geometricNormal{0.0f};
  // Unit interpolated vertex normal, flipped to the same side as geometricNormal. Where it still
  // faces away from wo or nearly (silhouettes of coarse meshes, where interpolated and flat normals
  // differ most) it is turned towards wo until it faces it by kMinShadingCosine
  // (shadingNormalFacingViewer, core/surface_material.h), so the BRDF (which reflects nothing when
  // wo is below the shading normal) never turns a visible surface black.
  // With a normal texture it is the perturbed normal (evaluateSurfaceMaterial about the
  // interpolated normal and tangent turned to wo's side), under the same rule. The glTF occlusion
  // texture is not applied: the tracer traces the visibility it approximates.
  glm::vec3 shadingNormal{0.0f};
  const Material* material = nullptr;  // the scene's material (factors and texture slots)
  // The material at this point: factors times the textures read here (the factors themselves for
  // an untextured material), and its lobes (brdfLobes of it; cached per untextured material).
  glm::vec3 baseColor{0.0f};
  glm::vec3 emissive{0.0f};
  BrdfLobes lobes;
  bool isGround = false;
};

class RenderScene {
 public:
  // Takes the scene's meshes and materials. Meshes without triangles are skipped; missing or
  // broken normals are regenerated (repairNormals), missing tangents of a normal-mapped mesh
  // generated (generateTangents). Throws Error("<scene file>: mesh '<name>' uses material N, but
  // the scene has M") for a material index out of range. `textureSlots`: the slots read
  // (TextureSlot bits; 0 traces the constant factors, iblkit-trace --no-textures).
  explicit RenderScene(Scene scene, unsigned textureSlots = kAllTextureSlots);

  const Scene& scene() const { return scene_; }
  const RayScene& rays() const { return rays_; }

  const SceneTextures& textures() const { return *textures_; }
  unsigned textureSlots() const { return slots_; }

  // The shading data at `hit` (a hit of rays()) seen from direction `wo` (unit, pointing away from
  // the surface, i.e. minus the ray direction). `cone` is the ray's footprint: a camera ray's
  // differentials set the texture level (textureFootprintFromDifferentials in alpha_filter.h),
  // else its width at hit.t (textureFootprint); the default reads the finest level.
  SurfacePoint surfacePoint(const Hit& hit, const glm::vec3& wo, const RayCone& cone = {}) const;

 private:
  Scene scene_;
  RayScene rays_;
  std::vector<unsigned> meshOfGeometry_;  // Embree geometry id -> index into scene_.meshes
  std::vector<BrdfLobes> lobes_;          // per material
  std::vector<bool> textured_;            // per material: a shading slot (not occlusion) reads a texture
  std::vector<bool> colored_;             // per mesh: it has vertex colours (Mesh::colors)
  // Per material (textured ones, and those of meshes with vertex colours): its slots prepared
  // against textures_ for surfacePoint.
  std::vector<PreparedSurfaceMaterial> prepared_;
  // Per mesh (empty for meshes whose material reads no texture), per triangle:
  // sqrt(uvPerWorldArea) of uv sets 0 and 1, the ray-cone footprint's per-triangle part
  // (textureFootprintFromLength), computed once rather than from the corners at every hit.
  std::vector<std::vector<glm::vec2>> uvPerWorldLength_;
  // Per mesh and uv set (empty for the same meshes, and for a set the mesh lacks), uvGradient of
  // each triangle, for camera rays' footprints (textureFootprintFromDifferentials).
  std::vector<std::array<std::vector<UvGradient>, 2>> uvGradients_;
  std::shared_ptr<const SceneTextures> textures_;
  unsigned slots_ = kAllTextureSlots;
};

}  // namespace iblkit
