#pragma once
// RayRecorder: a log of the rays an integrator traces (closest-hit and shadow queries, with their
// extents), for replaying them through bare Embree calls in a benchmark (bench/tracer_rays_bench.cpp)
// and so measuring how much of a render is ray tracing and how much is everything else.
//
// Off by default: an Integrator records only when given a recorder (Integrator::recordRays), and
// then only pays a pointer test per ray when it has none. Recording is thread-safe: each TBB
// worker appends to its own list, so it does not serialise the render; rays() concatenates the
// lists (each in the order its thread traced them).

#include <tbb/enumerable_thread_specific.h>

#include <cstddef>
#include <glm/glm.hpp>
#include <vector>

#include "raytrace/alpha_filter.h"

namespace iblkit {

struct RecordedRay {
  glm::vec3 origin{0.0f};
  float tmin = 0.0f;
  glm::vec3 direction{0.0f};
  float tmax = 0.0f;
  bool occlusion = false;  // true: a shadow query (RayScene::occluded); false: closest hit (intersect)
  RayQuery query;          // what the alpha filter was told (the ray's kind and cone)
};

class RayRecorder {
 public:
  void record(const RecordedRay& ray) { perThread_.local().push_back(ray); }

  // Every ray recorded so far, thread by thread.
  std::vector<RecordedRay> rays() const;
  std::size_t size() const;
  void clear();

 private:
  tbb::enumerable_thread_specific<std::vector<RecordedRay>> perThread_;
};

}  // namespace iblkit
