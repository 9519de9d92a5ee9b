// Shadow maps of the engine's disk lights (docs/engine.md "Shadows", engine/gl/shadow_maps.h): one
// orthographic map per light, fitted to the objects, holding per texel the exponential moments
// (d, exp(c (d - 1))) of its depth d (c = kShadowExponent; Annen et al. 2008, "Exponential Shadow
// Maps"), box-filtered down a mip chain. A trilinear tap at level log2(w) is then the moments'
// mean over a footprint about w texels wide: the soft shadow costs two taps a light whatever the
// penumbra, and no branch (llvmpipe runs both sides of every branch). It follows percentage-closer
// soft shadows (Fernando 2005): a blocker search over the largest penumbra a blocker could cast,
// then the visible fraction over the penumbra of a distant disk of angular radius sigma,
//   penumbra width = 2 (d_receiver - d_blocker) tan(sigma)     (d along the light direction),
// each read from a footprint's moments by one model (shadowBlockers), as Yang et al. 2010
// ("Variance Soft Shadow Mapping") do with variance moments.
// Needs shared_constants.glsl (units, kMaxEngineLights, kShadowExponent).
//
// The shadow mask (engine/gl/shadow_mask.h): on a single-sample target the renderer computes every
// receiver pixel's visibilities once, in a full-screen pass (shadow_mask.frag) over the visible
// surfaces' positions and geometric normals (shadow_surface.frag), and the lit pass reads them back
// (SHADOW_MASK 1: its own texel of a mask at the frame's resolution; 2: a coarser mask upsampled,
// upsampledShadowMask; 3: a planar ground's own visibility texture, groundShadowVisibilities). A
// software rasteriser shades in blocks of pixels, which the small triangles of a dense mesh fill
// poorly; the full-screen pass fills them (docs/engine.md "Shadows").

#include "light_directions.glsl"

#ifndef SHADOW_MASK
#define SHADOW_MASK 0
#endif
// The frame's shadow mask (shadow_mask.frag's MASK_BITS): at the frame's resolution lights 0 and 1
// in x, 2 and 3 in y, two unorm16 each; coarser, light i in byte i of x.
layout(binding = kTextureUnitShadowMask) uniform usampler2D shadowMask;
// SHADOW_MASK 2: the mask is coarser than the frame. Its pixels' window depths (the surface pass's
// depth buffer; 1 where no receiver was drawn), and mask pixels per frame pixel along x and y.
layout(binding = kTextureUnitShadowMaskDepth) uniform sampler2D shadowMaskDepth;
uniform vec2 shadowMaskScale;

#if SHADOW_MASK == 2
// This pixel's visibilities from a coarser mask, upsampled with its depth (shadow_mask.h): the 4
// mask pixels around the pixel's centre with their bilinear weights, each kept only where its
// depth is the lit pixel's surface's there. A planar surface's window depth is affine in screen
// position, so the lit pixel's own depth extrapolated along its screen gradient predicts each
// mask pixel's depth exactly on the same plane (and to second order on a curved one); a mask
// pixel off by more than kMaskDepthTolerance pixels' worth of that gradient (plus a floor for the
// depth's rounding) shows another surface (an occluder's silhouette, the ground behind it) and
// is dropped. Where all 4 are dropped (a sliver no mask pixel landed on), the one of nearest
// depth. `depthGradient`: dFdx and dFdy of gl_FragCoord.z, taken by the caller in uniform
// control flow.
const float kMaskDepthTolerance = 1.5;
const float kMaskDepthFloor = 2e-6;
vec4 upsampledShadowMask(vec2 depthGradient) {
  vec2 q = gl_FragCoord.xy * shadowMaskScale - 0.5;
  vec2 base = floor(q);
  vec2 f = q - base;
  // The 2 x 2 mask pixels from base, gathered at the corner they share (no rounding can pick other
  // pixels): their depths, and their visibilities (light i in byte i: shadow_mask.frag's MASK_BITS
  // 8). Gather's order: (0, 1), (1, 1), (1, 0), (0, 0).
  vec2 corner = (base + 1.0) / vec2(textureSize(shadowMaskDepth, 0));
  vec4 depths = textureGather(shadowMaskDepth, corner, 0);
  uvec4 packedMask = textureGather(shadowMask, corner, 0);
  float tolerance = kMaskDepthTolerance * (abs(depthGradient.x) + abs(depthGradient.y)) + kMaskDepthFloor;
  // Each mask pixel's centre in frame pixels, relative to this pixel's centre: the depth predicted there.
  vec2 step = 1.0 / shadowMaskScale;
  vec2 offset0 = (base + 0.5) * step - gl_FragCoord.xy;
  float predicted = gl_FragCoord.z + dot(depthGradient, offset0);
  vec2 dz = depthGradient * step;
  vec4 error = abs(depths - (predicted + vec4(dz.y, dz.x + dz.y, dz.x, 0.0)));
  vec4 weights = vec4((1.0 - f.x) * f.y, f.x * f.y, f.x * (1.0 - f.y), (1.0 - f.x) * (1.0 - f.y));
  weights *= vec4(lessThanEqual(error, vec4(tolerance)));
  // None on the pixel's surface: the nearest in depth.
  if (dot(weights, vec4(1.0)) <= 1e-4)
    weights = vec4(equal(error, vec4(min(min(error.x, error.y), min(error.z, error.w)))));
  vec4 sum = vec4(0.0);
  for (int k = 0; k < 4; ++k) sum += weights[k] * unpackUnorm4x8(packedMask[k]);
  return sum / dot(weights, vec4(1.0));
}
#endif

