#include "platform/image_bytes.h"
#include "platform/image_decoders.h"

#include <cstdint>

// stb_image decodes every image file here: PNG, and the five other formats it reads. It comes
// from Debian's libstb-dev as a header; its code is compiled into this file alone.
#define STBI_ONLY_PNG
#define STBI_ONLY_BMP
#define STBI_ONLY_GIF
#define STBI_ONLY_JPEG
#define STBI_ONLY_TGA
#define STBI_ONLY_PNM
#define STBI_NO_STDIO
#define STBI_MAX_DIMENSIONS 32767  // kMaxImageSide: refused before any pixel is allocated
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

namespace polar {
namespace {

bool readByStb(ImageFormat format) {
    switch (format) {
        case ImageFormat::png:
        case ImageFormat::bmp:
        case ImageFormat::gif:
        case ImageFormat::jpeg:
        case ImageFormat::tga:
        case ImageFormat::pnm:
            return true;
        default:
            return false;
    }
}

// Four channels out: grey, grey+alpha, palette and RGB files are widened as their formats define
// them (grey g → (g, g, g); a missing alpha → 255; GIF's transparent index → 0), and 16-bit
// samples become round(v·255/65535) = ⌊(v + 128) / 257⌋, as the native build's libpng does.
Result<RgbaImage> decodeWithStb(const std::string& path, const std::string& bytes, ImageFormat format) {
    const std::string name = imageFormatName(format);
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int size = static_cast<int>(bytes.size());
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(data, size, &width, &height, &channels))
        return imageError(path, "cannot decode the " + name + " image (" + stbi_failure_reason() + ")",
                          "a valid " + name + " image");
    if (width > kMaxImageSide || height > kMaxImageSide)
        return imageError(path,
                          "image is " + std::to_string(width) + "×" + std::to_string(height) + " pixels",
                          "at most " + std::to_string(kMaxImageSide) + " pixels a side");
    const bool wide = stbi_is_16_bit_from_memory(data, size) != 0;
    void* decoded =
        wide ? static_cast<void*>(stbi_load_16_from_memory(data, size, &width, &height, &channels, 4))
             : static_cast<void*>(stbi_load_from_memory(data, size, &width, &height, &channels, 4));
    if (!decoded)
        return imageError(path, "cannot decode the " + name + " image (" + stbi_failure_reason() + ")",
                          "a valid " + name + " image");
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

}  // namespace

std::string readableImageFormats() {
    return "PNG, BMP, GIF, JPEG, TGA or PNM";
}

Result<RgbaImage> decodePngBytes(const std::string& path, const std::string& bytes) {
    return decodeWithStb(path, bytes, ImageFormat::png);
}

Result<RgbaImage> decodeOtherImage(const std::string& path, const std::string& bytes, ImageFormat format) {
    if (!readByStb(format))
        return imageError(path,
                          std::string("cannot decode the image: it is a ") + imageFormatName(format) +
                              " image, which the browser build does not read",
                          "PNG, BMP, GIF, JPEG, TGA or PNM (convert it to PNG)");
    return decodeWithStb(path, bytes, format);
}

}  // namespace polar
