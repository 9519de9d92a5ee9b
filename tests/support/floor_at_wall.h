#pragma once
// The baker tests' floor at a wall: a floor fan around vertex 0 at (1e-3, 0, 0), covering x in
// [1e-3, 5] and z in [-5, 5], facing +Y, beside a wall box whose +X face is the plane x = 0
// (20 high, 40 wide). Every direction from vertex 0 with x < 0 hits the wall: by symmetry half
// of its cosine-weighted hemisphere.

#include <vector>

#include "core/mesh.h"

namespace iblkit::test {

// {floor, wall}.
std::vector<Mesh> floorAtWall();

}  // namespace iblkit::test
