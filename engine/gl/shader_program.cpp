#include "engine/gl/shader_program.h"

#include <glm/gtc/type_ptr.hpp>
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "engine/gl/embedded_shaders.h"

namespace iblkit {
namespace {

const EmbeddedShader& findShader(std::string_view name) {
  for (const EmbeddedShader& shader : embeddedShaders())
    if (shader.name == name) return shader;
  fail("shaders/" + std::string(name), "no such embedded shader");
}

std::string firstLine(const std::string& text) {
  const std::size_t end = text.find('\n');
  return text.substr(0, end);
}

// Maps the first message of a compiler log back to "shaders/<file>:<line>: <message>", using the
// source-string numbers of the #line directives (embedded_shaders.h). Understands Mesa's
// "N:L(C): error: ..." and NVIDIA's "N(L) : error ...".
std::string mapCompilerMessage(const EmbeddedShader& shader, const std::string& log) {
  static const std::regex mesa(R"(^(\d+):(\d+)\(\d+\): (.*)$)"), nvidia(R"(^(\d+)\((\d+)\) : (.*)$)");
  const std::string line = firstLine(log);
  std::smatch match;
  if (std::regex_match(line, match, mesa) || std::regex_match(line, match, nvidia)) {
    const std::size_t file = std::stoul(match[1].str());
    if (file < shader.files.size())
      return std::string(shader.files[file]) + ":" + match[2].str() + ": " + match[3].str();
  }
  return "shaders/" + std::string(shader.name) + ": " + line;
}

// The source with `defines` after the #version line (line 1 of every stage), then "#line 2 0" so
// that line numbers still match the file.
std::string withDefines(std::string_view source, std::string_view defines) {
  if (defines.empty()) return std::string(source);
  const std::size_t firstLineEnd = source.find('\n') + 1;
  return std::string(source.substr(0, firstLineEnd)) + std::string(defines) + "\n#line 2 0\n" +
         std::string(source.substr(firstLineEnd));
}

GLuint compileStage(GLenum type, std::string_view name, std::string_view defines) {
  const EmbeddedShader& shader = findShader(name);
  const GLuint id = glCreateShader(type);
  const std::string source = withDefines(shader.source, defines);
  const char* text = source.data();
  const GLint length = GLint(source.size());
  glShaderSource(id, 1, &text, &length);
  glCompileShader(id);
  GLint ok = GL_FALSE;
  glGetShaderiv(id, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint logLength = 0;
    glGetShaderiv(id, GL_INFO_LOG_LENGTH, &logLength);
    std::string log(std::size_t(std::max(logLength, 1)), '\0');
    glGetShaderInfoLog(id, GLsizei(log.size()), nullptr, log.data());
    glDeleteShader(id);
    throw Error(mapCompilerMessage(shader, log.c_str()));
  }
  return id;
}

}  // namespace

std::string expandedShaderSource(std::string_view name) { return std::string(findShader(name).source); }

ShaderProgram::ShaderProgram(std::string_view vertexShader, std::string_view fragmentShader,
                             std::string_view defines) {
  const GLuint vertex = compileStage(GL_VERTEX_SHADER, vertexShader, defines);
  GLuint fragment = 0;
  try {
    fragment = compileStage(GL_FRAGMENT_SHADER, fragmentShader, defines);
  } catch (...) {
    glDeleteShader(vertex);
    throw;
  }
  program_ = glCreateProgram();
  glAttachShader(program_, vertex);
  glAttachShader(program_, fragment);
  glLinkProgram(program_);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = GL_FALSE;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint logLength = 0;
    glGetProgramiv(program_, GL_INFO_LOG_LENGTH, &logLength);
    std::string log(std::size_t(std::max(logLength, 1)), '\0');
    glGetProgramInfoLog(program_, GLsizei(log.size()), nullptr, log.data());
    glDeleteProgram(program_);
    program_ = 0;
    fail("shaders/" + std::string(vertexShader) + " + " + std::string(fragmentShader),
         "link failed: " + firstLine(log.c_str()));
  }
}

ShaderProgram::ShaderProgram(ShaderProgram&& other) noexcept : program_(std::exchange(other.program_, 0)) {}

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& other) noexcept {
  std::swap(program_, other.program_);
  return *this;
}

ShaderProgram::~ShaderProgram() {
  if (program_) glDeleteProgram(program_);
}

void ShaderProgram::use() const { glUseProgram(program_); }

void ShaderProgram::set(const char* name, int value) const {
  glProgramUniform1i(program_, glGetUniformLocation(program_, name), value);
}
void ShaderProgram::set(const char* name, float value) const {
  glProgramUniform1f(program_, glGetUniformLocation(program_, name), value);
}
void ShaderProgram::set(const char* name, const glm::vec2& value) const {
  glProgramUniform2fv(program_, glGetUniformLocation(program_, name), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::vec3& value) const {
  glProgramUniform3fv(program_, glGetUniformLocation(program_, name), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::vec4& value) const {
  glProgramUniform4fv(program_, glGetUniformLocation(program_, name), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::mat4& value) const {
  glProgramUniformMatrix4fv(program_, glGetUniformLocation(program_, name), 1, GL_FALSE,
                            glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::mat3& value) const {
  glProgramUniformMatrix3fv(program_, glGetUniformLocation(program_, name), 1, GL_FALSE,
                            glm::value_ptr(value));
}
void ShaderProgram::setArray(const char* name, const glm::vec3* values, int count) const {
  glProgramUniform3fv(program_, glGetUniformLocation(program_, name), count, glm::value_ptr(values[0]));
}

std::string uniformElement(const char* name, std::size_t index) {
  std::string element(name);
  element += '[';
  element += std::to_string(index);
  element += ']';
  return element;
}

}  // namespace iblkit
