#pragma once
// Tangent frames for normal mapping, as glTF 2.0 asks when a primitive has a normal texture and no
// TANGENT: the MikkTSpace algorithm (M. S. Mikkelsen, "Simulation of Wrinkled Surfaces Revisited",
// MSc thesis, University of Copenhagen, 2008, chapter 4), written from the thesis, not vendored.
// Per triangle corner: the tangent and bitangent from the triangle's positions and uvs, projected
// onto the plane of the corner's normal, weighted by the corner's angle; corners sharing a vertex
// and the same handedness are averaged. Vertices are never split or reordered (iblkit keeps the
// primitive's vertex order, mesh.h), so where one vertex joins triangles of both handednesses
// (mirrored uv seams that share vertices) it takes the handedness of the larger summed angle;
// docs/material-model.md "Tangents" names this difference from MikkTSpace.
// Handedness is glTF's: w cross(n, t) points up the image (-v, glTF uv (0, 0) being the image's
// top-left), the +Y of normal textures; MikkTSpace's sign assumes v up, so it is negated.
// An upright image on a counter-clockwise quad gets t = +u, w = +1.

#include <cstddef>

#include "core/mesh.h"

namespace iblkit {

// Fills mesh.tangents from mesh.normals and the uv set `texCoord` (0 or 1) of the mesh, unless the
// mesh already has tangents. Degenerate uv triangles contribute nothing; a vertex without any
// contribution gets a tangent orthogonal to its normal (Frame::fromZ's x) with w = +1.
// Returns the number of tangents generated (0 when the mesh had them or has no such uv set).
std::size_t generateTangents(Mesh& mesh, int texCoord = 0);

}  // namespace iblkit
