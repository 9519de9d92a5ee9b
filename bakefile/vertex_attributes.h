#pragma once
// How baked vertex visibility is stored in glTF: custom per-vertex attributes (names starting
// with '_', glTF 2.0 section 3.7.2.1), float accessors, one value per vertex in the vertex order
// of the mesh. docs/baker.md documents the same table for the engine that reads them.
//
//   _AO          SCALAR  ambient occlusion in [0, 1] (fraction of cosine-weighted rays escaping)
//   _BENTNORMAL  VEC3    unit bent normal, world space
//   _BENTLENGTH  SCALAR  length of the mean escaping direction, in [0, 1] (visibility cone)
//   _SHT0        VEC3    SH transfer t0, t1, t2 (band 0 and the first two of band 1)
//   _SHT1        VEC3    t3, t4, t5
//   _SHT2        VEC3    t6, t7, t8
// with t_k in shBasis9's order (k = l(l+1) + m) and normalisation (baker/vertex_visibility.h).
// Optional (a bake of a map with suns; bakes older than it lack it, and the engine then estimates
// the bounce from the transfer):
//   _SUNBOUNCE   VEC4    the suns' bounced light b_i (baker/vertex_visibility.h bakeSunBounce) for
//                        the first four suns of env/lights.json, in its order; 0 past the last

#include <cstddef>
#include <filesystem>

#include "core/mesh.h"
#include "core/scene.h"
#include "core/spherical_harmonics.h"

namespace iblkit {

inline constexpr const char* kAmbientOcclusionAttribute = "_AO";
inline constexpr const char* kBentNormalAttribute = "_BENTNORMAL";
inline constexpr const char* kBentLengthAttribute = "_BENTLENGTH";
// _SHT0, _SHT1, _SHT2: three VEC3 attributes holding the nine transfer coefficients in order.
inline constexpr const char* kTransferAttributes[3] = {"_SHT0", "_SHT1", "_SHT2"};
inline constexpr const char* kSunBounceAttribute = "_SUNBOUNCE";
// The largest _SUNBOUNCE value a bake can write: each of its three passes adds at most 1 (albedo
// and the sunlight's cosine at most 1), so 3, with room for rounding.
inline constexpr float kMaxSunBounceValue = 3.01f;

// The nine transfer coefficients of vertex `vertex`, read back from _SHT0.._SHT2 (the inverse
// packing). Throws Error("vertex visibility attributes: ...") when an attribute is missing, is not
// VEC3, or has no such vertex.
ShBasis9 transferFromAttributes(const Mesh& mesh, std::size_t vertex);

// Every mesh of `scene` carries every attribute above, with its component count and one value per
// vertex. Throws Error("<file>: mesh '<name>' has no baked <attribute> attribute (not an iblkit-bake
// scene?)") otherwise. A _SUNBOUNCE, where there is one, must be VEC4 per vertex with values in
// [0, kMaxSunBounceValue] (Error("<file>: mesh '<name>': _SUNBOUNCE ...")).
void requireBakedAttributes(const Scene& scene, const std::filesystem::path& file);

}  // namespace iblkit
