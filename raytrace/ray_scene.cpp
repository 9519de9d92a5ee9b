#include "raytrace/ray_scene.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <type_traits>

#include "core/error.h"
#include "raytrace/ray_offset.h"

namespace iblkit {

namespace {

static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "Embree's FLOAT3 vertex buffer is read as glm::vec3");

const char* errorName(RTCError code) {
  switch (code) {
    case RTC_ERROR_NONE:
      return "RTC_ERROR_NONE";
    case RTC_ERROR_UNKNOWN:
      return "RTC_ERROR_UNKNOWN";
    case RTC_ERROR_INVALID_ARGUMENT:
      return "RTC_ERROR_INVALID_ARGUMENT";
    case RTC_ERROR_INVALID_OPERATION:
      return "RTC_ERROR_INVALID_OPERATION";
    case RTC_ERROR_OUT_OF_MEMORY:
      return "RTC_ERROR_OUT_OF_MEMORY";
    case RTC_ERROR_UNSUPPORTED_CPU:
      return "RTC_ERROR_UNSUPPORTED_CPU";
    case RTC_ERROR_CANCELLED:
      return "RTC_ERROR_CANCELLED";
  }
  return "RTC_ERROR_?";
}

// Embree reports errors through a C callback, on the thread that made the failing API call.
// Throwing from inside Embree's C interface would unwind through its frames, so the callback only
// records the first message of the current call, and checkEmbree() throws it once the call has
// returned. Thread-local, so concurrent scenes on other threads do not mix their errors.
thread_local std::string tEmbreeError;

void recordEmbreeError(void*, RTCError code, const char* message) {
  if (tEmbreeError.empty()) tEmbreeError = std::string(errorName(code)) + ": " + (message ? message : "");
}

void clearEmbreeError() { tEmbreeError.clear(); }

void checkEmbree() {
  if (tEmbreeError.empty()) return;
  const std::string message = std::move(tEmbreeError);
  tEmbreeError.clear();
  fail("Embree", message);
}

static_assert(offsetof(RayQueryContext, context) == 0);

// The filter callback of intersect and occluded queries alike: reject (valid = 0) the candidates
// the AlphaFilter says are not there. Embree passes N candidates (1 for rtcIntersect1).
void filterCandidates(const RTCFilterFunctionNArguments* args) {
  const auto* filter = static_cast<const AlphaFilter*>(args->geometryUserPtr);
  const auto* context = reinterpret_cast<const RayQueryContext*>(args->context);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    RTCRayN* ray = args->ray;
    RTCHitN* hit = args->hit;
    const unsigned n = args->N;
    const RayQuery& query = context->perRay ? context->query[RTCRayN_id(ray, n, i)] : *context->query;
    const glm::vec3 origin(RTCRayN_org_x(ray, n, i), RTCRayN_org_y(ray, n, i), RTCRayN_org_z(ray, n, i));
    const glm::vec3 direction(RTCRayN_dir_x(ray, n, i), RTCRayN_dir_y(ray, n, i), RTCRayN_dir_z(ray, n, i));
    const glm::vec3 ng(RTCHitN_Ng_x(hit, n, i), RTCHitN_Ng_y(hit, n, i), RTCHitN_Ng_z(hit, n, i));
    // During a filter call the ray's tfar holds the candidate's distance.
    if (!filter->accept(RTCHitN_geomID(hit, n, i), RTCHitN_primID(hit, n, i),
                        glm::vec2(RTCHitN_u(hit, n, i), RTCHitN_v(hit, n, i)), RTCRayN_tfar(ray, n, i), origin,
                        direction, ng, query))
      args->valid[i] = 0;
  }
}

// A Hit from Embree's answer (geomId RTC_INVALID_GEOMETRY_ID: none).
Hit hitFrom(unsigned geomId, unsigned primId, float t, float u, float v, const glm::vec3& ng) {
  Hit hit;
  if (geomId == RTC_INVALID_GEOMETRY_ID) return hit;
  hit.hit = true;
  hit.t = t;
  hit.geomId = geomId;
  hit.primId = primId;
  hit.barycentrics = glm::vec2(u, v);
  // Embree's Ng is unnormalised (its length is twice the triangle's area, scaled by Embree's
  // internal precision). Dividing by the largest component first keeps the tiny Ng of a minute
  // triangle from underflowing when squared in the normalisation.
  const float largest = std::max({std::abs(ng.x), std::abs(ng.y), std::abs(ng.z)});
  hit.geometricNormal = glm::normalize(ng / largest);
  return hit;
}

