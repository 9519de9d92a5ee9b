#pragma once
// env/lights.json of a bake folder (bake_layout.h): the dominant lights of the environment
// (core/environment_lights.h, docs/dominant-lights.md), the extracted suns and the median-cut
// regions, world space with the map's intensity applied. docs/baker.md shows the file.
//
//   {"kind": "iblkit environment lights", "sunThreshold": t, "medianCutLevels": n,
//    "suns": [LIGHT...], "medianCut": [LIGHT...]}
//   LIGHT = {"direction": [x, y, z], "irradiance": [r, g, b], "radiance": [r, g, b],
//            "solidAngle": sr, "angularRadius": radians, "texels": [x0, y0, x1, y1],
//            "sh9": [[r, g, b] x 9]}

#include <filesystem>

#include "core/environment_lights.h"

namespace iblkit {

// Writes `lights` (numbers with 9 significant digits: floats read back to the last bit). Temp
// name, then rename. Throws Error("<path>: ...") for a non-finite value or when the file cannot be
// written; nothing is left under `path` then.
void writeEnvironmentLightsJson(const std::filesystem::path& path, const EnvironmentLights& lights);

// Reads what writeEnvironmentLightsJson wrote. Throws Error("<path>: <what>: <problem>") for a
// missing, unreadable or malformed file, naming the entry ("suns[1].direction: ..."): a value
// missing or of the wrong type, a non-finite number, a direction that is not unit length (within
// 1e-3), negative irradiance or radiance, a solid angle outside (0, 4 pi], an angular radius
// outside [0, pi], an empty or inverted texel rectangle, medianCutLevels outside [0, 12].
EnvironmentLights readEnvironmentLightsJson(const std::filesystem::path& path);

}  // namespace iblkit
