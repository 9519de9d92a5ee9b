#include "reference/ground_visibility.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "core/low_discrepancy.h"
#include "raytrace/ray_offset.h"

namespace iblkit {

GroundVisibility::GroundVisibility(const GroundOcclusion& ground, const RayScene& rays,
                                   const EnvironmentSampler& sampler) {
  const float radius = ground.objectsRadius();
  if (!(radius > 0.0f)) return;
  const glm::vec3& center = ground.objectsCenter();
  const float half = kExtent * radius;
  origin_ = {center.x - half, center.z - half};
  spacing_ = 2.0f * half / float(kNodes - 1);
  values_.assign(std::size_t(kNodes) * kNodes, 1.0f);
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  const int bucket = sampler.bucketOf(up);
  // The light samples and their weights, the same at every node.
  struct Probe {
    glm::vec3 direction;
    float weight;
  };
  std::vector<Probe> probes;
  for (int k = 0; k < kProbes; ++k) {
    const EnvironmentSampler::Sample s = sampler.sample(bucket, hammersley(std::uint32_t(k), std::uint32_t(kProbes)));
    if (!(s.pdf > 0.0f && s.direction.y > 0.0f)) continue;
    const float weight = (s.radiance.r + s.radiance.g + s.radiance.b) * s.direction.y / s.pdf;
    if (weight > 0.0f && std::isfinite(weight)) probes.push_back({s.direction, weight});
  }
  if (probes.empty()) return;
  tbb::parallel_for(tbb::blocked_range<int>(0, kNodes), [&](const tbb::blocked_range<int>& range) {
    std::vector<OcclusionQuery> queries;
    std::vector<float> weights;
    std::vector<std::uint8_t> blocked;
    for (int j = range.begin(); j != range.end(); ++j)
      for (int i = 0; i < kNodes; ++i) {
        const glm::vec3 point(origin_.x + spacing_ * float(i), ground.groundHeight(), origin_.y + spacing_ * float(j));
        const glm::vec3 start = offsetRayOrigin(point, up);
        const GroundOcclusion::Cone cone = ground.coneAt(start);
        double visible = 0.0, total = 0.0;
        queries.clear();
        weights.clear();
        for (const Probe& probe : probes) {
          total += probe.weight;
          if (cone.contains(probe.direction)) {
            queries.push_back({start, probe.direction, 0.0f, std::numeric_limits<float>::infinity(), RayQuery{}});
            weights.push_back(probe.weight);
          } else {
            visible += probe.weight;
          }
        }
        blocked.assign(queries.size(), 0);
        if (!queries.empty()) rays.occluded(queries, blocked);
        for (std::size_t k = 0; k < queries.size(); ++k)
          if (!blocked[k]) visible += weights[k];
        values_[std::size_t(j) * kNodes + std::size_t(i)] = float(std::clamp(visible / total, 0.0, 1.0));
      }
  });
}

float GroundVisibility::at(const glm::vec3& x) const {
  if (values_.empty()) return 1.0f;
  const float u = (x.x - origin_.x) / spacing_, v = (x.z - origin_.y) / spacing_;
  const float last = float(kNodes - 1);
  if (!(u >= 0.0f && u <= last && v >= 0.0f && v <= last)) return 1.0f;
  const int i = std::min(int(u), kNodes - 2), j = std::min(int(v), kNodes - 2);
  const float fu = u - float(i), fv = v - float(j);
  const float bottom = glm::mix(node(i, j), node(i + 1, j), fu), top = glm::mix(node(i, j + 1), node(i + 1, j + 1), fu);
  return glm::mix(bottom, top, fv);
}

}  // namespace iblkit
