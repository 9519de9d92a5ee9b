#pragma once
// Private to the glTF loader and writer (includes tinygltf; do not include from public headers):
// reading a glTF file into a tinygltf::Model safely, and reading accessors with every index and
// byte range checked. All failures throw iblkit::Error naming the file.

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <span>
#include <string>
#include <vector>

#include "core/tiny_gltf_config.h"

namespace iblkit::gltf {

// Parses a .gltf (external or data-URI buffers) or .glb file. Before tinygltf reads anything,
// every external buffer URI is checked to stay inside the file's folder, and tinygltf only ever
// sees files inside that folder. tinygltf errors become one-line Errors; its warnings go to warn().
// Extensions listed in extensionsRequired must be ones iblkit understands or may ignore.
// KHR_draco_mesh_compression primitives are decoded into plain accessors (new buffers and buffer
// views; the compressed views are left unreferenced) and the extension is removed, so callers
// only ever see plain geometry in the decoder's vertex order.
tinygltf::Model readModel(const std::filesystem::path& file);

// The bytes of buffer view `index`, after checking that the view and its buffer exist and that
// the view lies inside the buffer.
std::span<const unsigned char> bufferViewBytes(const tinygltf::Model& model, int index,
                                               const std::filesystem::path& file);

// The encoded bytes of image `index` (glTF 2.0 section 5.17): its buffer view, its data: URI
// (base64 or percent-encoded; media types tinygltf does not know, image/webp among them, are
// decoded here), or the file its uri names. A file uri is percent-decoded and must stay inside the
// glTF file's folder, as buffer URIs must (no '..' leaving it, no absolute paths, no other URI
// schemes); the file is read through readInputFile. *declaredMimeType gets the image's mimeType
// (buffer view) or the data URI's media type, "" when the file declares none; *source gets the
// file the bytes came from (the image file, or `file` itself). `what` names the image in messages.
std::vector<std::uint8_t> imageBytes(const tinygltf::Model& model, int index, const std::filesystem::path& file,
                                     const std::string& what, std::string* declaredMimeType,
                                     std::filesystem::path* source);

// Components per element of a SCALAR, VEC2, VEC3 or VEC4 accessor; 0 for matrices.
int componentCount(int accessorType);

// Reads accessor `accessor` (named `semantic` in errors, e.g. "POSITION") as floats, converting
// the integer component types allowed by KHR_mesh_quantization (normalised per glTF 2.0 section
// 3.11, or plain integer values). `components` is the required element size (1..4). Honours
// byteStride and sparse accessors (glTF 2.0 section 3.6.2.3: the base view, or zeros without one,
// with the sparse elements replaced; indices must strictly increase and stay below count, and the
// expanded accessor within 256 MiB); rejects a missing buffer view on a dense accessor and
// out-of-range reads.
std::vector<float> readFloats(const tinygltf::Model& model, int accessor, int components,
                              const std::string& semantic, const std::filesystem::path& file);

// Reads an index accessor (SCALAR, unsigned byte, short or int) as 32-bit indices.
// Reads a MAT4 float accessor (skin.inverseBindMatrices), column-major as glTF and glm store it.
std::vector<glm::mat4> readMatrices(const tinygltf::Model& model, int accessor, const std::string& semantic,
                                    const std::filesystem::path& file);

std::vector<std::uint32_t> readIndices(const tinygltf::Model& model, int accessor,
                                       const std::filesystem::path& file);

}  // namespace iblkit::gltf
