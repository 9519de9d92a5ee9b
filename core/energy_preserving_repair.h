#pragma once
// Repair of negative radiance in a lat-long map that keeps the map's integral. Lossy OpenEXR
// compression (DWAA/DWAB) rings around very bright pixels, so the texels next to a sun can be
// negative: in sky.exr they carry -12.7% of the map's energy, and clamping them to 0 (what
// repairPixels does for other images) adds that 12.7% to every render. Here each negative value
// is set to 0 and its energy (value x texel solid angle) is taken from the positive texels around
// it, in proportion to their value, so that no texel goes negative and the per-channel integral
// sum L_i Omega_i is unchanged. docs/robustness.md, "Negative texels of environment maps".

#include <cstddef>
#include <filesystem>
#include <glm/glm.hpp>

#include "core/image.h"
#include "core/image_io.h"

namespace iblkit {

// The widest neighbourhood (in texels either side, a square window wrapping in longitude and
// clamped in latitude) that is asked to pay a negative texel's energy; debts no window up to this
// radius can pay are taken from every positive texel of the map at the end.
inline constexpr int kMaxRepairRadius = 16;

// What repairNegativeRadiance did, per colour channel (R, G, B) where it says so.
struct NegativeRadianceRepair {
  std::size_t negativeValues = 0;  // R, G, B or A components that were negative, now 0
  glm::dvec3 negativeEnergy{0.0};  // sum of the negative values x their texel solid angle (<= 0)
  glm::dvec3 signedEnergy{0.0};    // sum of L_i Omega_i over the map before the repair (steradian x radiance)
  int largestRadius = 0;           // the widest window that paid a debt (0: no debt paid locally)
  std::size_t paidByWholeMap = 0;  // negative values whose window up to kMaxRepairRadius could not pay
  // False where a channel's positive texels carry less energy than its negative ones: that
  // channel's negatives are then only set to 0 (the integral cannot be kept non-negative).
  bool energyKept = true;
};

// Sets every negative R, G or B value of the lat-long map `latLong` (any W x H, radiance x texel
// solid angle latLongTexelSolidAngle) to 0 and takes its energy from the positive values of the
// same channel in the smallest square window of radius 1, 2, 3, 4, 6, 8, 12 or 16 texels around
// it whose positive energy P covers the debt d: each of them is scaled by 1 - d / P. Debts no such
// window can pay are summed and taken from all positive values of the map the same way. Texels are
// visited in row order, each debt from the map as the earlier ones left it. Negative alpha becomes
// 0 (alpha carries no energy). The values must be finite (repairNonFinitePixels first).
NegativeRadianceRepair repairNegativeRadiance(Image& latLong);

// The warning of a loaded environment map's repairs, or "" when nothing was repaired:
// "<counts> pixel values set to 0; the negative values' -12.7% of the map's energy (luminance)
// taken from positive texels within 3 texels". `nonFinite` are the NaN and Inf counts of
// repairNonFinitePixels.
std::string environmentRepairSummary(const PixelRepairCounts& nonFinite,
                                     const NegativeRadianceRepair& negative);

}  // namespace iblkit
