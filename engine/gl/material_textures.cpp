#include "engine/gl/material_textures.h"

#include <algorithm>
#include <array>
#include <utility>

#include "core/error.h"
#include "engine/gl/texture_unit.h"

namespace iblkit {

GlSampler::GlSampler(GlSampler&& other) noexcept : id_(std::exchange(other.id_, 0)) {}

GlSampler& GlSampler::operator=(GlSampler&& other) noexcept {
  std::swap(id_, other.id_);
  return *this;
}

GlSampler::~GlSampler() {
  if (id_) glDeleteSamplers(1, &id_);
}

float maxTextureAnisotropy() {
  // GL_MAX_TEXTURE_MAX_ANISOTROPY (4.6) has the value of the extensions' _EXT enum (0x84FF).
  if (epoxy_gl_version() < 46 && !epoxy_has_gl_extension("GL_ARB_texture_filter_anisotropic") &&
      !epoxy_has_gl_extension("GL_EXT_texture_filter_anisotropic"))
    return 1.0f;
  GLfloat value = 1.0f;
  glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT, &value);
  return std::max(1.0f, value);
}

GlTexture uploadMipChain(const MipChain& chain) {
  if (chain.levels.empty() || chain.width() < 1 || chain.height() < 1)
    throw Error("texture upload: empty mip chain");
  requireTextureFits(chain.width(), chain.height(), GL_MAX_TEXTURE_SIZE, "a material texture");
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &id);
  GlTexture texture(id);
  const GLenum format = chain.colorSpace == ColorSpace::Srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8;
  glTextureStorage2D(id, GLsizei(chain.levels.size()), format, chain.width(), chain.height());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (std::size_t level = 0; level < chain.levels.size(); ++level) {
    const MipLevel& l = chain.levels[level];
    glTextureSubImage2D(id, GLint(level), 0, 0, l.width, l.height, GL_RGBA, GL_UNSIGNED_BYTE, l.rgba.data());
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureParameteri(id, GL_TEXTURE_MAX_LEVEL, GLint(chain.levels.size()) - 1);
  return texture;
}

namespace {

GLint glFilter(TextureFilter filter) { return filter == TextureFilter::Nearest ? GL_NEAREST : GL_LINEAR; }

GLint glMinFilter(const TextureSampler& s) {
  if (!s.mipmaps) return glFilter(s.minFilter);
  if (s.minFilter == TextureFilter::Nearest)
    return s.mipFilter == TextureFilter::Nearest ? GL_NEAREST_MIPMAP_NEAREST : GL_NEAREST_MIPMAP_LINEAR;
  return s.mipFilter == TextureFilter::Nearest ? GL_LINEAR_MIPMAP_NEAREST : GL_LINEAR_MIPMAP_LINEAR;
}

constexpr std::array<TextureSlot, 5> kSlots = {kSlotBaseColor, kSlotMetallicRoughness, kSlotNormal,
                                               kSlotOcclusion, kSlotEmissive};

const TextureRef& slotRef(const Material& m, int slot) {
  const TextureRef* refs[] = {&m.baseColorTexture, &m.metallicRoughnessTexture, &m.normalTexture,
                              &m.occlusionTexture, &m.emissiveTexture};
  return *refs[slot];
}

}  // namespace

ColorSpace slotColorSpace(TextureSlot slot) {
  return slot == kSlotBaseColor || slot == kSlotEmissive ? ColorSpace::Srgb : ColorSpace::Linear;
}

GlSampler createSampler(const TextureSampler& sampler, float anisotropy) {
  GLuint id = 0;
  glCreateSamplers(1, &id);
  GlSampler result(id);
  glSamplerParameteri(id, GL_TEXTURE_WRAP_S, GLint(sampler.wrapS));  // glTF uses the GL enums
  glSamplerParameteri(id, GL_TEXTURE_WRAP_T, GLint(sampler.wrapT));
  glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, glFilter(sampler.magFilter));
  const GLint minFilter = glMinFilter(sampler);
  glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, minFilter);
  const float maxAnisotropy = maxTextureAnisotropy();
  if (minFilter == GL_LINEAR_MIPMAP_LINEAR && maxAnisotropy > 1.0f)
    glSamplerParameterf(id, GL_TEXTURE_MAX_ANISOTROPY_EXT, std::clamp(anisotropy, 1.0f, maxAnisotropy));
  return result;
}

