#pragma once
// The textures of a scene's materials on the GPU (docs/engine.md "Textures"): each texture's core
// mip chain (texture_sampling.h: SceneTextures, buildMipChain) uploaded level by level, not
// glGenerateMipmap'd, so that the raster filters the very texels the reference and the baker read;
// sRGB chains as GL_SRGB8_ALPHA8 (the unit decodes before filtering, as the core does), linear ones
// as GL_RGBA8; one sampler object per texture from its glTF sampler, anisotropic where offered.
#include <epoxy/gl.h>

#include <vector>

#include "core/scene.h"
#include "core/texture_sampling.h"
#include "engine/gl/gpu_textures.h"
#include "engine/gl/shader_program.h"

namespace iblkit {

// An owned sampler object name (deleted with the object; needs the context current).
class GlSampler {
 public:
  GlSampler() = default;
  explicit GlSampler(GLuint id) : id_(id) {}
  GlSampler(GlSampler&& other) noexcept;
  GlSampler& operator=(GlSampler&& other) noexcept;
  GlSampler(const GlSampler&) = delete;
  GlSampler& operator=(const GlSampler&) = delete;
  ~GlSampler();
  GLuint id() const { return id_; }

 private:
  GLuint id_ = 0;
};

// The driver's GL_MAX_TEXTURE_MAX_ANISOTROPY where it offers anisotropic filtering (core in
// OpenGL 4.6, else GL_ARB_texture_filter_anisotropic or GL_EXT_texture_filter_anisotropic);
// 1 where it does not.
float maxTextureAnisotropy();

// `chain` as a 2D texture with all its levels, row 0 first (glTF uv (0, 0) at t = 0), in
// GL_SRGB8_ALPHA8 for an sRGB chain and GL_RGBA8 for a linear one. Throws Error for an empty chain.
GlTexture uploadMipChain(const MipChain& chain);

// A sampler object for `sampler`: wrap S and T; magFilter; minFilter with the mip filter when
// mipmaps (NEAREST/LINEAR_MIPMAP_NEAREST/LINEAR), without them NEAREST or LINEAR; `anisotropy`
// (clamped to [1, maxTextureAnisotropy()]) when the minification is LINEAR_MIPMAP_LINEAR.
GlSampler createSampler(const TextureSampler& sampler, float anisotropy);

class MaterialTextures {
 public:
  MaterialTextures() = default;
  // Builds the scene's chains (SceneTextures over scene.textures, scene.images, scene.materials)
  // and uploads them; `anisotropy` for trilinear samplers (1: isotropic).
  MaterialTextures(const Scene& scene, float anisotropy);

  // Binds the textures of `material`'s slots that are present, switched on in `slots` and
  // uploaded (in the slot's colour space) to kTextureUnitBaseColor.. kTextureUnitEmissive, with
  // their samplers; returns those slots' TextureSlot bits. The other units get a 1 x 1 white
  // texture, which the shader reads but does not use.
  unsigned bind(const Material& material, unsigned slots) const;
  // The bits bind() returns, without binding anything.
  unsigned boundSlots(const Material& material, unsigned slots) const;

  std::size_t textureCount() const { return samplers_.size(); }
  float anisotropy() const { return anisotropy_; }

 private:
  struct SlotTexture {
    GLuint texture = 0, sampler = 0;
  };
  // The texture and sampler `material`'s slot (a kSlots index) reads with `slots` switched on;
  // zeros when it reads none.
  SlotTexture slotTexture(const Material& material, int slot, unsigned slots) const;

  std::vector<GlTexture> linear_, srgb_;  // per texture; id 0 where no slot reads it so
  std::vector<GlSampler> samplers_;       // per texture
  GlTexture white_;
  float anisotropy_ = 1.0f;
};

// Sets material.glsl's uniforms (and mesh.frag's specularWeight, specularColor, doubleSided,
// textureSlots) on `program` for `material`, clamped to the glTF ranges (clampedToGltfRanges;
// alpha and occlusion strength to [0, 1]), with `boundSlots` the bits MaterialTextures::bind
// returned.
void setMaterialUniforms(const ShaderProgram& program, const Material& material, unsigned boundSlots);

// The colour space a slot reads its texture in (core/material.h): sRGB for base colour and
// emissive, linear for metallic-roughness, normal and occlusion. `slot` is one TextureSlot bit.
ColorSpace slotColorSpace(TextureSlot slot);

}  // namespace iblkit
