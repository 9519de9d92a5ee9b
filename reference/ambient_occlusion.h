#pragma once
// The reference's per-point ambient-occlusion estimate: one cosine-weighted direction about the
// shading normal, traced from the point (offset off the surface with offsetRayOrigin on the side
// the ray leaves into) with rtcOccluded1 up to a maximum distance. The `ao` integrator averages it
// per pixel at the camera ray's hit; the baker's cross test (tests/baker/vertex_ao_reference_test)
// averages it at mesh vertices, so the two programs are checked against each other.

#include <glm/glm.hpp>

#include "raytrace/ray_scene.h"

namespace iblkit {

struct OcclusionSample {
  bool escaped = false;       // no geometry within the distance along the direction
  glm::vec3 direction{0.0f};  // the unit direction traced (world space)
};

// `geometricNormal` is the unit normal of the surface's plane (for the origin offset),
// `shadingNormal` the unit normal the hemisphere is about, `u` a point of [0,1)^2 (Malley's method
// with the concentric map, sampling.h), `maxDistance` > 0 (infinity: no limit). `positionError`:
// the position's error bound (a hit point's, RayScene::surfacePosition), for the offset by it;
// null for a point without one (a mesh vertex: the fixed offset of ray_offset.h).
OcclusionSample sampleAmbientOcclusion(const RayScene& rays, const glm::vec3& position, const glm::vec3* positionError,
                                       const glm::vec3& geometricNormal, const glm::vec3& shadingNormal,
                                       glm::vec2 u, float maxDistance);

}  // namespace iblkit
