#include "engine/gl/shadow_maps.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "engine/gl/light_constants.h"
#include "engine/gl/texture_unit.h"

namespace iblkit {
namespace {

// The plane n.p = offset of a mesh whose vertices all lie on one (within 1e-4 of its size); false
// for a mesh that is not planar or has no triangle of area.
bool meshPlane(const Mesh& mesh, glm::vec3& normal, float& offset) {
  if (mesh.positions.empty()) return false;
  const Bounds bounds = mesh.bounds();
  const float tolerance = 1e-4f * std::max(bounds.radius(), 1e-6f);
  float bestArea = 0.0f;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::vec3 a = mesh.positions[mesh.indices[t]], b = mesh.positions[mesh.indices[t + 1]],
                    c = mesh.positions[mesh.indices[t + 2]];
    const glm::vec3 n = glm::cross(b - a, c - a);
    const float area = glm::length(n);
    if (area > bestArea) bestArea = area, normal = n / area, offset = glm::dot(normal, a);
  }
  if (bestArea <= 0.0f) return false;
  return std::all_of(mesh.positions.begin(), mesh.positions.end(),
                     [&](const glm::vec3& p) { return std::abs(glm::dot(normal, p) - offset) <= tolerance; });
}

// Whether any mesh but the ground has vertices: something to cast a shadow.
bool hasObject(const std::vector<Mesh>& meshes) {
  return std::any_of(meshes.begin(), meshes.end(), [](const Mesh& m) { return !m.isGround && !m.positions.empty(); });
}

// The plane the ground meshes lie on, when they all lie on one: false when there is no ground, a
// ground mesh is not planar, or two lie on different planes.
bool groundPlane(const std::vector<Mesh>& meshes, glm::vec3& normal, float& offset) {
  bool found = false;
  for (const Mesh& mesh : meshes) {
    if (!mesh.isGround) continue;
    glm::vec3 n;
    float o = 0.0f;
    if (!meshPlane(mesh, n, o)) return false;
    if (found) {
      const float tolerance = 1e-4f * std::max(mesh.bounds().radius(), 1e-6f);
      if (std::abs(glm::dot(n, normal)) < 1.0f - 1e-5f) return false;
      if (std::abs(glm::dot(n, normal) * o - offset) > tolerance) return false;
      continue;
    }
    normal = n, offset = o, found = true;
  }
  return found;
}

}  // namespace

