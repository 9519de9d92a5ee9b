#pragma once
// Private: the one way iblkit includes tinygltf (Debian's libtinygltf-dev 2.7.0 header; its shared
// library is not linked, tiny_gltf_impl.cpp compiles the implementation). Include this from .cpp
// files only, never from a public header: the header is large and its types stay internal.
//
// tinygltf's image codecs and external image loading are compiled out: images are read and
// decoded by gltf_model.cpp (imageBytes, with the folder rule buffers follow) and texture_image.h
// (stb_image and libwebp, sizes checked before decoding). Draco is deliberately NOT enabled here (no TINYGLTF_ENABLE_DRACO):
// tinygltf 2.7.0 decodes KHR_draco_mesh_compression without bounds checks on the indices it
// follows and ignores decode failures, so gltf_model.cpp decodes Draco itself with full checks.

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>