struct GeometryRelease {
  void operator()(RTCGeometry geometry) const { rtcReleaseGeometry(geometry); }
};

}  // namespace

RayScene::RayScene(const std::string& embreeConfig) {
  device_.reset(rtcNewDevice(embreeConfig.empty() ? nullptr : embreeConfig.c_str()));
  // The callback is not installed yet: the only information about a failed creation is the code.
  if (!device_)
    fail("Embree", std::string(errorName(rtcGetDeviceError(nullptr))) +
                       ": cannot create a device with config \"" + embreeConfig + "\"");
  rtcSetDeviceErrorFunction(device_.get(), recordEmbreeError, nullptr);
  clearEmbreeError();
  scene_.reset(rtcNewScene(device_.get()));
  checkEmbree();
  nativePacket16_ = rtcGetDeviceProperty(device_.get(), RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED) != 0;
  rtcSetSceneBuildQuality(scene_.get(), RTC_BUILD_QUALITY_HIGH);
  rtcSetSceneFlags(scene_.get(), RTC_SCENE_FLAG_ROBUST);
  checkEmbree();
}

unsigned RayScene::addTriangleMesh(std::span<const glm::vec3> positions, std::span<const uint32_t> indices) {
  const auto id = static_cast<unsigned>(meshes_.size());
  const std::string subject = "ray scene mesh " + std::to_string(id);
  if (indices.empty()) fail(subject, "has no triangles");
  if (indices.size() % 3 != 0)
    fail(subject, std::to_string(indices.size()) + " indices do not make whole triangles");
  for (std::size_t i = 0; i < positions.size(); ++i)
    if (!std::isfinite(positions[i].x) || !std::isfinite(positions[i].y) || !std::isfinite(positions[i].z))
      fail(subject, "vertex " + std::to_string(i) + " has a non-finite position");
  for (std::size_t i = 0; i < indices.size(); ++i)
    if (indices[i] >= positions.size())
      fail(subject, "triangle " + std::to_string(i / 3) + " uses vertex " + std::to_string(indices[i]) +
                        " but the mesh has " + std::to_string(positions.size()) + " vertices");

  clearEmbreeError();
  const std::unique_ptr<RTCGeometryTy, GeometryRelease> geometry(
      rtcNewGeometry(device_.get(), RTC_GEOMETRY_TYPE_TRIANGLE));
  checkEmbree();
  // rtcSetNewGeometryBuffer pads the vertex buffer so Embree's 16-byte loads of the last vertex
  // stay inside it, which a caller's array would not guarantee: hence the copy.
  auto* vertices = static_cast<glm::vec3*>(rtcSetNewGeometryBuffer(
      geometry.get(), RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, sizeof(glm::vec3), positions.size()));
  auto* triangles = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
      geometry.get(), RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), indices.size() / 3));
  checkEmbree();
  std::copy(positions.begin(), positions.end(), vertices);
  std::copy(indices.begin(), indices.end(), triangles);
  rtcCommitGeometry(geometry.get());
  rtcAttachGeometryByID(scene_.get(), geometry.get(), id);
  checkEmbree();

  Bounds box{positions.front(), positions.front()};  // valid indices imply at least one vertex
  for (const glm::vec3& p : positions) {
    box.lower = glm::min(box.lower, p);
    box.upper = glm::max(box.upper, p);
  }
  bounds_ =
      meshes_.empty() ? box : Bounds{glm::min(bounds_.lower, box.lower), glm::max(bounds_.upper, box.upper)};
  meshes_.push_back({vertices, triangles});
  committed_ = false;
  return id;
}

void RayScene::setAlphaFilter(std::shared_ptr<const AlphaFilter> filter) {
  if (filter && filter->geometryCount() != meshes_.size())
    fail("ray scene", "the alpha filter has " + std::to_string(filter->geometryCount()) + " geometries, the scene " +
                          std::to_string(meshes_.size()));
  clearEmbreeError();
  for (unsigned id = 0; id < meshes_.size(); ++id) {
    RTCGeometry geometry = rtcGetGeometry(scene_.get(), id);
    const unsigned needs = filter ? filter->needs(id) : 0u;
    rtcSetGeometryUserData(geometry, needs ? const_cast<AlphaFilter*>(filter.get()) : nullptr);
    rtcSetGeometryIntersectFilterFunction(geometry, needs ? filterCandidates : nullptr);
    rtcSetGeometryOccludedFilterFunction(geometry,
                                         needs & AlphaFilter::kAlphaTest ? filterCandidates : nullptr);
    rtcCommitGeometry(geometry);
  }
  checkEmbree();
  filter_ = std::move(filter);
  committed_ = false;
}

