// Environment lookups, in the conventions of core (docs/conventions.md).

const float kPi = 3.14159265358979;

// R_y(angle) d: the right-handed rotation about +Y (takes +Z to +X for +90 degrees);
// cosSin = (cos(angle), sin(angle)).
vec3 rotateAboutY(vec3 d, vec2 cosSin) {
  return vec3(cosSin.x * d.x + cosSin.y * d.z, d.y, -cosSin.y * d.x + cosSin.x * d.z);
}

// latLongUv of core/latlong.h: lon = atan2(x, z), lat = atan2(y, hypot(x, z)),
// u = 0.5 - lon / 2pi, v = 0.5 - lat / pi (u = 0.5 is +Z, v = 0 is +Y).
vec2 latLongUv(vec3 d) {
  float lon = atan(d.x, d.z);
  float lat = atan(d.y, length(d.xz));
  return vec2(0.5 - lon / (2.0 * kPi), 0.5 - lat / kPi);
}

// sampleLatLongBilinear of core/latlong.h: bilinear between texel centres, u wrapping across the
// seam, v clamped to the centres of the first and last rows. The texture is uploaded with image
// row 0 first (v = 0 at t = 0), GL_REPEAT in s, GL_CLAMP_TO_EDGE in t, GL_LINEAR: at lod 0, which
// this reads explicitly, exactly that filter (its mip levels are for sampleLatLongFootprint,
// latlong_footprint.glsl).
vec3 sampleLatLongBilinear(sampler2D latLong, vec2 uv) { return textureLod(latLong, uv, 0.0).rgb; }

