#pragma once
// A minimal 16-bit PNG writer for tests (stb_image_write writes 8-bit only): uncompressed
// deflate blocks, big-endian samples. Grey (1) or RGB (3) channels.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace pbr::test {

void writePng16(const std::filesystem::path& path, int width, int height, int channels,
                const std::vector<std::uint16_t>& samples);

}  // namespace pbr::test
