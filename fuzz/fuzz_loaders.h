#pragma once
// The loaders the fuzz targets drive (docs/robustness.md): each takes the bytes of one input
// file, hands them to the real library loader as a file of the right name, and reports whether
// the loader returned (true) or refused the input by throwing std::exception (false). Anything
// else (a crash, a sanitizer report, a hang, an exception of another type) is a finding.
// One function for the libFuzzer targets (fuzz/fuzz_<loader>.cpp) and for the corpus replay test
// of the normal build (tests/fuzz/fuzz_corpus_test.cpp), so both run exactly the same code.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "core/enum_names.h"

namespace iblkit::fuzz {

enum class Loader { Exr, Hdr, Png, Gltf, Scene, BakeRecord, Sh9, Texture, Lights, PassSum };

// The target names: fuzz_<name> is the libFuzzer program, fuzz/corpus/<name>/ its corpus.
inline constexpr EnumName<Loader> kLoaderNames[] = {
    {Loader::Exr, "exr"},     {Loader::Hdr, "hdr"},          {Loader::Png, "png"},  {Loader::Gltf, "gltf"},
    {Loader::Scene, "scene"}, {Loader::BakeRecord, "bake_record"}, {Loader::Sh9, "sh9"},
    {Loader::Texture, "texture"}, {Loader::Lights, "lights"}, {Loader::PassSum, "pass_sum"}};

// Writes `bytes` to a file in this process's scratch folder (under $TMPDIR, removed at exit),
// named as the loader expects (input.exr, input.hdr, input.png, input.glb or input.gltf by the
// "glTF" magic, scene.json, bake.json, sh9.json, texture.img, lights.json, pass.sum), and runs:
//   Exr: readExrLevels, then readExr of level 0 with PixelRepair::Keep; Hdr: readRadianceHdr;
//   Png: readPng; Gltf: loadGltf (Draco included); Scene: loadSceneFile (models it names are
//   loaded; environment files are only checked to exist; beside the scene lie model.gltf, one
//   triangle, env.hdr, 2 x 1, and albedo.png, 1 x 1, for it to name); BakeRecord: readBakeRecord; Sh9: readSh9Json;
//   Texture: readInputFile, then decodeTextureImage (PNG and JPEG through stb_image, WebP through
//   libwebp, the format by signature: the texture image decoders of glTF materials); Lights:
//   readEnvironmentLightsJson (env/lights.json); PassSum: readPassSum (a reference pass's sums,
//   reference/pass_sum.h).
// Warnings are silenced. With the environment variable IBLKIT_FUZZ_STRICT=1 a refusal must also
// be an iblkit::Error whose message is one line naming the input file, else it aborts.
// A refusal's message goes to *refusal when given.
bool runLoader(Loader loader, std::span<const std::uint8_t> bytes, std::string* refusal = nullptr);

}  // namespace iblkit::fuzz
