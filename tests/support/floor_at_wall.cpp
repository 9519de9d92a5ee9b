#include "support/floor_at_wall.h"

#include "core/procedural_mesh.h"

namespace iblkit::test {

std::vector<Mesh> floorAtWall() {
  constexpr float d = 1e-3f;
  Mesh floor;
  floor.name = "floor";
  floor.positions = {{d, 0, 0}, {d, 0, 5}, {5, 0, 5}, {5, 0, -5}, {d, 0, -5}};
  floor.normals.assign(5, glm::vec3(0, 1, 0));
  floor.indices = {0, 1, 2, 0, 2, 3, 0, 3, 4};
  return {floor, toMesh(box(glm::vec3(-0.5f, 10.0f, 0.0f), glm::vec3(1.0f, 20.0f, 40.0f)), "wall")};
}

}  // namespace iblkit::test