layout(binding = kTextureUnitShadowDepth) uniform sampler2DArray shadowMoments;  // trilinear
// Light i's map: world -> (u, v, depth) in [0, 1] (depth 0 on the side of the light). "World" in the
// engine's shaders is render space (engine/gl/render_space.h): world space moved by the scene's centre.
uniform mat4 shadowFromWorld[kMaxEngineLights];
// World extent of the map: x, y the sides along u and v, z the depth range; w the texel's side.
uniform vec4 shadowExtent[kMaxEngineLights];
// A receiver plane's normal g -> h, |h.xy| / |h.z| the world slope of the map's depth along the
// plane (the depth is measured from a flat ground's plane where there is one: shadow_maps.h).
uniform mat3 shadowSlopeFromNormal[kMaxEngineLights];

// Bias, in texels of the map: a constant depth offset, and the receiver moved along its geometric
// normal (docs/engine.md "Shadows" says how they were chosen).
const float kShadowDepthBiasTexels = 1.0;
const float kShadowNormalOffsetTexels = 0.75;
const float kPenumbraFilterScale = 1.25;
// The trilinear tap's footprint against a disk: level L averages 2^L texels and the bilinear
// interpolation between its texels widens that to a quadratic B-spline of standard deviation
// 2^L / 2 that reaches 1.5 x 2^L texels from its centre; a disk of radius R has R / 2 and reaches
// R. The penumbra's tap is at level log2(R / kPenumbraFilterScale): a B-spline of the disk's own
// deviation (scale 1) reaches half as far again as the disk, past the edge of a caster about as
// wide as its penumbra, and the centre of that caster's shadow came out lit (the bunny's head and
// ears under `studio`: 12% of the key lamp seen where the reference sees 7.6%). 1.25 reaches 1.2 R
// with 0.8 of the deviation (docs/engine.md "Shadows" gives what 1, 1.25 and 1.5 measured).
// Both taps read the mean moments of their footprint; every pixel pays the same two taps.

// The blockers in a footprint, from its mean moments `moments` at receiver depth z: the model is a
// fraction f of the footprint at one depth z - x / c and the rest at the receiver's depth, which
// has mean depth z - f x / c and mean exp(c (d - z)) = 1 - f (1 - exp(-x)). Solving the two for
// x (the root of 1 - exp(-x) = q x, q = b / (c a) below, in the closed form p (1/q + 1 + 0.36 p),
// p = 1 - q: its f within 0.1% of the exact root's over [1e-4, 0.9999], with no exp or Newton
// step, which llvmpipe pays per pixel and light; docs/engine.md "Shadows") gives f also where a
// blocker is so close to the receiver that the exponential test alone would leak (a contact
// shadow). Returns f and the blockers' separation z - d_blocker = (z - mean depth) / f.
// `spread`: c times the receiver plane's depth change over the footprint's standard deviation; a
// plane alone then has mean exp(c (d - z)) = exp(spread^2 / 2) (the exponential is convex), which
// is divided out so that a tilted receiver is not taken for a lit one in front of its blockers.
vec2 shadowBlockers(vec2 moments, float z, float spread) {
  float a = z - moments.x;
  float b = 1.0 - moments.y * exp(kShadowExponent * (1.0 - z) - 0.5 * spread * spread);
  bool blocked = a > 0.0 && b > 0.0;
  float q = clamp(blocked ? b / (kShadowExponent * a) : 1.0, 1e-4, 0.9999);
  float p = 1.0 - q;
  float x = p * (1.0 / q + 1.0 + 0.36 * p);
  // No blocker lies in front of the map's near side (x <= c z). Where the mean depth is not in
  // front of the receiver (a footprint that also holds surfaces far behind it), the exponential
  // test alone: f = b.
  x = blocked ? min(x, kShadowExponent * z) : 0.0;
  float f = clamp(a > 0.0 ? b / max(1.0 - exp(-x), 1e-6) : b, 0.0, 1.0);
  // The blockers' separation from the mean depth, a = f (z - d_blocker).
  return vec2(f, blocked ? clamp(a / max(f, 1e-3), 0.0, z) : 0.0);
}