void RayScene::commit() {
  clearEmbreeError();
  rtcCommitScene(scene_.get());
  checkEmbree();
  committed_ = true;
}

void RayScene::requireCommitted(const char* query) const {
  if (!committed_) fail("ray scene", std::string(query) + " called before commit()");
}

Hit RayScene::intersect(const Ray& ray, float tmin, float tmax, const RayQuery& rayQuery) const {
  requireCommitted("intersect");
  // A context per call: it carries no shared state, which is what makes concurrent queries safe.
  RayQueryContext context(rayQuery);
  RTCRayHit query{};
  query.ray.org_x = ray.origin.x;
  query.ray.org_y = ray.origin.y;
  query.ray.org_z = ray.origin.z;
  query.ray.dir_x = ray.direction.x;
  query.ray.dir_y = ray.direction.y;
  query.ray.dir_z = ray.direction.z;
  query.ray.tnear = tmin;
  query.ray.tfar = tmax;
  query.ray.mask = ~0u;
  query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_.get(), &context.context, &query);

  return hitFrom(query.hit.geomID, query.hit.primID, query.ray.tfar, query.hit.u, query.hit.v,
                 glm::vec3(query.hit.Ng_x, query.hit.Ng_y, query.hit.Ng_z));
}

bool RayScene::occluded(glm::vec3 origin, glm::vec3 direction, float tmin, float tmax,
                        const RayQuery& rayQuery) const {
  requireCommitted("occluded");
  RayQueryContext context(rayQuery);
  RTCRay query{};
  query.org_x = origin.x;
  query.org_y = origin.y;
  query.org_z = origin.z;
  query.dir_x = direction.x;
  query.dir_y = direction.y;
  query.dir_z = direction.z;
  query.tnear = tmin;
  query.tfar = tmax;
  query.mask = ~0u;
  rtcOccluded1(scene_.get(), &context.context, &query);
  // Embree marks an occluded ray by setting tfar to -infinity.
  return query.tfar == -std::numeric_limits<float>::infinity();
}

