#version 450 core
// The environment seen directly behind the objects: the camera ray of each pixel looked up in the
// lat-long map through the pixel's footprint (sampleLatLongFootprint), with the same rotation as
// every other lookup. Alpha 0 (no object).

#include "shared_constants.glsl"
#include "latlong_footprint.glsl"

in vec2 ndc;

uniform mat4 inverseViewProjection;
layout(binding = kTextureUnitLatLong) uniform sampler2D latLongMap;
uniform vec2 latLongRotation;
uniform float latLongIntensity;

layout(location = 0) out vec4 fragColor;

void main() {
  // Two points of the pixel's ray, unprojected (the camera's primaryRay, camera.h).
  vec4 nearPoint = inverseViewProjection * vec4(ndc, -1.0, 1.0);
  vec4 farPoint = inverseViewProjection * vec4(ndc, 1.0, 1.0);
  vec3 direction = farPoint.xyz / farPoint.w - nearPoint.xyz / nearPoint.w;
  fragColor = vec4(latLongIntensity * sampleLatLongFootprint(latLongMap, rotateAboutY(direction, latLongRotation)), 0.0);
}
