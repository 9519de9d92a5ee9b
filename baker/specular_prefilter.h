#pragma once
// The specular half of the split sum (Karis 2013, "Real Shading in Unreal Engine 4", section
// "Image Based Lighting"): the environment convolved with the GGX lobe under the assumption
// N = V = R, one cube mip level per roughness, so the engine reads level
// roughness * (levels - 1) with trilinear filtering. docs/prefilter.md.
//
// Level i of a chain of n levels has perceptual roughness i / (n - 1) (linear, as the Khronos
// glTF-Sample-Viewer's IBL sampler) and face size baseSize >> i; level 0 is the environment
// itself on the cube. Each texel of a rougher level is
//   sum_j L(l_j) NoL_j / sum_j NoL_j,
// over Hammersley samples of the GGX NDF around its direction n (h_j from D(h) cos(theta_h),
// l_j = reflect(-n, h_j)), with filtered importance sampling (Krivanek & Colbert 2008, "Real-time
// Shading with Filtered Importance Sampling", section 3): sample j reads the source cube's mip
// chain at lod = 0.5 log2(Omega_s / Omega_p) + 1, Omega_s = 1 / (count pdf_j) the solid angle the
// sample stands for, pdf_j = D(h_j) / 4 (N = V), Omega_p = 4 pi / (6 size_0^2) a source texel's.

#include <cstdint>
#include <vector>

#include "core/cube_map.h"
#include "bakefile/specular_exr.h"
#include "core/environment_map.h"

namespace iblkit {

struct SpecularPrefilterOptions {
  // Face size of level 0; 0 picks defaultSpecularBaseSize(environment.width()).
  int baseSize = 0;
  // Number of levels; 0 picks the full chain down to 1 x 1 (log2(baseSize) + 1 levels).
  int levelCount = 0;
  // GGX samples per texel of the roughest level; smoother levels take fewer
  // (specularSampleCount).
  std::uint32_t sampleCount = 1024;
};

// Samples per texel for a level of perceptual roughness r: round(maxSamples * r), at least
// min(64, maxSamples). Narrow lobes cover few source texels, and filtered importance sampling
// widens each sample's footprint to match, so they need fewer samples; the smooth levels are also
// the large ones, and this keeps them from dominating the cost (level 1 of a 128 base at 1024
// samples would be 75% of the chain). Checked per level against brute force in the tests.
std::uint32_t specularSampleCount(float roughness, std::uint32_t maxSamples);

// The source of the convolution: `environment` (rotation and intensity applied) on a size x size
// cube (cubeFromRadiance's values, 2x2 samples per texel, computed in parallel) and its
// box-filtered mip chain.
CubeMapLevels specularSourceChain(const EnvironmentMap& environment, int size);

// One prefiltered size x size cube for perceptual roughness `roughness` in (0, 1], from a source
// chain made by specularSourceChain (formula above). Parallel over rows of faces (TBB).
// Throws std::invalid_argument unless size >= 1, sampleCount >= 1, roughness in (0, 1] and the
// chain is non-empty.
CubeMap prefilterSpecularLevel(const CubeMapLevels& source, int size, float roughness,
                               std::uint32_t sampleCount);

// The largest face size defaultSpecularBaseSize gives: 1024, a level 0 texel of about 0.11 degree
// at a face's centre, finer than a 1280 x 720 frame's pixel on a mirror sphere that fills it (about
// 0.25 degree). Users' photographs come at 8192 and 16384 texels wide, where width / 4 would be a
// 2048 or 4096 base: 4x or 16x the prefiltering time, files and GPU memory of a 1024 base for
// detail no frame shows (docs/prefilter.md "Large maps"). Filament's cmgen makes a 256 base. A
// larger base is asked for explicitly (SpecularPrefilterOptions::baseSize, iblkit-bake
// --specular-size).
inline constexpr int kMaxDefaultSpecularBaseSize = 1024;

// The default face size of level 0 for a lat-long map `latLongWidth` texels wide: the largest
// power of two at most width / 4 (128 for 512 x 256, 512 for a 3000 x 1500 photograph) and at most
// kMaxDefaultSpecularBaseSize, so any map at least 8 wide prefilters; the source cube samples the
// map by direction, so no size must divide.
int defaultSpecularBaseSize(int latLongWidth);

// The whole chain. Throws std::invalid_argument for a base size that is not a power of two, or a
// level count outside [2, log2(baseSize) + 1].
SpecularCube prefilterSpecular(const EnvironmentMap& environment,
                               const SpecularPrefilterOptions& options = {});

}  // namespace iblkit
