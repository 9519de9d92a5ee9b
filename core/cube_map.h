#pragma once
// Cube maps in OpenGL's layout: six square faces in the order +X, -X, +Y, -Y, +Z, -Z, each with
// OpenGL's orientation (OpenGL 4.5 core spec, section 8.13, Table 8.19), so face i uploads
// unchanged to GL_TEXTURE_CUBE_MAP_POSITIVE_X + i with image row 0 as the first row in memory.
// For a direction r the face is the one of the major axis ma (largest |component|), and
//   s = (sc / |ma| + 1) / 2,  t = (tc / |ma| + 1) / 2
//   +X: sc = -rz, tc = -ry    -X: sc = +rz, tc = -ry
//   +Y: sc = +rx, tc = +rz    -Y: sc = +rx, tc = -rz
//   +Z: sc = +rx, tc = -ry    -Z: sc = -rx, tc = -ry
// Texel (x, y) of a face of size N covers s in [x/N, (x+1)/N], t in [y/N, (y+1)/N]; row y = 0 is
// t = 0. Also OpenEXR's cube-map file layout (a vertical strip) and conversions to and from
// lat-long. Formulas and pictures: docs/conventions.md.

#include <array>
#include <filesystem>
#include <glm/glm.hpp>
#include <vector>

#include "core/image.h"
#include "core/latlong.h"

namespace iblkit {

// Face indices, in OpenGL's order (GL_TEXTURE_CUBE_MAP_POSITIVE_X + face).
enum CubeFace : int {
  kCubeFacePositiveX = 0,
  kCubeFaceNegativeX = 1,
  kCubeFacePositiveY = 2,
  kCubeFaceNegativeY = 3,
  kCubeFacePositiveZ = 4,
  kCubeFaceNegativeZ = 5,
};

// Six size x size faces (linear RGBA), indexed by CubeFace.
struct CubeMap {
  int size = 0;
  std::array<Image, 6> faces;
};

// A mip chain: level 0 first, each level half the size of the one before (rounded up), down to 1.
using CubeMapLevels = std::vector<CubeMap>;

// A point on the cube: a face and (s, t) in [0, 1]^2 on it.
struct CubeCoord {
  int face = kCubeFacePositiveZ;
  glm::vec2 st{0.5f};
};

// Direction (any non-zero length) -> face and (s, t), by Table 8.19. Ties between axes of equal
// magnitude (cube edges and corners) go to X, then Y, then Z. A zero vector gives the centre of +Z.
CubeCoord cubeCoord(const glm::vec3& direction);

// Face and (s, t) -> unit direction; the inverse of cubeCoord.
glm::vec3 cubeDirection(int face, const glm::vec2& st);

// Exact solid angle (steradians) of texel (x, y) of a face of the given size. With face
// coordinates a, b in [-1, 1], the solid angle of the rectangle from (0, 0) to (a, b) is
// atan(a b / sqrt(a^2 + b^2 + 1)) (the integral of (1 + a^2 + b^2)^(-3/2) da db); a texel is
// four such terms. The 6 size^2 texels sum to 4*pi.
float cubeTexelSolidAngle(int size, int x, int y);

// Bilinear lookup (RGB) between texel centres, seamless across face edges: a tap that falls one
// texel outside the face reads the adjacent face's texel across the shared edge, and a tap beyond
// a corner reads the mean of the three texels meeting at that cube corner (the rule of OpenGL's
// TEXTURE_CUBE_MAP_SEAMLESS, OpenGL 4.5 section 8.13.1). Faces must be size x size with size >= 1.
// A non-finite direction gives NaN.
glm::vec3 sampleCubeBilinear(const CubeMap& cube, const glm::vec3& direction);

// The texel sampleCubeBilinear reads for tap (x, y) of `face`, x and y in [-1, size]: the face's
// own texel inside, the adjacent face's across an edge, the mean of three beyond a corner. For
// copies of the faces with a one-texel border (the baker's specular prefilter).
glm::vec3 cubeTexelSeamless(const CubeMap& cube, int face, int x, int y);

// Renders a cube map of `radiance`: each texel is the solid-angle-weighted mean of
// samplesPerAxis^2 stratified samples (weight (1 + sc^2 + tc^2)^(-3/2), the solid angle per unit
// face area). Alpha is 1. Throws std::invalid_argument unless size and samplesPerAxis are >= 1.
CubeMap cubeFromRadiance(int size, int samplesPerAxis, const RadianceFunction& radiance);

// Lat-long image (docs/conventions.md) -> cube map, supersampled with bilinear lat-long lookups.
CubeMap cubeFromLatLong(const Image& latLong, int size, int samplesPerAxis = 2);

// Cube map -> width x width/2 lat-long image, supersampled with seamless bilinear cube lookups.
// Throws std::invalid_argument unless width is even and >= 2.
Image latLongFromCube(const CubeMap& cube, int width, int samplesPerAxis = 2);

// Mip chain of a cube map: level 0 is `base`, each next level downsample2x of every face (a 2x2
// box filter; odd sizes round up), ending with size 1.
CubeMapLevels cubeMipChain(const CubeMap& base);

// OpenEXR's cube-map layout (ImfEnvmap.h, namespace CubeMap): a W x 6W image, faces stacked
// top to bottom in the order +X, -X, +Y, -Y, +Z, -Z, each with OpenEXR's orientation, which is
// OpenGL's mirrored left-right on the X and Z faces and top-bottom on the Y faces. Converting
// moves texels without resampling: a direction finds the same radiance in the strip under
// OpenEXR's CubeMap functions as in the cube under Table 8.19 (docs/conventions.md).
Image cubeToExrStrip(const CubeMap& cube);

// The inverse of cubeToExrStrip. Throws Error("<file>: cube map strip is WxH, expected W x 6W")
// unless the strip is W x 6W with W >= 1.
CubeMap cubeFromExrStrip(const Image& strip, const std::filesystem::path& fileForErrors);

}  // namespace iblkit