namespace {

// Embree's packet types and calls by width.
template <int W>
struct Packet {
  static_assert(W == 8 || W == 16, "Embree packets used here are 8 or 16 wide");
  using RayHit = std::conditional_t<W == 8, RTCRayHit8, RTCRayHit16>;
  using Ray = std::conditional_t<W == 8, RTCRay8, RTCRay16>;
  static void intersect(const int* valid, RTCScene scene, RTCIntersectContext* context, RayHit* query) {
    if constexpr (W == 8)
      rtcIntersect8(valid, scene, context, query);
    else
      rtcIntersect16(valid, scene, context, query);
  }
  static void occluded(const int* valid, RTCScene scene, RTCIntersectContext* context, Ray* query) {
    if constexpr (W == 8)
      rtcOccluded8(valid, scene, context, query);
    else
      rtcOccluded16(valid, scene, context, query);
  }
};

// Lane k of a packet's rays.
template <class RayN>
void setLane(RayN& ray, std::size_t k, const glm::vec3& origin, const glm::vec3& direction, float tmin, float tmax,
             unsigned id) {
  ray.org_x[k] = origin.x;
  ray.org_y[k] = origin.y;
  ray.org_z[k] = origin.z;
  ray.dir_x[k] = direction.x;
  ray.dir_y[k] = direction.y;
  ray.dir_z[k] = direction.z;
  ray.tnear[k] = tmin;
  ray.tfar[k] = tmax;
  ray.time[k] = 0.0f;
  ray.mask[k] = ~0u;
  ray.id[k] = id;
  ray.flags[k] = 0;
}

// The rays in packets of W; the last packet's unused lanes repeat its last ray, invalid.
template <int W>
void intersectPackets(RTCScene scene, RTCIntersectContext* context, std::span<const Ray> rays, float tmin, float tmax,
                      std::span<Hit> hits) {
  for (std::size_t first = 0; first < rays.size(); first += W) {
    const std::size_t count = std::min<std::size_t>(W, rays.size() - first);
    alignas(64) int valid[W];
    alignas(64) typename Packet<W>::RayHit query;
    for (std::size_t k = 0; k < W; ++k) {
      valid[k] = k < count ? -1 : 0;
      const Ray& ray = rays[first + std::min(k, count - 1)];
      setLane(query.ray, k, ray.origin, ray.direction, tmin, tmax, 0);
      query.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
      query.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
    }
    Packet<W>::intersect(valid, scene, context, &query);
    for (std::size_t k = 0; k < count; ++k)
      hits[first + k] = hitFrom(query.hit.geomID[k], query.hit.primID[k], query.ray.tfar[k], query.hit.u[k],
                                query.hit.v[k], glm::vec3(query.hit.Ng_x[k], query.hit.Ng_y[k], query.hit.Ng_z[k]));
  }
}

// Each packet's queries go to the filter through the context, indexed by the lanes' ray ids.
template <int W>
void occludedPackets(RTCScene scene, std::span<const OcclusionQuery> rays, std::span<std::uint8_t> blocked) {
  RayQuery queries[W];
  RayQueryContext context(queries[0]);
  context.perRay = true;
  for (std::size_t first = 0; first < rays.size(); first += W) {
    const std::size_t count = std::min<std::size_t>(W, rays.size() - first);
    alignas(64) int valid[W];
    alignas(64) typename Packet<W>::Ray query;
    for (std::size_t k = 0; k < W; ++k) {
      valid[k] = k < count ? -1 : 0;
      const OcclusionQuery& ray = rays[first + std::min(k, count - 1)];
      queries[k] = ray.query;
      setLane(query, k, ray.origin, ray.direction, ray.tmin, ray.tmax, static_cast<unsigned>(k));
    }
    Packet<W>::occluded(valid, scene, &context.context, &query);
    // Embree marks an occluded ray by setting tfar to -infinity.
    for (std::size_t k = 0; k < count; ++k)
      blocked[first + k] = query.tfar[k] == -std::numeric_limits<float>::infinity();
  }
}

}  // namespace

void RayScene::intersectCoherent(std::span<const Ray> rays, float tmin, float tmax, const RayQuery& rayQuery,
                                 std::span<Hit> hits) const {
  requireCommitted("intersect");
  if (hits.size() != rays.size()) throw std::invalid_argument("RayScene::intersectCoherent: rays and hits differ in number");
  RayQueryContext context(rayQuery);
  context.context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  if (nativePacket16_)
    intersectPackets<16>(scene_.get(), &context.context, rays, tmin, tmax, hits);
  else
    intersectPackets<8>(scene_.get(), &context.context, rays, tmin, tmax, hits);
}

void RayScene::occluded(std::span<const OcclusionQuery> rays, std::span<std::uint8_t> blocked) const {
  requireCommitted("occluded");
  if (blocked.size() != rays.size()) throw std::invalid_argument("RayScene::occluded: rays and results differ in number");
  // Shadow rays start apart and scatter: 16-wide packets of them were no faster than 8.
  occludedPackets<8>(scene_.get(), rays, blocked);
}

RayScene::SurfacePosition RayScene::surfacePosition(const Hit& hit) const {
  const MeshBuffers& mesh = meshes_.at(hit.geomId);
  const uint32_t* corner = mesh.indices + 3 * std::size_t(hit.primId);
  const glm::vec3 &p0 = mesh.positions[corner[0]], &p1 = mesh.positions[corner[1]], &p2 = mesh.positions[corner[2]];
  const glm::vec3 point = trianglePoint(p0, p1, p2, hit.barycentrics.x, hit.barycentrics.y);
  return {point, surfaceErrorBound(point, triangleExtent(p0, p1, p2))};
}

RayScene::Bounds RayScene::bounds() const { return bounds_; }

float RayScene::scale() const { return glm::length(bounds_.upper - bounds_.lower); }

float RayScene::rayEpsilon() const {
  const glm::vec3 largest = glm::max(glm::abs(bounds_.lower), glm::abs(bounds_.upper));
  return iblkit::rayEpsilon(std::max({largest.x, largest.y, largest.z}));
}

}  // namespace iblkit
