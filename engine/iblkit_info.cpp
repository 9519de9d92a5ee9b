// iblkit-info FILE...: prints what iblkit reads from images, environment maps, glTF models and
// scene files: size, channels and pixel statistics, or meshes, triangles and materials.
#include <cstdio>

int main() {
  std::puts("iblkit-info: not built yet");
  return 0;
}
