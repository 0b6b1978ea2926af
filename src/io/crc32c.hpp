#pragma once
// CRC-32C (Castagnoli, reflected polynomial 0x82F63B78), the checksum E57
// puts at the end of every page (iSCSI's, not zlib's CRC-32).

#include <cstddef>
#include <cstdint>

namespace occlusion::detail {

std::uint32_t crc32c(const unsigned char* data, std::size_t size);

}  // namespace occlusion::detail
