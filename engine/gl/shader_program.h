#pragma once
// GLSL programs built from the shader sources embedded in the library (shaders/*.glsl, validated
// by glslangValidator at build time). `#include "file.glsl"` lines are expanded and `#line`
// directives keep compile errors pointing at the original file and line.
#include <epoxy/gl.h>

#include <glm/glm.hpp>
#include <string>
#include <string_view>

namespace iblkit {

// The embedded source of shaders/<name> with its includes expanded, a `#line 1 <n>` before each
// file (n numbering the files), for compilation. Throws Error("shaders/<name>: no such embedded
// shader") for an unknown name, or when an include is.
std::string expandedShaderSource(std::string_view name);

class ShaderProgram {
 public:
  // Compiles and links the two embedded stages, with `defines` ("#define NAME VALUE" lines)
  // inserted after each stage's #version line. Throws Error("shaders/<file>:<line>: <message>")
  // with the compiler's first message mapped back to the file it came from.
  ShaderProgram(std::string_view vertexShader, std::string_view fragmentShader,
                std::string_view defines = {});
  ShaderProgram(ShaderProgram&& other) noexcept;
  ShaderProgram& operator=(ShaderProgram&& other) noexcept;
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;
  ~ShaderProgram();

  GLuint id() const { return program_; }
  void use() const;

  // Uniform setters on this program (glProgramUniform*, no need to bind it). Unknown or unused
  // names are ignored, as GL does for location -1.
  void set(const char* name, int value) const;
  void set(const char* name, float value) const;
  void set(const char* name, const glm::vec2& value) const;
  void set(const char* name, const glm::vec3& value) const;
  void set(const char* name, const glm::vec4& value) const;
  void set(const char* name, const glm::mat4& value) const;
  void set(const char* name, const glm::mat3& value) const;
  void setArray(const char* name, const glm::vec3* values, int count) const;

 private:
  GLuint program_ = 0;
};

// "name[index]", the uniform name of an array element.
std::string uniformElement(const char* name, std::size_t index);

}  // namespace iblkit
