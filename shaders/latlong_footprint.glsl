// The lat-long map read through a pixel's footprint (screen derivatives: fragment shaders only;
// environment.glsl is shared with the vertex stage).

#include "environment.glsl"

// The change of latLongUv(d) for a small change e of d (any length of d), with u's change measured
// along the row's circle: u = 0.5 - atan(x, z) / 2pi and v = 0.5 - atan(y, r) / pi (r = |(x, z)|)
// differentiated, u's times sin(theta) = r / |d|. A row near a pole is a small circle that u goes
// round in full, so a step in u there is a small angle: without the factor a pixel near the pole
// (a mirror sphere reflects both poles) asked for the map's coarsest levels, its whole rows
// averaged (errors of 24% measured on a smooth sky), where the path tracer's pixel sees a small
// solid angle. Analytic, so the seam's jump of u from 1 to 0 is no derivative.
vec2 latLongUvChange(vec3 d, vec3 e) {
  float r2 = d.x * d.x + d.z * d.z, r = sqrt(r2), l2 = r2 + d.y * d.y;
  float du = -(d.z * e.x - d.x * e.z) / (2.0 * kPi * max(r, 1e-20) * sqrt(max(l2, 1e-30)));
  float dr = (d.x * e.x + d.z * e.z) / max(r, 1e-20);
  float dv = -(r * e.y - d.y * dr) / (kPi * max(l2, 1e-30));
  return vec2(du, dv);
}

// The side of the square the lookup filters over, as a fraction of the side of the square of the
// pixel's footprint's area. GL's trilinear lookup blurs more than the path tracer's plain average
// over the pixel (box-filtered levels with a bilinear tent on top). Measured on a mirror sphere at
// 320 x 180 against 256-spp references (docs/engine.md "The map through a pixel"), FLIP for an
// 8192-wide map with texel-scale detail, `sky` and `studio`: 1: 0.024, 0.018, 0.058; 0.7: 0.020,
// 0.015, 0.048; 0.6: 0.020, 0.018, 0.055; level 0 alone (before): 0.111, 0.024, 0.083.
const float kLatLongFootprintScale = 0.7;

// The map in direction d as a pixel sees it: latLongUv(d) read through the pixel's footprint (the
// change of uv across the pixel from the screen derivatives of d), trilinearly between the map's
// box-filtered levels (textureGrad) at the level of a square of the footprint's area times
// kLatLongFootprintScale. Where that is less than a texel (the bundled 512-wide maps behind a
// 320 x 180 frame) it is level 0, sampleLatLongBilinear itself; where many texels fall in one pixel
// (an 8192-wide photograph behind the same frame, any map in a mirror sphere's shrunken
// reflection) it averages them, as the path tracer's samples over the pixel do, where level 0
// alone aliased. The area, not the longer side that GL's own level takes: a mirror sphere's
// reflection near its rim is squeezed many times over in one direction, and the longer side
// blurred it along the other too. Not anisotropic filtering: llvmpipe's anisotropic lookups of the
// float map left bright specks. Uniform control flow only (derivatives).
vec3 sampleLatLongFootprint(sampler2D latLong, vec3 d) {
  vec2 size = vec2(textureSize(latLong, 0));
  vec2 gx = latLongUvChange(d, dFdx(d)) * size, gy = latLongUvChange(d, dFdy(d)) * size;
  float side = kLatLongFootprintScale * sqrt(abs(gx.x * gy.y - gx.y * gy.x));
  return textureGrad(latLong, latLongUv(d), vec2(side / size.x, 0.0), vec2(0.0, side / size.y)).rgb;
}