ShadowFrame fitShadowFrame(const std::vector<Mesh>& meshes, const ShadowLight& light, int size) {
  const glm::vec3 d = glm::normalize(light.towardsLight);
  // Any basis perpendicular to the light; the map is a square over the fitted rectangle.
  const glm::vec3 helper = std::abs(d.y) < 0.99f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
  ShadowFrame frame;
  frame.right = glm::normalize(glm::cross(helper, d));
  frame.up = glm::cross(d, frame.right);
  const bool anyObject = hasObject(meshes);
  // The depth coordinate: the distance towards the light, measured from the plane of a planar
  // ground (t = (n.p - offset) / (n.d), the distance along d from the plane to p) where there is
  // one, else from the plane through the origin across the light (t = d.p). Both grow by exactly
  // delta when p moves by delta along d, so at any (u, v) they order the surfaces alike and
  // measure their separations alike; the first makes the ground a plane of constant depth in the
  // map, so that a wide filter footprint over the ground holds one depth where it held a ramp
  // (docs/engine.md "Shadows": the exponential moments of a ramp are dominated by its deepest
  // texels, which leaked light into large lights' shadows).
  glm::vec3 depthAxis = d;
  float depthOffset = 0.0f;
  glm::vec3 groundNormal;
  float groundOffset = 0.0f;
  const bool groundFlat = anyObject && groundPlane(meshes, groundNormal, groundOffset) &&
                          std::abs(glm::dot(groundNormal, d)) > kShadowGroundShearMinCos;
  if (groundFlat) {
    const float nd = glm::dot(groundNormal, d);
    depthAxis = groundNormal / nd;
    depthOffset = -groundOffset / nd;
  }
  auto inLightFrame = [&](const glm::vec3& p) {
    return glm::vec3(glm::dot(p, frame.right), glm::dot(p, frame.up), glm::dot(p, depthAxis) + depthOffset);
  };
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const Mesh& mesh : meshes)
    if (!anyObject || !mesh.isGround)
      for (const glm::vec3& p : mesh.positions) {
        const glm::vec3 q = inLightFrame(p);
        lo = glm::min(lo, q);
        hi = glm::max(hi, q);
      }
  if (lo.x > hi.x) lo = glm::vec3(-1.0f), hi = glm::vec3(1.0f);
  // The ground's depth under a rectangle [uvLo, uvHi] of the map: 0 on a flat ground's plane, a
  // plane's at the corners (the depth of a plane is linear across the map), else every vertex's.
  auto groundDepths = [&](const glm::vec2& uvLo, const glm::vec2& uvHi) {
    if (!anyObject) return;
    if (groundFlat) {
      lo.z = std::min(lo.z, 0.0f);
      hi.z = std::max(hi.z, 0.0f);
      return;
    }
    for (const Mesh& mesh : meshes) {
      if (!mesh.isGround) continue;
      glm::vec3 n;
      float offset = 0.0f;
      if (meshPlane(mesh, n, offset) && std::abs(glm::dot(n, d)) > 1e-3f) {
        for (int corner = 0; corner < 4; ++corner) {
          const glm::vec2 uv((corner & 1) ? uvHi.x : uvLo.x, (corner & 2) ? uvHi.y : uvLo.y);
          const glm::vec3 p = uv.x * frame.right + uv.y * frame.up;  // depth 0 on the plane through the origin
          const float depth = (offset - glm::dot(n, p)) / glm::dot(n, d);
          lo.z = std::min(lo.z, depth);
          hi.z = std::max(hi.z, depth);
        }
      } else {
        for (const glm::vec3& p : mesh.positions) {
          const float depth = glm::dot(p, d);
          lo.z = std::min(lo.z, depth);
          hi.z = std::max(hi.z, depth);
        }
      }
    }
  };
  // A degenerate side (a plane seen edge-on) gets the other's size.
  glm::vec2 side(hi.x - lo.x, hi.y - lo.y);
  const float largest = std::max({side.x, side.y, 1e-6f});
  side = glm::max(side, glm::vec2(largest * 1e-3f));
  // The blocker search of a receiver at depth z looks z tan(r) around it (shadow.glsl): with the
  // ground's depth under the grown rectangle, grow it again until the margin covers the search at
  // the far end (twice is enough for a sun of a few degrees; the margin only grows).
  glm::vec2 margin = side * (2.0f / float(size - 4));
  for (int pass = 0; pass < 3; ++pass) {
    groundDepths(glm::vec2(lo) - margin, glm::vec2(lo) + side + margin);
    const float search = 1.02f * (hi.z - lo.z) * std::tan(light.angularRadius);
    margin = glm::vec2(search) + (side + 2.0f * search) * (2.0f / float(size - 4));
  }
  groundDepths(glm::vec2(lo) - margin, glm::vec2(lo) + side + margin);  // the final rectangle's
  const glm::vec2 uvLo = glm::vec2(lo) - margin;
  side += 2.0f * margin;
  const float depthMargin = std::max(0.01f * (hi.z - lo.z), 1e-3f * largest);
  const float zNear = hi.z + depthMargin, range = (hi.z - lo.z) + 2.0f * depthMargin;
  // Rows of the map: u = (right.p - uvLo.x) / side.x, v likewise, depth = (zNear - t(p)) / range.
  glm::mat4 m(0.0f);
  for (int c = 0; c < 3; ++c) {
    m[c][0] = frame.right[c] / side.x;
    m[c][1] = frame.up[c] / side.y;
    m[c][2] = -depthAxis[c] / range;
  }
  m[3] = glm::vec4(-uvLo.x / side.x, -uvLo.y / side.y, (zNear - depthOffset) / range, 1.0f);
  frame.shadowFromWorld = m;
  // A receiver plane of normal g has the map-space normal A^-T g (A: the 3 x 3 of the map);
  // scaled so that the world slope of its depth across the map is |xy| / |z|.
  const glm::mat3 normalToMap = glm::transpose(glm::inverse(glm::mat3(m)));
  frame.slopeFromNormal = glm::mat3(glm::vec3(range / side.x, 0.0f, 0.0f), glm::vec3(0.0f, range / side.y, 0.0f),
                                    glm::vec3(0.0f, 0.0f, 1.0f)) * normalToMap;
  frame.extent = glm::vec4(side.x, side.y, range, std::max(side.x, side.y) / float(size));
  return frame;
}

