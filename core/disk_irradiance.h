#pragma once
// Irradiance from a disk light: a cap of directions of angular radius r, of uniform radiance L,
// whose centre makes the angle theta with the surface normal (a distant sphere or disk light;
// the extracted suns of environment_lights.h). docs/dominant-lights.md.
//
// With the cap wholly above the horizon (theta <= pi/2 - r) E = pi sin^2(r) cos(theta) L; wholly
// below (theta >= pi/2 + r) E = 0; across the horizon the part above it is integrated exactly:
//   x = cot(r), y = -x cot(theta),
//   E / L = (cos(theta) acos(y) - x sin(theta) sqrt(1 - y^2)) sin^2(r)
//           + atan(sin(theta) sqrt(1 - y^2) / x)
// (Snyder 1996, "Area light sources for real-time graphics", Microsoft Research technical report,
// as written in Lagarde & de Rousiers 2014, "Moving Frostbite to Physically Based Rendering 3.0",
// section 4.7 on sphere and disk lights, function illuminanceSphereOrDisk). Float arithmetic, as
// the GLSL twin. tests/core/disk_irradiance_test.cpp checks it against quadrature of the cap.

namespace iblkit {

// E / L for cos(theta) = cosTheta in [-1, 1] (clamped) and angular radius r = angularRadius
// (radians; clamped to [0, pi/2]: a cap wider than a hemisphere is taken as the hemisphere).
// Continuous in theta; 0 for r = 0.
float uniformDiskIrradiance(float cosTheta, float angularRadius);

}  // namespace iblkit
