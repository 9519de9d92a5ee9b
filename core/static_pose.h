#pragma once
// The static pose of a deformable glTF mesh (glTF 2.0 sections 3.7.2.2 "Morph Targets" and 3.7.3
// "Skins"): what a viewer shows of a skinned or morphed asset without playing an animation.
// Morph targets at their default weights (the node's `weights`, else the mesh's) add their
// displacements first; a skin then moves every vertex by the weighted sum of its joints' matrices
// (joint world transform times inverse bind matrix), applied by transformMeshPerVertex (core/mesh.h).
// No animation is read: the pose is the one the node hierarchy holds.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "core/mesh.h"

namespace iblkit {

// One morph target's displacements (glTF target attributes POSITION, NORMAL, TANGENT; each empty
// when the target has none, else one per vertex).
struct MorphTarget {
  std::vector<glm::vec3> positions, normals, tangents;
};

// Adds sum_i weights[i] * targets[i] to the mesh's positions, normals and tangents' xyz (normals
// and tangents are re-normalised after, by whoever transforms the mesh next). Weights of 0 change
// nothing; extra weights or targets beyond the shorter list are ignored.
void applyMorphTargets(Mesh& mesh, std::span<const MorphTarget> targets, std::span<const float> weights);

// Up to eight influences per vertex (JOINTS_0/WEIGHTS_0 and JOINTS_1/WEIGHTS_1).
struct VertexInfluences {
  std::array<std::uint32_t, 8> joints{};
  std::array<float, 8> weights{};
};

// The skinning matrix of each vertex: sum_k w_k jointMatrices[j_k], the weights divided by their
// sum (glTF asks for a sum of 1; exporters round). A vertex whose weights sum to 0 keeps the
// identity. Joint indices must be below jointMatrices.size() (the loader checks them).
std::vector<glm::mat4> skinningMatrices(std::span<const VertexInfluences> influences,
                                        std::span<const glm::mat4> jointMatrices);

}  // namespace iblkit
