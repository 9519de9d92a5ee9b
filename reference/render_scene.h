#pragma once
// RenderScene: a core Scene (every mesh, the ground included) made traceable. The meshes go into
// an Embree RayScene in scene order (meshes without triangles skipped), a table maps each
// geometry id back to its mesh, and a hit is turned into the shading data the integrators need.

#include <vector>

#include "core/brdf.h"
#include "core/material.h"
#include "core/scene.h"
#include "raytrace/ray_scene.h"

namespace iblkit {

// What an integrator needs to know about a hit point.
struct SurfacePoint {
  glm::vec3 position{0.0f};  // from the triangle's corners and barycentrics (for offsetRayOrigin)
  // Unit normal of the triangle's plane, flipped towards the side the ray came from (wo).
  glm::vec3 geometricNormal{0.0f};
  // Unit interpolated vertex normal, flipped to the same side as geometricNormal. Where it still
  // faces away from wo (silhouettes of coarse meshes, where interpolated and flat normals differ
  // most) it is replaced by geometricNormal, so the BRDF (which reflects nothing when wo is below
  // the shading normal) never turns a visible surface black.
  glm::vec3 shadingNormal{0.0f};
  const Material* material = nullptr;
  const BrdfLobes* lobes = nullptr;  // brdfLobes(*material), derived once per material
  bool isGround = false;
};

class RenderScene {
 public:
  // Takes the scene's meshes and materials. Meshes without triangles are skipped; missing or
  // broken normals are regenerated (repairNormals). Throws Error("<scene file>: mesh '<name>'
  // uses material N, but the scene has M") for a material index out of range.
  explicit RenderScene(Scene scene);

  const Scene& scene() const { return scene_; }
  const RayScene& rays() const { return rays_; }

  // The shading data at `hit` (a hit of rays()) seen from direction `wo` (unit, pointing away from
  // the surface, i.e. minus the ray direction).
  SurfacePoint surfacePoint(const Hit& hit, const glm::vec3& wo) const;

 private:
  Scene scene_;
  RayScene rays_;
  std::vector<unsigned> meshOfGeometry_;  // Embree geometry id -> index into scene_.meshes
  std::vector<BrdfLobes> lobes_;          // per material
};

}  // namespace iblkit