ShadowCoverage shadowCoverage(const Mesh& mesh, const std::vector<ShadowFrame>& frames) {
  ShadowCoverage coverage;
  const auto append = [](std::vector<TriangleRun>& runs, std::size_t triangle) {
    if (!runs.empty() && runs.back().first + runs.back().count == triangle)
      ++runs.back().count;
    else
      runs.push_back({triangle, 1});
  };
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    bool covered = false;
    for (const ShadowFrame& frame : frames) {
      glm::vec2 low(std::numeric_limits<float>::infinity()), high(-std::numeric_limits<float>::infinity());
      for (int k = 0; k < 3; ++k) {
        const glm::vec4 s = frame.shadowFromWorld * glm::vec4(mesh.positions[mesh.indices[3 * t + std::size_t(k)]], 1.0f);
        low = glm::min(low, glm::vec2(s));
        high = glm::max(high, glm::vec2(s));
      }
      // Overlaps [0, 1]^2 (NaN corners count as covered).
      if (!(high.x < 0.0f || high.y < 0.0f || low.x > 1.0f || low.y > 1.0f)) {
        covered = true;
        break;
      }
    }
    append(covered ? coverage.covered : coverage.uncovered, t);
  }
  return coverage;
}

ShadowMaps::ShadowMaps(int size) : size_(size) {
  glCreateFramebuffers(1, &framebuffer_);
  glCreateVertexArrays(1, &emptyVertexArray_);
  glCreateSamplers(1, &groundSampler_);
  // The ground's visibility: bilinear; beyond the texture its edge texels, lit (shadow_ground.frag).
  glSamplerParameteri(groundSampler_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(groundSampler_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(groundSampler_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(groundSampler_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glCreateSamplers(1, &momentsSampler_);
  // Outside the map: the far plane, whose moments are (1, exp(0)).
  const float border[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  glSamplerParameteri(momentsSampler_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glSamplerParameteri(momentsSampler_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  glSamplerParameterfv(momentsSampler_, GL_TEXTURE_BORDER_COLOR, border);
  glSamplerParameteri(momentsSampler_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(momentsSampler_, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
}

ShadowMaps::~ShadowMaps() {
  if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
  if (emptyVertexArray_) glDeleteVertexArrays(1, &emptyVertexArray_);
  if (groundSampler_) glDeleteSamplers(1, &groundSampler_);
  if (momentsSampler_) glDeleteSamplers(1, &momentsSampler_);
}

void ShadowMaps::update(const std::vector<Mesh>& meshes, const std::vector<GpuMesh>& gpuMeshes,
                        const std::vector<ShadowLight>& lights) {
  if (lights == lights_) return;
  lights_ = lights;
  frames_.clear();
  ground_ = {};
  if (lights.empty()) return;
  const int layers = int(lights.size());
  if (layers > layers_) {
    GLuint ids[2] = {0, 0};
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 2, ids);
    int levels = 1;
    while ((size_ >> levels) > 0) ++levels;
    glTextureStorage3D(ids[0], 1, GL_DEPTH_COMPONENT32F, size_, size_, layers);
    glTextureStorage3D(ids[1], levels, GL_RG32F, size_, size_, layers);
    depth_ = GlTexture(ids[0]);
    moments_ = GlTexture(ids[1]);
    layers_ = layers;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glNamedFramebufferDrawBuffer(framebuffer_, GL_COLOR_ATTACHMENT0);
  glViewport(0, 0, size_, size_);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);  // both faces: the ground is one-sided, meshes may be open
  glDisable(GL_SAMPLE_SHADING);
  depthProgram_.use();
  const float far[4] = {1.0f, 1.0f, 0.0f, 0.0f};  // depth 1: moments (1, exp(0))
  for (int i = 0; i < layers; ++i) {
    frames_.push_back(fitShadowFrame(meshes, lights[std::size_t(i)], size_));
    glNamedFramebufferTextureLayer(framebuffer_, GL_DEPTH_ATTACHMENT, depth_.id(), 0, i);
    glNamedFramebufferTextureLayer(framebuffer_, GL_COLOR_ATTACHMENT0, moments_.id(), 0, i);
    glClearNamedFramebufferfv(framebuffer_, GL_COLOR, 0, far);
    glClearNamedFramebufferfi(framebuffer_, GL_DEPTH_STENCIL, 0, 1.0f, 0);
    depthProgram_.set("shadowFromWorld", frames_.back().shadowFromWorld);
    for (const GpuMesh& mesh : gpuMeshes) mesh.draw();
  }
  glGenerateTextureMipmap(moments_.id());
  renderGroundVisibility(meshes, lights);
  ++renderCount_;
  glDisable(GL_DEPTH_TEST);
  glBindVertexArray(0);
  glUseProgram(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

GroundVisibilityFrame fitGroundVisibility(const std::vector<Mesh>& meshes, const std::vector<ShadowLight>& lights,
                                          const std::vector<ShadowFrame>& frames, int maxSize) {
  GroundVisibilityFrame ground;
  glm::vec3 n;
  float offset = 0.0f;
  if (!hasObject(meshes) || lights.size() != frames.size() || !groundPlane(meshes, n, offset)) return ground;
  // The plane's axes, and its points as (a.p, b.p).
  const glm::vec3 helper = std::abs(n.y) < 0.99f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
  const glm::vec3 a = glm::normalize(glm::cross(helper, n)), b = glm::cross(n, a);
  glm::vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  float texel = std::numeric_limits<float>::max();
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const glm::vec3 d = glm::normalize(lights[i].towardsLight);
    const float nd = glm::dot(n, d);
    // A light along the plane lights none of it; the shadows' region is that of the others.
    if (std::abs(nd) < 1e-3f) continue;
    const glm::mat4 worldFromShadow = glm::inverse(frames[i].shadowFromWorld);
    for (int corner = 0; corner < 4; ++corner) {
      const glm::vec3 o = glm::vec3(worldFromShadow * glm::vec4(float(corner & 1), float(corner >> 1), 0.0f, 1.0f));
      const glm::vec3 p = o + (offset - glm::dot(n, o)) / nd * d;
      lo = glm::min(lo, glm::vec2(glm::dot(a, p), glm::dot(b, p)));
      hi = glm::max(hi, glm::vec2(glm::dot(a, p), glm::dot(b, p)));
    }
    texel = std::min(texel, frames[i].extent.w);
  }
  // Within the ground meshes.
  glm::vec2 groundLo(std::numeric_limits<float>::max()), groundHi(-std::numeric_limits<float>::max());
  for (const Mesh& mesh : meshes)
    if (mesh.isGround)
      for (const glm::vec3& p : mesh.positions) {
        groundLo = glm::min(groundLo, glm::vec2(glm::dot(a, p), glm::dot(b, p)));
        groundHi = glm::max(groundHi, glm::vec2(glm::dot(a, p), glm::dot(b, p)));
      }
  lo = glm::max(lo, groundLo);
  hi = glm::min(hi, groundHi);
  if (!(lo.x < hi.x && lo.y < hi.y) || !(texel > 0.0f) || !std::isfinite(texel)) return ground;
  const glm::vec2 side = hi - lo;
  // A texel of the finest map's size, at most maxSize along the longer side.
  const float step = std::max(texel, std::max(side.x, side.y) / float(maxSize));
  ground.width = std::clamp(int(std::ceil(side.x / step)), 2, maxSize);
  ground.height = std::clamp(int(std::ceil(side.y / step)), 2, maxSize);
  ground.origin = lo.x * a + lo.y * b + offset * n;
  ground.stepU = a * (side.x / float(ground.width));
  ground.stepV = b * (side.y / float(ground.height));
  ground.normal = n;
  ground.uFromWorld = a / side.x;
  ground.vFromWorld = b / side.y;
  return ground;
}

void setLightDirections(const ShaderProgram& program, const std::vector<ShadowLight>& lights) {
  for (std::size_t i = 0; i < lights.size(); ++i) {
    const ShadowLight& light = lights[i];
    program.set(uniformElement("lightDirection", i).c_str(), glm::normalize(light.towardsLight));
    program.set(uniformElement("lightCosSin", i).c_str(),
                glm::vec2(std::cos(light.angularRadius), std::sin(light.angularRadius)));
  }
}

void ShadowMaps::renderGroundVisibility(const std::vector<Mesh>& meshes, const std::vector<ShadowLight>& lights) {
  ground_ = fitGroundVisibility(meshes, lights, frames_, kGroundVisibilityMaxSize);
  if (!ground_.valid()) return;
  if (ground_.width != groundWidth_ || ground_.height != groundHeight_) {
    groundVisibility_ = GlTexture(createTargetTexture(GL_RGBA8, ground_.width, ground_.height));
    groundWidth_ = ground_.width;
    groundHeight_ = ground_.height;
  }
  const int count = int(lights.size());
  auto found = groundPrograms_.find(count);
  if (found == groundPrograms_.end())
    found = groundPrograms_
                .emplace(count, ShaderProgram("fullscreen.vert", "shadow_ground.frag",
                                              "#define LIGHT_COUNT " + std::to_string(count)))
                .first;
  const ShaderProgram& program = found->second;
  setUniforms(program);
  setLightDirections(program, lights);
  program.set("groundOrigin", ground_.origin);
  program.set("groundStepU", ground_.stepU);
  program.set("groundStepV", ground_.stepV);
  program.set("groundNormal", ground_.normal);
  glBindTextureUnit(kTextureUnitShadowDepth, moments_.id());
  glBindSampler(kTextureUnitShadowDepth, momentsSampler_);
  glNamedFramebufferTexture(framebuffer_, GL_DEPTH_ATTACHMENT, 0, 0);
  glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0, groundVisibility_.id(), 0);
  glViewport(0, 0, ground_.width, ground_.height);
  glDisable(GL_DEPTH_TEST);
  program.use();
  glBindVertexArray(emptyVertexArray_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void ShadowMaps::bind() const {
  glBindTextureUnit(kTextureUnitShadowDepth, moments_.id());
  glBindSampler(kTextureUnitShadowDepth, momentsSampler_);
  glBindTextureUnit(kTextureUnitShadowGround, groundVisibility_.id());
  glBindSampler(kTextureUnitShadowGround, groundSampler_);
}

void ShadowMaps::setUniforms(const ShaderProgram& program) const {
  program.set("groundVisibilityOrigin", ground_.origin);
  program.set("groundVisibilityU", ground_.uFromWorld);
  program.set("groundVisibilityV", ground_.vFromWorld);
  for (std::size_t i = 0; i < frames_.size(); ++i) {
    program.set(uniformElement("shadowFromWorld", i).c_str(), frames_[i].shadowFromWorld);
    program.set(uniformElement("shadowExtent", i).c_str(), frames_[i].extent);
    program.set(uniformElement("shadowSlopeFromNormal", i).c_str(), frames_[i].slopeFromNormal);
  }
}

}  // namespace iblkit
