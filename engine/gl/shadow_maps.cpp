#include "engine/gl/shadow_maps.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/gl/light_constants.h"
#include "engine/gl/texture_unit.h"

namespace iblkit {

ShadowFrame fitShadowFrame(const std::vector<Mesh>& meshes, const glm::vec3& towardsLight, int size) {
  const glm::vec3 d = glm::normalize(towardsLight);
  // Any basis perpendicular to the light; the map is a square over the fitted rectangle.
  const glm::vec3 helper = std::abs(d.y) < 0.99f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
  ShadowFrame frame;
  frame.right = glm::normalize(glm::cross(helper, d));
  frame.up = glm::cross(d, frame.right);
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const Mesh& mesh : meshes)
    for (const glm::vec3& p : mesh.positions) {
      const glm::vec3 q(glm::dot(p, frame.right), glm::dot(p, frame.up), glm::dot(p, d));
      lo = glm::min(lo, q);
      hi = glm::max(hi, q);
    }
  if (lo.x > hi.x) lo = glm::vec3(-1.0f), hi = glm::vec3(1.0f);
  // Two texels of margin on each side of u and v; a degenerate side (a plane seen edge-on) gets the
  // other's size. Depth: a margin of 1% of the range (at least 1e-3 of the size) on both ends.
  glm::vec2 side(hi.x - lo.x, hi.y - lo.y);
  const float largest = std::max({side.x, side.y, 1e-6f});
  side = glm::max(side, glm::vec2(largest * 1e-3f));
  const glm::vec2 margin = side * (2.0f / float(size - 4));
  const glm::vec2 uvLo = glm::vec2(lo) - margin;
  side += 2.0f * margin;
  const float depthMargin = std::max(0.01f * (hi.z - lo.z), 1e-3f * largest);
  const float zNear = hi.z + depthMargin, range = (hi.z - lo.z) + 2.0f * depthMargin;
  // Rows of the map: u = (right.p - uvLo.x) / side.x, v likewise, depth = (zNear - d.p) / range.
  glm::mat4 m(0.0f);
  for (int c = 0; c < 3; ++c) {
    m[c][0] = frame.right[c] / side.x;
    m[c][1] = frame.up[c] / side.y;
    m[c][2] = -d[c] / range;
  }
  m[3] = glm::vec4(-uvLo.x / side.x, -uvLo.y / side.y, zNear / range, 1.0f);
  frame.shadowFromWorld = m;
  frame.extent = glm::vec4(side.x, side.y, range, std::max(side.x, side.y) / float(size));
  return frame;
}

ShadowMaps::ShadowMaps(int size) : size_(size) {
  glCreateFramebuffers(1, &framebuffer_);
  glCreateSamplers(1, &rawSampler_);
  glCreateSamplers(1, &compareSampler_);
  const float border[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  for (GLuint sampler : {rawSampler_, compareSampler_}) {
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    glSamplerParameterfv(sampler, GL_TEXTURE_BORDER_COLOR, border);
  }
  glSamplerParameteri(rawSampler_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glSamplerParameteri(rawSampler_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glSamplerParameteri(compareSampler_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glSamplerParameteri(compareSampler_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(compareSampler_, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glSamplerParameteri(compareSampler_, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
}

ShadowMaps::~ShadowMaps() {
  if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
  if (rawSampler_) glDeleteSamplers(1, &rawSampler_);
  if (compareSampler_) glDeleteSamplers(1, &compareSampler_);
}

void ShadowMaps::update(const std::vector<Mesh>& meshes, const std::vector<GpuMesh>& gpuMeshes,
                        const std::vector<glm::vec3>& directions) {
  if (directions == directions_) return;
  directions_ = directions;
  frames_.clear();
  if (directions.empty()) return;
  const int layers = int(directions.size());
  if (layers > layers_) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
    glTextureStorage3D(id, 1, GL_DEPTH_COMPONENT32F, size_, size_, layers);
    depth_ = GlTexture(id);
    layers_ = layers;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  glViewport(0, 0, size_, size_);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);  // both faces: the ground is one-sided, meshes may be open
  glDisable(GL_SAMPLE_SHADING);
  depthProgram_.use();
  for (int i = 0; i < layers; ++i) {
    frames_.push_back(fitShadowFrame(meshes, directions[std::size_t(i)], size_));
    glNamedFramebufferTextureLayer(framebuffer_, GL_DEPTH_ATTACHMENT, depth_.id(), 0, i);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    depthProgram_.set("shadowFromWorld", frames_.back().shadowFromWorld);
    for (const GpuMesh& mesh : gpuMeshes) mesh.draw();
  }
  ++renderCount_;
  glDisable(GL_DEPTH_TEST);
  glBindVertexArray(0);
  glUseProgram(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void ShadowMaps::bind() const {
  glBindTextureUnit(kTextureUnitShadowDepth, depth_.id());
  glBindTextureUnit(kTextureUnitShadowCompare, depth_.id());
  glBindSampler(kTextureUnitShadowDepth, rawSampler_);
  glBindSampler(kTextureUnitShadowCompare, compareSampler_);
}

std::vector<glm::vec2> vogelDiskTaps(int n) {
  std::vector<glm::vec2> taps;
  for (int i = 0; i < n; ++i) {
    const float r = std::sqrt((float(i) + 0.5f) / float(n)), theta = float(i) * 2.39996323f;
    taps.emplace_back(r * std::cos(theta), r * std::sin(theta));
  }
  return taps;
}

void ShadowMaps::setUniforms(const ShaderProgram& program) const {
  static const std::vector<glm::vec2> blockerTaps = vogelDiskTaps(kBlockerSearchTaps), pcfTaps = vogelDiskTaps(kPcfTaps);
  for (int k = 0; k < kBlockerSearchTaps; ++k)
    program.set(uniformElement("blockerSearchTaps", std::size_t(k)).c_str(), blockerTaps[std::size_t(k)]);
  for (int k = 0; k < kPcfTaps; ++k)
    program.set(uniformElement("pcfTaps", std::size_t(k)).c_str(), pcfTaps[std::size_t(k)]);
  for (std::size_t i = 0; i < frames_.size(); ++i) {
    program.set(uniformElement("shadowFromWorld", i).c_str(), frames_[i].shadowFromWorld);
    program.set(uniformElement("shadowExtent", i).c_str(), frames_[i].extent);
    program.set(uniformElement("shadowRight", i).c_str(), frames_[i].right);
    program.set(uniformElement("shadowUp", i).c_str(), frames_[i].up);
  }
}

}  // namespace iblkit
