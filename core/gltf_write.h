#pragma once
// Writing per-vertex results (baked occlusion, irradiance...) back into a glTF file as custom
// vertex attributes, which gltf_load.h reads back into Mesh::attributes.

#include <filesystem>
#include <string>
#include <vector>

namespace iblkit {

// Values for one glTF primitive, in that primitive's own vertex order (the order of the Mesh
// loaded from it: MeshSource::mesh / primitive).
struct PrimitiveAttributes {
  int meshIndex = 0;        // glTF mesh index
  int primitiveIndex = 0;   // primitive index within the mesh
  std::string name;         // attribute name; must start with '_' (glTF 2.0 section 3.7.2.1)
  int componentCount = 1;   // 1..4: written as SCALAR, VEC2, VEC3 or VEC4 float accessors
  std::vector<float> data;  // componentCount floats per vertex, finite
};

// Copies the glTF file `input` to `output` (.glb, or .gltf with its buffer embedded as a data URI;
// chosen by the output's extension, case-insensitively) with the given attributes added; an
// attribute already present under the same name is replaced. Nodes, materials, cameras, extras
// and extensions are kept. Draco-compressed primitives are written as plain (decoded) accessors
// and KHR_draco_mesh_compression is removed; all buffers are merged into one, and buffer views
// no accessor or image uses (such as the Draco streams) are dropped. External image URIs are
// copied as they are (relative to the output). The file is written under a temporary name and
// renamed, so `output` is either complete or untouched; it may equal `input`.
// Throws Error for a bad input file (as gltf_load.h), a name not starting with '_', a component
// count outside 1..4, a missing mesh or primitive, a data size that does not match the
// primitive's vertex count, or a non-finite value.
void writeGltfWithAttributes(const std::filesystem::path& input, const std::filesystem::path& output,
                             const std::vector<PrimitiveAttributes>& attributes);

}  // namespace iblkit
