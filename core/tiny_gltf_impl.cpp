// The single translation unit that compiles tinygltf's implementation, with the configuration of
// tiny_gltf_config.h (every other file includes that header without TINYGLTF_IMPLEMENTATION).
#define TINYGLTF_IMPLEMENTATION
#include "core/tiny_gltf_config.h"
