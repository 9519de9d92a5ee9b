#pragma once
// The shader stages of shaders/, embedded at build time by embed_shaders_tool.cpp: each stage's
// source with its #include lines expanded. `#line L N` directives number the files: N indexes
// `files` ("shaders/<name>"), 0 being the stage itself, so a compiler message "N:L" maps back to
// the file and line it came from.
#include <span>
#include <string_view>

namespace iblkit {

struct EmbeddedShader {
  std::string_view name;  // file name in shaders/, e.g. "mesh.frag"
  std::string_view source;
  std::span<const std::string_view> files;
};

// Every embedded stage (defined in the generated embedded_shaders.cpp).
std::span<const EmbeddedShader> embeddedShaders();

}  // namespace iblkit
