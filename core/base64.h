#pragma once
// RFC 4648 base64 (standard alphabet, with padding): the report page's embedded images (read back
// by the viewer's report cases) and the tests' data: URIs.
#include <cstdint>
#include <string>
#include <vector>

namespace iblkit {

std::string base64(const std::vector<std::uint8_t>& bytes);
// The inverse of base64; throws Error("base64: ...") for text that is not base64.
std::vector<std::uint8_t> base64Decode(const std::string& text);

}  // namespace iblkit
