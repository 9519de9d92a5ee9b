#pragma once
// Textures made in code for the tracer's and the baker's tests: images texel by texel, a unit
// quad with texture coordinates, and the scene entries that tie them together.

#include <cstdint>
#include <functional>
#include <utility>

#include <glm/glm.hpp>
#include <glm/gtc/type_precision.hpp>

#include "core/mesh.h"
#include "core/scene.h"
#include "core/texture.h"

namespace iblkit::test {

// A width x height RGBA8 image, texel (x, y) (row 0 at the top, glTF uv (0, 0)) from `texel`.
inline TextureImage generatedImage(int width, int height, const std::function<glm::u8vec4(int, int)>& texel) {
  TextureImage image;
  image.name = "generated";
  image.mimeType = "image/png";
  image.width = width;
  image.height = height;
  image.rgba.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const glm::u8vec4 value = texel(x, y);
      for (int c = 0; c < 4; ++c) image.rgba[(static_cast<std::size_t>(y) * width + x) * 4 + c] = value[c];
    }
  return image;
}

// Nearest texel, no mip chain: each texel reads exactly as stored.
inline TextureSampler nearestSampler(TextureWrap wrap = TextureWrap::ClampToEdge) {
  TextureSampler sampler;
  sampler.wrapS = sampler.wrapT = wrap;
  sampler.magFilter = sampler.minFilter = TextureFilter::Nearest;
  sampler.mipmaps = false;
  return sampler;
}

// Adds `image` and a texture of it to `scene`; returns the TextureRef of that texture.
inline TextureRef addTexture(Scene& scene, TextureImage image, const TextureSampler& sampler = nearestSampler()) {
  scene.images.push_back(std::move(image));
  Texture texture;
  texture.image = static_cast<int>(scene.images.size()) - 1;
  texture.sampler = sampler;
  scene.textures.push_back(texture);
  TextureRef ref;
  ref.texture = static_cast<int>(scene.textures.size()) - 1;
  return ref;
}

// The square [lo, hi]^2 at height z, facing +z (counter-clockwise seen from +z), normal +z,
// TEXCOORD_0 u = (x - lo) / (hi - lo), v = (hi - y) / (hi - lo) (the image upright seen from +z),
// tangent +x with w = 1 (bitangent +y).
inline Mesh texturedQuad(float lo, float hi, float z, int material) {
  Mesh mesh;
  mesh.name = "quad";
  mesh.positions = {{lo, lo, z}, {hi, lo, z}, {hi, hi, z}, {lo, hi, z}};
  mesh.normals.assign(4, glm::vec3(0.0f, 0.0f, 1.0f));
  mesh.texcoords = {{0.0f, 1.0f}, {1.0f, 1.0f}, {1.0f, 0.0f}, {0.0f, 0.0f}};
  mesh.tangents.assign(4, glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
  mesh.indices = {0, 1, 2, 0, 2, 3};
  mesh.material = material;
  return mesh;
}

}  // namespace iblkit::test
