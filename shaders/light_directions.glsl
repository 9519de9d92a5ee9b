// The engine's disk lights as the shadows need them (renderer.cpp sets them): the world direction
// towards each and the cos and sin of its angular radius. dominant_lights.glsl adds the rest.
// LIGHT_COUNT: a constant of the program (renderer.cpp compiles one per count), so that the loops
// over the lights unroll with constant indices.
#ifndef LIGHT_DIRECTIONS_GLSL
#define LIGHT_DIRECTIONS_GLSL
#ifndef LIGHT_COUNT
#define LIGHT_COUNT kMaxEngineLights
#endif
const int lightCount = LIGHT_COUNT;
// SUN_BOUNCE: 1 where the program reads the suns' bounce the bake stored per vertex (_SUNBOUNCE,
// mesh.vert's lightsBounceAt), 0 where it estimates it.
#ifndef SUN_BOUNCE
#define SUN_BOUNCE 0
#endif
uniform vec3 lightDirection[kMaxEngineLights];
uniform vec2 lightCosSin[kMaxEngineLights];
#endif
