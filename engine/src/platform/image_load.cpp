#include "platform/image_bytes.h"
#include "platform/image_decoders.h"
#include "platform/image_format.h"
#include "polar/platform/image_file.h"

#include <string>

namespace polar {
namespace {

Error tooLarge(const std::string& path, std::int64_t width, std::int64_t height) {
    return imageError(path, "image is " + std::to_string(width) + "×" + std::to_string(height) + " pixels",
                      "at most " + std::to_string(kMaxImageSide) + " pixels a side");
}

}  // namespace

Result<RgbaImage> loadRgbaImage(const std::string& path) {
    Result<std::string> file = readImageBytes(path, "an image file");
    if (!file) return file.error();
    return decodeImageBytes(path, *file);
}

Result<RgbaImage> decodeImageBytes(const std::string& path, const std::string& bytes) {
    if (bytes.empty()) return imageError(path, "cannot decode the image: the file is empty", "an image file");
    const ImageFormat format = imageFormatOf(bytes);
    if (format == ImageFormat::png) return decodePngBytes(path, bytes);
    const std::string readable = readableImageFormats();
    if (format == ImageFormat::unknown)
        return imageError(path,
                          "cannot decode the image: its first bytes are those of no image format read here",
                          "an image in one of " + readable);
    if (format >= ImageFormat::avif)
        return imageError(path,
                          std::string("cannot decode the image: it is a ") + imageFormatName(format) +
                              " image, which is not read here",
                          "an image in one of " + readable + " (export it as PNG, say)");
    if (std::optional<DeclaredSize> size = declaredSize(format, bytes);
        size && (size->width > kMaxImageSide || size->height > kMaxImageSide))
        return tooLarge(path, size->width, size->height);
    Result<RgbaImage> image = decodeOtherImage(path, bytes, format);
    if (image && (image->width > kMaxImageSide || image->height > kMaxImageSide))
        return tooLarge(path, image->width, image->height);
    if (image && (image->width < 1 || image->height < 1))
        return imageError(
            path,
            "image is " + std::to_string(image->width) + "×" + std::to_string(image->height) + " pixels",
            "at least 1 pixel a side");
    return image;
}

}  // namespace polar
