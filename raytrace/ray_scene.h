#pragma once
// RayScene: ray queries against static triangle meshes with Embree 3, shared by the reference
// path tracer and the baker. Meshes are plain arrays (positions + triangle-list indices); each gets
// a geometry id (0, 1, 2, ... in the order added) that hits report, so the caller maps a hit back
// to its own mesh, material and vertex attributes. After commit(), intersect/occluded may be called
// from any number of threads at once.

#include <embree3/rtcore.h>

#include <cstdint>
#include <glm/glm.hpp>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/ray.h"
#include "raytrace/alpha_filter.h"

namespace iblkit {

// A shadow ray for RayScene::occluded's batch form: the segment origin + t direction, tmin <= t <=
// tmax, and its query.
struct OcclusionQuery {
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0.0f};
  float tmin = 0.0f;
  float tmax = std::numeric_limits<float>::infinity();
  RayQuery query;
};

// The closest intersection found by RayScene::intersect.
struct Hit {
  bool hit = false;  // false: nothing in [tmin, tmax]; the other fields keep these defaults
  float t = std::numeric_limits<float>::infinity();  // hit point = origin + t * direction
  unsigned geomId = RTC_INVALID_GEOMETRY_ID;         // id returned by addTriangleMesh
  unsigned primId = RTC_INVALID_GEOMETRY_ID;         // triangle index within that mesh
  // Embree's (u, v): the hit point is (1 - u - v) * v0 + u * v1 + v * v2 for the triangle's
  // corners in index order; interpolate vertex attributes with the same weights.
  glm::vec2 barycentrics{0.0f};
  // Unit normal of the triangle's plane in world space, as Embree reports it (not flipped towards
  // the ray): it is the right-hand normal cross(v1 - v0, v2 - v0), so it points towards a viewer
  // who sees the corners counter-clockwise (glTF's front face). dot(direction, geometricNormal) > 0
  // means the ray hit the back face.
  glm::vec3 geometricNormal{0.0f};
};

// A per-vertex attribute at a hit: Embree's barycentric weights (Hit::barycentrics) applied to the
// values of the triangle's three corners (`corner` points at its three indices). The one
// interpolation the tracer's shading and the alpha filter both use.
template <class T>
T interpolateAtHit(const std::vector<T>& values, const std::uint32_t* corner, glm::vec2 barycentrics) {
  const float u = barycentrics.x, v = barycentrics.y;
  return (1.0f - u - v) * values[corner[0]] + u * values[corner[1]] + v * values[corner[2]];
}

// Embree's intersect context extended by the query (Embree 3 passes the context pointer to filter
// callbacks unchanged, and documents embedding it first in a larger struct for this purpose): the
// filter callbacks of a RayScene with an AlphaFilter read the query through it, so a caller that
// calls Embree directly on embreeScene() (the replay benchmark) must pass &context of one of these.
struct RayQueryContext {
  RTCIntersectContext context;
  const RayQuery* query;
  // Set: `query` is an array, and a ray's query is query[its Embree ray id] (the packet queries
  // of RayScene::occluded, whose rays each carry their own cone). Unset: one query for every ray.
  bool perRay = false;
  explicit RayQueryContext(const RayQuery& rayQuery) : query(&rayQuery) { rtcInitIntersectContext(&context); }
};

class RayScene {
 public:
  struct Bounds {
    glm::vec3 lower{0.0f}, upper{0.0f};
  };

  // Creates the Embree device and an empty scene. `embreeConfig` is passed to rtcNewDevice
  // ("threads=2", "verbose=1", ...; empty for the defaults). Embree errors, here and in later calls,
  // throw Error("Embree: RTC_ERROR_...: <Embree's message>").
  explicit RayScene(const std::string& embreeConfig = "");
  // Move-only; a moved-from RayScene may only be destroyed or assigned to. (Member order does not
  // matter for release: an Embree scene holds a reference to its device.)
  RayScene(RayScene&&) noexcept = default;
  RayScene& operator=(RayScene&&) noexcept = default;
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;

  // Adds a triangle mesh (copied into Embree's buffers) and returns its geometry id. `indices` is a
  // triangle list; triangles with zero area are allowed (Embree never reports hits on them).
  // Throws Error("ray scene mesh <id>: ...") when there are no triangles, the index count is not a
  // multiple of 3, an index is out of range or a position is not finite. The scene must be
  // committed again before the next query.
  unsigned addTriangleMesh(std::span<const glm::vec3> positions, std::span<const uint32_t> indices);

  // Attaches `filter` (alpha_filter.h) to the geometries whose material needs a test (its
  // needs() bits): an intersect filter callback for alpha or back-face culling, an occluded one
  // for alpha, on the geometries added so far, whose ids the filter's geometry table must follow.
  // Others stay without callbacks. The scene keeps the filter alive; commit() again before the
  // next query. Throws Error("ray scene: ...") when the filter's table does not have one entry
  // per geometry.
  void setAlphaFilter(std::shared_ptr<const AlphaFilter> filter);

