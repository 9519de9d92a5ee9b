#pragma once
// Which candidate hits of a ray count: the glTF alpha mode and doubleSided rule of every ray the
// reference tracer and the baker trace, tested in Embree filter callbacks (RayScene::setAlphaFilter)
// so that closest-hit and occlusion queries agree. The rules (docs/reference-tracer.md, "Alpha and
// faces"; docs/material-model.md "Alpha"):
// - MASK: a candidate is there where surfaceAlpha >= alphaCutoff, for every kind of ray.
// - BLEND: alpha is coverage. A candidate is kept when u < alpha, u in [0, 1) a hash of the ray
//   (origin and direction bits) and of the triangle (geometry and primitive id): the same ray
//   decides the same way in intersect and occluded, the result is deterministic, and rays of
//   different samples see independent u, so the expected transmission is 1 - alpha (pbrt-v4
//   tests alpha with HashFloat(ray.o, ray.d) the same way; the ids decorrelate stacked layers).
// - doubleSided false: camera rays (RayKind::Camera) pass through back faces, as the raster culls
//   them; every other ray (bounces, shadow, AO, the baker's) hits both faces, so a closed
//   single-sided mesh still blocks light from the inside.
// Only geometries whose material needs a test get a callback (needs()), so opaque double-sided
// scenes trace at full speed.

#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "core/material.h"
#include "core/mesh.h"
#include "core/texture_sampling.h"

namespace iblkit {

enum class RayKind : std::uint8_t {
  Camera,     // primary rays: single-sided back faces are culled
  Secondary,  // everything else
};

// A ray's footprint as a cone (Akenine-Möller et al. 2019, "Texture Level of Detail Strategies
// for Real-Time Ray Tracing", Ray Tracing Gems ch. 20): its width at distance t along the unit
// direction is width + spread * t. Zero: the sharpest texture level.
// A camera ray also carries its differentials (Igehy 1999, "Tracing Ray Differentials",
// SIGGRAPH): how the pinhole camera's unnormalised direction d = forward + x right + y up
// (core/camera.h, PrimaryRays) changes per footprint step along the image's x and y, from which
// the first hit's footprint is the raster's own (textureFootprintFromDifferentials). A bounce drops
// them (the integrator), and the cone alone follows the rest of the path.
struct PixelDifferentials {
  glm::vec3 forward{0.0f};  // the camera's unit view direction (d . forward = 1); zero: none
  glm::vec3 dx{0.0f}, dy{0.0f};
  bool present() const { return forward != glm::vec3(0.0f); }
};

struct RayCone {
  float width = 0.0f;
  float spread = 0.0f;  // radians (small-angle: the width grows by spread per unit distance)
  PixelDifferentials pixel;
  float widthAt(float t) const { return width + spread * t; }
};

// What a query tells the filters about its ray (carried in Embree's intersect context).
struct RayQuery {
  RayKind kind = RayKind::Secondary;
  RayCone cone;
};

// The largest anisotropy the isotropic lookups stand in for (the raster's
// GL_TEXTURE_MAX_ANISOTROPY, 16 where the driver offers it): see textureFootprint.
inline constexpr float kMaxTextureAnisotropy = 16.0f;

// The uv footprint (width in uv units) of a cone `width` wide hitting a triangle whose uv area per
// world area is `uvPerWorldArea`, at cosine `cosine` between the ray and the triangle's normal:
// width * sqrt(uvPerWorldArea) / max(|cosine|, 1 / kMaxTextureAnisotropy). Akenine-Möller et al.
// divide by the cosine (the footprint's major axis); GL's anisotropic filtering picks the level of
// max(major / maxAnisotropy, minor) and averages along the major axis, and a tracer that
// supersamples the pixel averages along it too, so the cosine is clamped where GL's anisotropy is.
float textureFootprint(float width, float uvPerWorldArea, float cosine);

// textureFootprint with sqrt(uvPerWorldArea) given (`uvPerWorldLength`): a caller that keeps it
// per triangle (RenderScene) skips the sqrt and the triangle's corners per hit. Same arithmetic,
// so the same value as textureFootprint(width, uvPerWorldLength^2 as computed, cosine).
float textureFootprintFromLength(float width, float uvPerWorldLength, float cosine);

// The world-space gradients of texCoord set `set` over triangle `triangle` of `mesh`: along a step
// dP in the triangle's plane, u changes by du . dP and v by dv . dP. Zero when the mesh has no such
// set or the triangle no area.
struct UvGradient {
  glm::vec3 du{0.0f}, dv{0.0f};
};
UvGradient uvGradient(const Mesh& mesh, std::size_t triangle, int set);

// The uv footprint of a camera ray with differentials `pixel` (present()) that hits a triangle at
// distance `t` along its unit `direction`, `geometricNormal` the triangle's normal (any length,
// either side), `gradient` its uvGradient: max(|duv/dx|, |duv/dy|), the change of the uv per
// footprint step along the image's axes. That is the level of detail OpenGL's isotropic filtering
// takes (OpenGL 4.5 section 8.14.1, eq. 8.7, rho = max of the two derivatives' lengths in texels:
// the same for a square texture; for a w x h one, textureLod's sqrt(w h) stands in for the axes'
// sizes). The hit point moves by dP = t (D . forward) (d' - (d' . n) / (D . n) D) (Igehy 1999,
// section 3.1.2, for the unit direction D = d / |d|, |d| = 1 / (D . forward)), and uv by the
// gradient along dP. 0 for a zero gradient; the largest float when the ray grazes the triangle's
// plane (the coarsest level).
float textureFootprintFromDifferentials(const PixelDifferentials& pixel, const glm::vec3& direction, float t,
                                        const glm::vec3& geometricNormal, const UvGradient& gradient);

// The ratio uv area / world area of triangle `triangle` of `mesh` in texCoord set `set` (0 when
// the mesh has no such set or the triangle no area), for textureFootprint.
float uvPerWorldArea(const Mesh& mesh, std::size_t triangle, int set);

class AlphaFilter {
 public:
  enum Need : unsigned {
    kNoTest = 0,
    kAlphaTest = 1u << 0,        // MASK or BLEND with a non-constant or partial alpha
    kCullCameraBackFaces = 1u << 1,  // single-sided, and camera rays are traced
  };

