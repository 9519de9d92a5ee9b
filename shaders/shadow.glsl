// Shadow maps of the engine's disk lights (docs/engine.md "Shadows", engine/gl/shadow_maps.h): one
// orthographic depth map per light, fitted to the scene, filtered with percentage-closer soft
// shadows (Fernando 2005, "Percentage-Closer Soft Shadows", SIGGRAPH sketch): a blocker search,
// then PCF over the penumbra of a distant disk of angular radius sigma,
//   penumbra width = 2 (d_receiver - d_blocker) tan(sigma)     (d along the light direction),
// with the receiver's plane followed by every tap (Isidoro 2006, "Shadow Mapping: GPU-based Tips and
// Techniques", GDC: receiver plane depth bias), here from the geometric normal.
// Needs shared_constants.glsl (units, kMaxEngineLights) and environment.glsl (kPi).

layout(binding = kTextureUnitShadowDepth) uniform sampler2DArray shadowDepths;            // raw depths
layout(binding = kTextureUnitShadowCompare) uniform sampler2DArrayShadow shadowCompare;   // compare mode
// Light i's map: world -> (u, v, depth) in [0, 1] (depth 0 on the side of the light).
uniform mat4 shadowFromWorld[kMaxEngineLights];
// World extent of the map: x, y the sides along shadowRight / shadowUp, z the depth range; w the
// texel's side (the larger of x, y over the map's size).
uniform vec4 shadowExtent[kMaxEngineLights];
uniform vec3 shadowRight[kMaxEngineLights];
uniform vec3 shadowUp[kMaxEngineLights];

// Bias, in texels of the map: a constant depth offset, and the receiver moved along its geometric
// normal (docs/engine.md "Shadows" says how they were chosen).
const float kShadowDepthBiasTexels = 1.0;
const float kShadowNormalOffsetTexels = 0.75;

// Interleaved gradient noise (Jimenez 2014, "Next Generation Post Processing in Call of Duty:
// Advanced Warfare", SIGGRAPH course): a per-pixel rotation of the tap pattern, so that few taps
// give noise rather than bands.
float interleavedGradientNoise(vec2 pixel) {
  return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
}

// The taps on the unit disk, uniform in area: golden-angle (Vogel 1979) spirals of
// kBlockerSearchTaps and kPcfTaps points, tap i at radius sqrt((i + 0.5) / n) and angle
// i 2.39996 (vogelDiskTaps in shadow_maps.cpp), turned per pixel by a 2 x 2 rotation.
uniform vec2 blockerSearchTaps[kBlockerSearchTaps];
uniform vec2 pcfTaps[kPcfTaps];

// The per-pixel rotation of the taps, from interleavedGradientNoise.
mat2 shadowTapRotation() {
  float angle = 2.0 * kPi * interleavedGradientNoise(gl_FragCoord.xy);
  float c = cos(angle), s = sin(angle);
  return mat2(c, s, -s, c);
}

// A receiver in light i's map: its (u, v, depth) moved along its geometric normal, and its plane's
// depth change per unit of uv (Isidoro 2006), the slope clamped at 84 degrees.
struct ShadowReceiver {
  vec3 s;
  vec2 depthPerUv;
};

ShadowReceiver shadowReceiver(int i, vec3 position, vec3 g, vec3 l) {
  vec4 extent = shadowExtent[i];
  ShadowReceiver r;
  r.s = (shadowFromWorld[i] * vec4(position + g * (kShadowNormalOffsetTexels * extent.w), 1.0)).xyz;
  float gl = max(dot(g, l), 0.1);
  r.depthPerUv = vec2(extent.x * dot(g, shadowRight[i]), extent.y * dot(g, shadowUp[i])) / (gl * extent.z);
  return r;
}

// PCSS (Fernando 2005) at receiver r of light i, angular radius sigma (tanSigma), the taps turned by
// `rotation`: the fraction of the disk visible.
float pcssVisibility(int i, ShadowReceiver r, float tanSigma, mat2 rotation) {
  vec4 extent = shadowExtent[i];
  float texel = extent.w;
  float receiver = r.s.z - kShadowDepthBiasTexels * texel / extent.z;
  vec2 uvPerWorld = 1.0 / extent.xy;
  // Blocker search over the largest penumbra a blocker could cast here (one at depth 0).
  float searchWorld = max(r.s.z * extent.z * tanSigma, 1.5 * texel);
  float blockers = 0.0, blockerDepth = 0.0;
  for (int k = 0; k < kBlockerSearchTaps; ++k) {
    vec2 offset = (rotation * blockerSearchTaps[k]) * searchWorld * uvPerWorld;
    float d = texture(shadowDepths, vec3(r.s.xy + offset, float(i))).r;
    if (d < receiver + dot(r.depthPerUv, offset)) {
      blockers += 1.0;
      blockerDepth += d;
    }
  }
  if (blockers == 0.0) return 1.0;
  blockerDepth /= blockers;
  // The penumbra's half width at this receiver; at least a texel (plain PCF where it is sharp).
  float filterWorld = max((r.s.z - blockerDepth) * extent.z * tanSigma, texel);
  float lit = 0.0;
  for (int k = 0; k < kPcfTaps; ++k) {
    vec2 offset = (rotation * pcfTaps[k]) * filterWorld * uvPerWorld;
    lit += texture(shadowCompare, vec4(r.s.xy + offset, float(i), receiver + dot(r.depthPerUv, offset)));
  }
  return lit / float(kPcfTaps);
}

// The fraction of light i's disk visible from `position` (geometric normal g, facing the light:
// g.l > 0), angular radius sigma (tanSigma). On llvmpipe every pixel pays the whole of it: a
// software rasteriser runs both sides of every branch (masked), so the early return without
// blockers saves nothing there (docs/engine.md "Shadows", the measured cost).
float shadowVisibility(int i, vec3 position, vec3 g, vec3 l, float tanSigma, mat2 rotation) {
  return pcssVisibility(i, shadowReceiver(i, position, g, l), tanSigma, rotation);
}
