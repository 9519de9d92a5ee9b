#pragma once
// The magma colour map (van der Walt and Smith, matplotlib 1.5, 2015): perceptually uniform, dark
// for no error and pale yellow for the largest, readable in greyscale and by colour-blind viewers.

#include <glm/glm.hpp>

namespace iblkit {

// Linear RGB of magma at t in [0,1] (clamped; NaN gives 0).
glm::vec3 magma(float t);

}  // namespace iblkit
