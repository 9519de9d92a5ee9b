// The baker's rays and glTF alpha: AO, bent-normal and transfer rays pass through masked texels,
// through the same AlphaFilter as the tracer's shadow rays (raytrace/alpha_filter.h).
#include <gtest/gtest.h>

#include "baker/vertex_visibility.h"
#include "core/procedural_mesh.h"
#include "support/generated_textures.h"

namespace iblkit {
namespace {

// A 4 x 4 ground grid (mesh 0, material 0) under the card [-1, 1]^2 at y = 0.5 (mesh 1, material
// 1), whose uv maps the card's 4 x 4 alpha texture: (x, z) -> ((x + 1) / 2, (z + 1) / 2).
struct CardOverPlane {
  Scene scene;

  explicit CardOverPlane(AlphaMode mode, const std::function<std::uint8_t(int, int)>& alpha) {
    scene.materials = {Material{}, Material{}};
    scene.materials[1].alphaMode = mode;
    scene.materials[1].baseColorTexture = test::addTexture(scene, test::generatedImage(4, 4, [&](int x, int y) {
      return glm::u8vec4(255, 255, 255, alpha(x, y));
    }));
    scene.meshes.push_back(toMesh(gridPlane(glm::vec3(0.0f), 4.0f, 8), "ground"));
    Mesh card = test::texturedQuad(-1.0f, 1.0f, 0.0f, 1);
    for (glm::vec3& p : card.positions) p = glm::vec3(p.x, 0.5f, p.y);
    for (glm::vec3& n : card.normals) n = glm::vec3(0.0f, -1.0f, 0.0f);
    for (glm::vec2& uv : card.texcoords) uv = glm::vec2(uv.x, 1.0f - uv.y);
    card.indices = {0, 2, 1, 0, 3, 2};  // facing down
    scene.meshes.push_back(card);
  }

  std::vector<float> groundAo() const {
    VisibilitySettings settings;
    settings.rayCount = 256;
    useSceneMaterials(settings, scene);
    return bakeVertexVisibility(scene.meshes, settings)[0].ambientOcclusion;
  }
};

std::vector<float> groundAoAlone() {
  VisibilitySettings settings;
  settings.rayCount = 256;
  return bakeVertexVisibility({toMesh(gridPlane(glm::vec3(0.0f), 4.0f, 8), "ground")}, settings)[0].ambientOcclusion;
}

std::size_t vertexAt(const Mesh& mesh, const glm::vec3& point) {
  std::size_t best = 0;
  for (std::size_t v = 1; v < mesh.vertexCount(); ++v)
    if (glm::distance(mesh.positions[v], point) < glm::distance(mesh.positions[best], point)) best = v;
  return best;
}

// Alpha 0 everywhere under MASK: the card is not there for the bake, whose ground AO is, ray for
// ray, that of the ground alone. Opaque, the same card darkens the ground under it.
TEST(VertexVisibilityAlpha, FullyMaskedCardDoesNotDarkenThePlane) {
  const std::vector<float> alone = groundAoAlone();
  const std::vector<float> masked = CardOverPlane(AlphaMode::Mask, [](int, int) { return 0; }).groundAo();
  EXPECT_EQ(masked, alone);
  const std::vector<float> opaque = CardOverPlane(AlphaMode::Opaque, [](int, int) { return 0; }).groundAo();
  const std::size_t centre = vertexAt(CardOverPlane(AlphaMode::Opaque, [](int, int) { return 0; }).scene.meshes[0],
                                      glm::vec3(0.0f));
  EXPECT_LT(opaque[centre], alone[centre] - 0.3f);
}

// A hole (the centre 2 x 2 texels, |x|, |z| < 0.5) in a masked card 0.5 above the ground: the
// vertex under its centre sees the sky through it. The form factor of a rectangle X x Y (in units
// of its height) from a point under its corner, (X / sqrt(1 + X^2) atan(Y / sqrt(1 + X^2)) +
// Y / sqrt(1 + Y^2) atan(X / sqrt(1 + Y^2))) / (2 pi), over four quadrants: the hole (X = Y = 1)
// is 0.554 of the cosine-weighted hemisphere, the card (X = Y = 2) 0.831. So AO = 1 - 0.831 =
// 0.169 under the opaque card and 0.169 + 0.554 = 0.723 with the hole.
TEST(VertexVisibilityAlpha, MaskedHoleLetsTheBakeSeeTheSky) {
  const auto hole = [](int x, int y) -> std::uint8_t { return (x == 1 || x == 2) && (y == 1 || y == 2) ? 0 : 255; };
  const CardOverPlane holed(AlphaMode::Mask, hole);
  const std::vector<float> withHole = holed.groundAo();
  const std::vector<float> opaque = CardOverPlane(AlphaMode::Opaque, hole).groundAo();
  const std::vector<float> alone = groundAoAlone();
  const std::size_t centre = vertexAt(holed.scene.meshes[0], glm::vec3(0.0f));
  EXPECT_NEAR(withHole[centre], 0.723f, 0.04f);
  EXPECT_NEAR(opaque[centre], 0.169f, 0.04f);
  EXPECT_EQ(alone[centre], 1.0f);
}

}  // namespace
}  // namespace iblkit
