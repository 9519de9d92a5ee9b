#pragma once
// Embree's single-ray queries called through its C API directly, without RayScene: the "raw"
// baseline of the ray benchmarks (embree_rays_bench, ao_bake_bench). Rays from tnear = 0 to
// infinity, every geometry mask.

#include <embree3/rtcore.h>

#include <limits>

#include "core/ray.h"

namespace iblkit {

inline bool rawOccluded(RTCScene scene, const Ray& ray) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay query{};
  query.org_x = ray.origin.x, query.org_y = ray.origin.y, query.org_z = ray.origin.z;
  query.dir_x = ray.direction.x, query.dir_y = ray.direction.y, query.dir_z = ray.direction.z;
  query.tnear = 0.0f;
  query.tfar = std::numeric_limits<float>::infinity();
  query.mask = ~0u;
  rtcOccluded1(scene, &context, &query);
  return query.tfar == -std::numeric_limits<float>::infinity();
}

inline bool rawIntersect(RTCScene scene, const Ray& ray) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit query{};
  query.ray.org_x = ray.origin.x, query.ray.org_y = ray.origin.y, query.ray.org_z = ray.origin.z;
  query.ray.dir_x = ray.direction.x, query.ray.dir_y = ray.direction.y, query.ray.dir_z = ray.direction.z;
  query.ray.tnear = 0.0f;
  query.ray.tfar = std::numeric_limits<float>::infinity();
  query.ray.mask = ~0u;
  query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene, &context, &query);
  return query.hit.geomID != RTC_INVALID_GEOMETRY_ID;
}

}  // namespace iblkit
