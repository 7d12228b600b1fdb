#include "polar/platform/png_io.h"

#include "platform/png_file.h"

#include <cstdint>

// stb_image decodes PNG, and only PNG, here; stb_image_write encodes. Both come from Debian's
// libstb-dev as headers; their code is compiled into this file alone.
#define STBI_ONLY_PNG
#define STBI_NO_STDIO
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>
#define STBI_WRITE_NO_STDIO
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

namespace polar {
namespace {

// The renderer's fixed-point sprite code assumes sides below 2¹⁵, and nothing in the game is larger.
constexpr int kMaxSide = 32767;

void appendBytes(void* out, void* data, int size) {
    static_cast<std::string*>(out)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}

}  // namespace

Result<RgbaImage> loadPng(const std::string& path) {
    Result<std::string> file = readPngFile(path);
    if (!file) return file.error();
    const std::string& bytes = *file;
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), static_cast<int>(bytes.size()),
                               &width, &height, &channels))
        return imageError(path, std::string("cannot decode the image (") + stbi_failure_reason() + ")",
                          "a valid PNG image");
    if (width > kMaxSide || height > kMaxSide)
        return imageError(path,
                          "image is " + std::to_string(width) + "×" + std::to_string(height) + " pixels",
                          "at most " + std::to_string(kMaxSide) + " pixels a side");
    // Four channels out: grey, grey+alpha, palette and RGB files are widened as PNG defines them
    // (grey g → (g, g, g), tRNS or a missing alpha → 0 or 255), and 16-bit samples become
    // round(v·255/65535) = ⌊(v + 128) / 257⌋, as the libpng decoder of the native build does.
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int size = static_cast<int>(bytes.size());
    const bool wide = stbi_is_16_bit_from_memory(data, size) != 0;
    void* decoded =
        wide ? static_cast<void*>(stbi_load_16_from_memory(data, size, &width, &height, &channels, 4))
             : static_cast<void*>(stbi_load_from_memory(data, size, &width, &height, &channels, 4));
    if (!decoded)
        return imageError(path, std::string("cannot decode the image (") + stbi_failure_reason() + ")",
                          "a valid PNG image");
    RgbaImage image{width, height, {}};
    image.pixels.resize(static_cast<std::size_t>(width) * height);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        std::uint32_t c[4];
        for (std::size_t k = 0; k < 4; ++k)
            c[k] = wide ? (static_cast<const std::uint16_t*>(decoded)[4 * i + k] + 128u) / 257u
                        : static_cast<const stbi_uc*>(decoded)[4 * i + k];
        image.pixels[i] = (c[3] << 24) | (c[0] << 16) | (c[1] << 8) | c[2];
    }
    stbi_image_free(decoded);
    return image;
}

Result<std::string> encodePng(const RgbaImage& image) {
    std::vector<std::uint8_t> rgba(image.pixels.size() * 4);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        const std::uint32_t v = image.pixels[i];
        rgba[4 * i + 0] = static_cast<std::uint8_t>(v >> 16);
        rgba[4 * i + 1] = static_cast<std::uint8_t>(v >> 8);
        rgba[4 * i + 2] = static_cast<std::uint8_t>(v);
        rgba[4 * i + 3] = static_cast<std::uint8_t>(v >> 24);
    }
    std::string bytes;
    if (!stbi_write_png_to_func(appendBytes, &bytes, image.width, image.height, 4, rgba.data(),
                                image.width * 4))
        return imageError("", "cannot encode the PNG", "");
    return bytes;
}

}  // namespace polar