MaterialTextures::MaterialTextures(const Scene& scene, float anisotropy)
    : anisotropy_(std::clamp(anisotropy, 1.0f, maxTextureAnisotropy())) {
  const std::uint8_t white[4] = {255, 255, 255, 255};
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &id);
  white_ = GlTexture(id);
  glTextureStorage2D(id, 1, GL_RGBA8, 1, 1);
  glTextureSubImage2D(id, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, white);
  if (scene.textures.empty()) return;
  const SceneTextures textures(scene.textures, scene.images, scene.materials);
  for (std::size_t t = 0; t < scene.textures.size(); ++t) {
    const MipChain* linear = textures.chain(int(t), ColorSpace::Linear);
    const MipChain* srgb = textures.chain(int(t), ColorSpace::Srgb);
    linear_.push_back(linear && !linear->levels.empty() ? uploadMipChain(*linear) : GlTexture());
    srgb_.push_back(srgb && !srgb->levels.empty() ? uploadMipChain(*srgb) : GlTexture());
    samplers_.push_back(createSampler(textures.sampler(int(t)), anisotropy_));
  }
}

void setMaterialUniforms(const ShaderProgram& program, const Material& material, unsigned boundSlots) {
  const Material m = clampedToGltfRanges(material);
  program.set("baseColor", m.baseColor);
  program.set("metallic", m.metallic);
  program.set("roughness", m.roughness);
  program.set("specularWeight", m.specular);
  program.set("specularColor", m.specularColor);
  program.set("emissive", m.emissive);
  program.set("baseAlpha", std::clamp(m.alpha, 0.0f, 1.0f));
  program.set("normalScale", m.normalScale);
  program.set("occlusionStrength", std::clamp(m.occlusionStrength, 0.0f, 1.0f));
  program.set("alphaMode", int(m.alphaMode));
  program.set("alphaCutoff", m.alphaCutoff);
  program.set("doubleSided", int(m.doubleSided));
  program.set("textureSlots", int(boundSlots));
  if (boundSlots == 0) return;  // the untextured variant reads no slot
  static const char* const kTexCoord[] = {"slotTexCoord[0]", "slotTexCoord[1]", "slotTexCoord[2]",
                                          "slotTexCoord[3]", "slotTexCoord[4]"};
  static const char* const kTransform[] = {"slotTransform[0]", "slotTransform[1]", "slotTransform[2]",
                                           "slotTransform[3]", "slotTransform[4]"};
  for (int slot = 0; slot < int(kSlots.size()); ++slot) {
    const TextureRef& ref = slotRef(m, slot);
    program.set(kTexCoord[slot], ref.texCoord);
    program.set(kTransform[slot], ref.transform.matrix());
  }
}

MaterialTextures::SlotTexture MaterialTextures::slotTexture(const Material& material, int slot, unsigned slots) const {
  const TextureRef& ref = slotRef(material, slot);
  if (!(slots & kSlots[std::size_t(slot)]) || !ref.present() || std::size_t(ref.texture) >= samplers_.size()) return {};
  const auto& chains = slotColorSpace(kSlots[std::size_t(slot)]) == ColorSpace::Srgb ? srgb_ : linear_;
  return {chains[std::size_t(ref.texture)].id(), samplers_[std::size_t(ref.texture)].id()};
}

unsigned MaterialTextures::bind(const Material& material, unsigned slots) const {
  unsigned bound = 0;
  for (int slot = 0; slot < int(kSlots.size()); ++slot) {
    const GLuint unit = kTextureUnitBaseColor + GLuint(slot);
    const SlotTexture t = slotTexture(material, slot, slots);
    if (t.texture) bound |= kSlots[std::size_t(slot)];
    glBindTextureUnit(unit, t.texture ? t.texture : white_.id());
    glBindSampler(unit, t.texture ? t.sampler : 0);
  }
  return bound;
}

unsigned MaterialTextures::boundSlots(const Material& material, unsigned slots) const {
  unsigned bound = 0;
  for (int slot = 0; slot < int(kSlots.size()); ++slot)
    if (slotTexture(material, slot, slots).texture) bound |= kSlots[std::size_t(slot)];
  return bound;
}

}  // namespace iblkit