  // `geometryMeshes[g]` is the mesh of Embree geometry id g; `materials` is what Mesh::material
  // indexes; `textures` holds the scene's textures (may be empty: then alpha is the factor's).
  // `slots`: the texture slots switched on (only kSlotBaseColor matters here). `cameraRays`:
  // whether RayKind::Camera queries will be traced (the baker traces none, so single-sided
  // geometry then needs no callback). The meshes must outlive the filter; materials are copied.
  AlphaFilter(std::vector<const Mesh*> geometryMeshes, const std::vector<Material>& materials,
              std::shared_ptr<const SceneTextures> textures, unsigned slots = kAllTextureSlots,
              bool cameraRays = true);

  unsigned geometryCount() const { return static_cast<unsigned>(geometries_.size()); }
  // The Need bits of geometry g.
  unsigned needs(unsigned geometry) const { return geometries_[geometry].needs; }

  // Whether the candidate hit of a ray (origin, unit-or-not direction) on triangle `primitive` of
  // `geometry` at Embree barycentrics (u, v) and distance t counts; `geometricNormal` is Embree's
  // Ng (any length). The callbacks call this; so may anything that wants the same answer.
  bool accept(unsigned geometry, unsigned primitive, glm::vec2 barycentrics, float t, const glm::vec3& origin,
              const glm::vec3& direction, const glm::vec3& geometricNormal, const RayQuery& query) const;

  // The coverage hash u in [0, 1) of a ray and a triangle (the BLEND test keeps u < alpha).
  static float coverageHash(const glm::vec3& origin, const glm::vec3& direction, unsigned geometry,
                            unsigned primitive);

 private:
  struct Geometry {
    const Mesh* mesh = nullptr;
    Material material;
    unsigned needs = kNoTest;
    bool alphaFromTexture = false;
    bool alphaFromVertices = false;  // its vertex colours' alpha is below 1 somewhere (Mesh::hasVertexAlpha)
  };
  std::vector<Geometry> geometries_;
  std::shared_ptr<const SceneTextures> textures_;
  unsigned slots_;
};

}  // namespace iblkit
