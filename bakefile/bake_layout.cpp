#include "bakefile/bake_layout.h"

#include "core/error.h"

namespace iblkit {

std::filesystem::path requireBakeFile(const std::filesystem::path& file) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) fail(file, "missing (incomplete bake folder?)");
  return file;
}

}  // namespace iblkit