  // Builds the acceleration structure. Build quality HIGH (Embree's SAH builder with spatial
  // splits: slower to build, faster to trace, right for scenes built once and traced millions of
  // times). The scene is built with RTC_SCENE_FLAG_ROBUST: Embree then uses robust traversal and
  // avoids optimisations that lose arithmetic accuracy, the documented remedy for rays slipping
  // through the edge shared by neighbouring triangles (Embree's triangle test is still not exactly
  // watertight, but leaks become rare). In the reference such a leak sees the bright environment
  // through a closed object and shows as a firefly; the speed cost is in docs/benchmarks.md.
  void commit();

  // Closest hit along the ray with tmin <= t <= tmax (rtcIntersect1). Thread-safe after commit();
  // throws Error if the scene was changed and not committed.
  // `query` tells the alpha filter the ray's kind and cone (a default query: a secondary ray, the
  // finest texture level); without a filter it changes nothing.
  Hit intersect(const Ray& ray, float tmin, float tmax, const RayQuery& query = {}) const;

  // intersect() for each of `rays`, all with the same extent and query, into hits[i]: Embree's
  // 8-wide packet traversal (rtcIntersect8, flagged coherent), which pays for rays that start
  // together and travel together (one pixel's camera rays). The same hits as intersect() up to
  // the rounding of Embree's packet kernels. `hits` has the size of `rays`.
  void intersectCoherent(std::span<const Ray> rays, float tmin, float tmax, const RayQuery& query,
                         std::span<Hit> hits) const;

  // True if anything lies along origin + t * direction, tmin <= t <= tmax (rtcOccluded1, which
  // stops at the first hit found: cheaper than intersect for shadow and ambient-occlusion rays).
  // Thread-safe after commit(); throws Error if the scene was changed and not committed.
  bool occluded(glm::vec3 origin, glm::vec3 direction, float tmin, float tmax, const RayQuery& query = {}) const;

  // occluded() for each of `rays` into blocked[k] (1: something lies along it), in 8-wide packets
  // (rtcOccluded8), each ray with its own query. `blocked` has the size of `rays`.
  void occluded(std::span<const OcclusionQuery> rays, std::span<std::uint8_t> blocked) const;

  // The hit point recomputed from the triangle's corners and the barycentrics (trianglePoint,
  // ray_offset.h), which is more accurate than origin + t * direction (Wächter and Binder, Ray
  // Tracing Gems chapter 6): the point to pass to offsetRayOrigin. `hit` must be a hit of this scene.
  glm::vec3 surfacePoint(const Hit& hit) const { return surfacePosition(hit).point; }
  // surfacePoint(hit) with a bound on each coordinate's rounding (surfaceErrorBound,
  // ray_offset.h): the error to pass to offsetRayOrigin with that point.
  struct SurfacePosition {
    glm::vec3 point{0.0f}, error{0.0f};
  };
  SurfacePosition surfacePosition(const Hit& hit) const;

  // Axis-aligned box around every vertex added (zero box for an empty scene).
  Bounds bounds() const;
  // Length of the bounding box's diagonal: the scene's size, for scale-relative tolerances.
  float scale() const;
  // rayEpsilon (ray_offset.h) for this scene's largest absolute coordinate.
  float rayEpsilon() const;

  unsigned meshCount() const { return static_cast<unsigned>(meshes_.size()); }

  // The committed Embree scene, for queries this class does not wrap (ray packets and streams) and
  // for the raw-throughput benchmark; pass a RayQueryContext to every query on it.
  RTCScene embreeScene() const { return scene_.get(); }

 private:
  struct DeviceRelease {
    void operator()(RTCDevice device) const { rtcReleaseDevice(device); }
  };
  struct SceneRelease {
    void operator()(RTCScene scene) const { rtcReleaseScene(scene); }
  };
  // Where Embree's copies of a mesh live (owned by its RTCGeometry, which the scene keeps alive).
  struct MeshBuffers {
    const glm::vec3* positions;
    const uint32_t* indices;
  };
  void requireCommitted(const char* query) const;

  std::unique_ptr<RTCDeviceTy, DeviceRelease> device_;
  std::unique_ptr<RTCSceneTy, SceneRelease> scene_;
  // Embree traces 16-wide packets natively on this machine (AVX-512): the packet queries use them,
  // else 8-wide ones.
  bool nativePacket16_ = false;
  std::vector<MeshBuffers> meshes_;
  std::shared_ptr<const AlphaFilter> filter_;
  Bounds bounds_;
  bool committed_ = false;
};

}  // namespace iblkit
