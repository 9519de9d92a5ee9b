#pragma once
// Attaching the baker's per-vertex visibility (vertex_visibility.h) to meshes as the attributes a
// bake folder stores (bakefile/vertex_attributes.h names and documents them).

#include <vector>

#include "baker/vertex_visibility.h"
#include "bakefile/vertex_attributes.h"
#include "core/environment_lights.h"
#include "core/mesh.h"

namespace iblkit {

// Stores visibility[i] in meshes[i].attributes under the names above (replacing any present).
// Throws Error("vertex visibility attributes: ...") when the counts of meshes or vertices differ.
void attachVisibilityAttributes(std::vector<Mesh>& meshes, const std::vector<MeshVisibility>& visibility);

// The suns whose bounced light a bake stores: the directions of the first kMaxSunBounceLights of
// lights.suns (brightest first), the suns the engine draws first.
std::vector<glm::vec3> sunBounceDirections(const EnvironmentLights& lights);

// Stores bounce[i] (bakeSunBounce) in meshes[i].attributes as _SUNBOUNCE. Throws like
// attachVisibilityAttributes.
void attachSunBounceAttribute(std::vector<Mesh>& meshes, const std::vector<std::vector<glm::vec4>>& bounce);

// What iblkit-bake and the in-memory bake store for the engine's lights modes: bakeSunBounce of
// the suns of `lights` (sunBounceDirections) with `settings` (its albedos required, its progress
// not called), attached as _SUNBOUNCE. Nothing when there is no sun.
void attachSunBounce(std::vector<Mesh>& meshes, const EnvironmentLights& lights, VisibilitySettings settings,
                     VisibilityStatistics* statistics = nullptr);

}  // namespace iblkit