// The fraction of light i's disk visible from `position` (geometric normal g, facing the light:
// g.l > 0), angular radius sigma (tanSigma).
float shadowVisibility(int i, vec3 position, vec3 g, float tanSigma) {
  vec4 extent = shadowExtent[i];
  float texel = extent.w;
  vec3 s = (shadowFromWorld[i] * vec4(position + g * (kShadowNormalOffsetTexels * texel), 1.0)).xyz;
  // Receivers beyond the map's depth range are on the ground outside the objects' footprint.
  float z = min(s.z - kShadowDepthBiasTexels * texel / extent.z, 1.0);
  float depthToTexels = extent.z * tanSigma / texel;  // penumbra half-width per unit of depth, texels
  // The receiver plane's depth change per texel across the map (its slope clamped at 10: 84
  // degrees where the depth is along the light), times c and the footprint's standard deviation
  // per texel of radius (1/2: level log2(R)). On a flat ground the depth is constant: no spread.
  vec3 h = shadowSlopeFromNormal[i] * g;
  float slope = min(length(h.xy), 10.0 * abs(h.z)) / max(abs(h.z), 1e-6);
  float spreadPerTexel = 0.5 * kShadowExponent * slope * texel / extent.z;
  // Blocker search: over radius z tan(sigma), the penumbra of a blocker at the map's near side. The
  // tap's B-spline reaches 1.5 x 2^L texels from its centre, hence level log2(radius / 1.5).
  float searchRadius = max(z * depthToTexels / 1.5, 1.0);
  vec2 search = shadowBlockers(textureLod(shadowMoments, vec3(s.xy, float(i)), log2(searchRadius)).rg, z,
                               spreadPerTexel * searchRadius);
  // The penumbra's half width from the blockers' depth, over kPenumbraFilterScale; at least a texel.
  float radius = max(search.y * depthToTexels / kPenumbraFilterScale, 1.0);
  vec2 filtered = shadowBlockers(textureLod(shadowMoments, vec3(s.xy, float(i)), log2(radius)).rg, z,
                                 spreadPerTexel * radius);
  return 1.0 - filtered.x;
}


// The planar ground's visibilities (shadow_maps.h GroundVisibilityFrame): light i's in component
// i of a texture over the ground's plane (shadow_ground.frag), read bilinearly at the point.
layout(binding = kTextureUnitShadowGround) uniform sampler2D shadowGroundVisibility;
uniform vec3 groundVisibilityOrigin, groundVisibilityU, groundVisibilityV;
vec4 groundShadowVisibilities(vec3 position) {
  vec3 p = position - groundVisibilityOrigin;
  return textureLod(shadowGroundVisibility, vec2(dot(p, groundVisibilityU), dot(p, groundVisibilityV)), 0.0);
}

// The visibility of drawn light i from `position`, with `geometric` the surface's geometric normal
// (either side: it is turned towards the light).
float lightVisibility(int i, vec3 position, vec3 geometric) {
  vec3 l = lightDirection[i];
  vec3 g = dot(geometric, l) < 0.0 ? -geometric : geometric;
  return shadowVisibility(i, position, g, lightCosSin[i].y / max(lightCosSin[i].x, 1e-4));
}

// lightVisibility of each drawn light in component i (1 past lightCount): the mask's texel.
vec4 shadowVisibilities(vec3 position, vec3 geometric) {
  vec4 visibility = vec4(1.0);
  for (int i = 0; i < lightCount; ++i) visibility[i] = lightVisibility(i, position, geometric);
  return visibility;
}
