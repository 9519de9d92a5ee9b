#pragma once
// The real-time engine's shading modes (docs/engine.md has each formula and its source). Each
// isolates one approximation of the reference path tracer, so the scorer can measure them apart.
#include <string_view>

#include "core/enum_names.h"

namespace iblkit {

enum class ShadingMode {
  Unlit,     // base colour only (the cost floor for benchmarks)
  Mirror,    // the lat-long environment along reflect(-v, n): a perfect mirror, no visibility
  Sh,        // SH9 irradiance along n times albedo / pi, no visibility
  // The brute-force irradiance cube (env/irradiance.exr) in place of SH9: the glTF Sample Viewer's
  // diffuse, without SH9's truncation.
  Irradiance,        // the irradiance cube along n times albedo / pi, no visibility
  IrradianceAoBent,  // the irradiance cube along the baked bent normal, times the ambient occlusion
  ShAo,      // Sh times the baked ambient occlusion
  ShAoBent,  // SH9 irradiance along the baked bent normal, times the ambient occlusion
  Prt,       // baked SH transfer dotted with the environment's SH9 radiance, times albedo / pi
  Full,      // the material model: diffuse (PRT) + split-sum specular with occlusion terms
  // Dominant lights (docs/dominant-lights.md, engine section): the environment split into K disk
  // lights (the extracted suns) and the residual map. The residual as in sh-ao-bent (its SH9 along
  // the bent normal times AO) plus its split-sum specular as in full; each light with the core's
  // BRDF (brdf.h) and the disk's exact irradiance; unshadowed, then with a shadow map each
  // (two trilinear taps on mipmapped depth and exponential moments, docs/engine.md).
  Lights,
  LightsShadowed,
  // glTF occlusion (the material's occlusionTexture, 1 + strength (R - 1); glTF 2.0 section
  // 3.9.3: it applies to indirect light, here all the environment's): Full with the asset's AO
  // texture in place of the baked per-vertex visibility, and Full with both (their product).
  FullGltfAo,  // Full, unshadowed SH9 irradiance, the glTF occlusion as the AO term
  FullBothAo,  // Full, baked AO times the glTF occlusion
};

// The one spelling of each mode (iblkit-view --mode and the viewer's menu; the report passes them on), in
// the order of the enum: the ladder from the cost floor to the full model.
inline constexpr EnumName<ShadingMode> kShadingModeNames[] = {
    {ShadingMode::Unlit, "unlit"}, {ShadingMode::Mirror, "mirror"},       {ShadingMode::Sh, "sh"},
    {ShadingMode::Irradiance, "irradiance"}, {ShadingMode::IrradianceAoBent, "irradiance-ao-bent"},
    {ShadingMode::ShAo, "sh-ao"},  {ShadingMode::ShAoBent, "sh-ao-bent"}, {ShadingMode::Prt, "prt"},
    {ShadingMode::Full, "full"},   {ShadingMode::Lights, "lights"},       {ShadingMode::LightsShadowed, "lights-shadowed"},
    {ShadingMode::FullGltfAo, "full-gltf-ao"}, {ShadingMode::FullBothAo, "full-both-ao"}};

// Every mode, in the order of the enum (for benchmarks, tests and the viewer's mode menu).
inline constexpr ShadingMode kShadingModes[] = {ShadingMode::Unlit, ShadingMode::Mirror,   ShadingMode::Sh,
                                                ShadingMode::Irradiance, ShadingMode::IrradianceAoBent,
                                                ShadingMode::ShAo,  ShadingMode::ShAoBent, ShadingMode::Prt,
                                                ShadingMode::Full,  ShadingMode::Lights,   ShadingMode::LightsShadowed,
                                                ShadingMode::FullGltfAo, ShadingMode::FullBothAo};

// The mode named `name` in kShadingModeNames. Throws Error("--mode: unknown shading mode '<name>'
// (expected one of unlit, mirror, ...)") for anything else.
ShadingMode parseShadingMode(std::string_view name);

// The name parseShadingMode accepts for `mode`.
std::string_view shadingModeName(ShadingMode mode);

}  // namespace iblkit
