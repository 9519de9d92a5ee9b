#pragma once
// Probes of GLSL functions: a fragment shader of shaders/ run once per texel of an n x 1 target
// (fullscreen.vert), reading its arguments from n x 1 float tables at texelFetch(table, texel).
#include <functional>
#include <vector>

#include "core/image.h"
#include "engine/gl/gl_debug.h"
#include "engine/gl/gpu_textures.h"
#include "engine/gl/render_target.h"
#include "engine/gl/shader_program.h"
#include "gl/test_context.h"

namespace iblkit::test {

struct ProbeInput {
  const char* sampler;  // the probe's sampler2D uniform
  const Image* table;   // n x 1, one argument set per texel
};

// The probe's RGBA output for texel 0..n-1. Input i is bound to texture unit i; `setUniforms`
// sets the probe's other uniforms.
inline std::vector<glm::vec4> runFragmentProbe(
    const char* fragmentShader, const std::vector<ProbeInput>& inputs,
    const std::function<void(const ShaderProgram&)>& setUniforms = {}) {
  glContext();
  const int n = inputs.front().table->width();
  std::vector<GlTexture> textures;
  const ShaderProgram probe("fullscreen.vert", fragmentShader);
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    textures.push_back(uploadTable(*inputs[i].table));
    glBindTextureUnit(GLuint(i), textures.back().id());
    probe.set(inputs[i].sampler, int(i));
  }
  if (setUniforms) setUniforms(probe);
  RenderTarget target(n, 1, 1);
  GLuint vertexArray = 0;
  glCreateVertexArrays(1, &vertexArray);
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer());
  glViewport(0, 0, n, 1);
  glDisable(GL_DEPTH_TEST);
  probe.use();
  glBindVertexArray(vertexArray);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glDeleteVertexArrays(1, &vertexArray);
  glUseProgram(0);
  const Image out = target.readColor();
  checkGlErrors(fragmentShader);
  std::vector<glm::vec4> values;
  for (int i = 0; i < n; ++i) values.push_back(out.at(i, 0));
  return values;
}

}  // namespace iblkit::test
