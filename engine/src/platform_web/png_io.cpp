#include "polar/platform/png_io.h"

#include "platform/image_bytes.h"
#include "platform/image_decoders.h"

#include <cstdint>

// stb_image_write encodes PNG files here (stb_image, the decoder, is in image_decode.cpp). It
// comes from Debian's libstb-dev as a header; its code is compiled into this file alone.
#define STBI_WRITE_NO_STDIO
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

namespace polar {
namespace {

void appendBytes(void* out, void* data, int size) {
    static_cast<std::string*>(out)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}

}  // namespace

Result<RgbaImage> loadPng(const std::string& path) {
    Result<std::string> file = readImageBytes(path, "a PNG image");
    if (!file) return file.error();
    if (imageFormatOf(*file) != ImageFormat::png)
        return imageError(path, "cannot decode the image: it does not start with the PNG signature",
                          "a PNG image");
    return decodePngBytes(path, *file);
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
