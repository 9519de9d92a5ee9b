#include "reference/ambient_occlusion.h"

#include "core/frame.h"
#include "core/sampling.h"
#include "raytrace/ray_offset.h"

namespace iblkit {

OcclusionSample sampleAmbientOcclusion(const RayScene& rays, const glm::vec3& position, const glm::vec3* positionError,
                                       const glm::vec3& geometricNormal, const glm::vec3& shadingNormal,
                                       glm::vec2 u, float maxDistance) {
  OcclusionSample sample;
  sample.direction = Frame::fromZ(shadingNormal).toWorld(sampleCosineHemisphere(u));
  // The side of the surface the ray leaves into.
  const glm::vec3 side =
      glm::dot(sample.direction, geometricNormal) > 0.0f ? geometricNormal : -geometricNormal;
  const glm::vec3 origin = positionError ? offsetRayOrigin(position, *positionError, side) : offsetRayOrigin(position, side);
  sample.escaped = !rays.occluded(origin, sample.direction, 0.0f, maxDistance);
  return sample;
}

}  // namespace iblkit
