#pragma once
// Base64 (RFC 4648, with padding) for data: URIs in self-contained HTML
// reports.
#include <cstdint>
#include <span>
#include <string>

namespace facet {

std::string base64_encode(std::span<const uint8_t> bytes);

}  // namespace facet
