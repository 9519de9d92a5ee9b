#pragma once
// RFC 4648 base64 (standard alphabet, with padding): the report page's embedded images and the
// tests' data: URIs.
#include <cstdint>
#include <string>
#include <vector>

namespace iblkit {

std::string base64(const std::vector<std::uint8_t>& bytes);

}  // namespace iblkit
