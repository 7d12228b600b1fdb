#include "polar/platform/image_file.h"

#include <cstring>

#include "polar/atomic_file.h"
#include "polar/platform/png_io.h"

namespace polar {

// Either codec (libpng, or stb_image on the web) only turns pixels into bytes; the file is written
// here, once, atomically.
std::optional<Error> savePng(const RgbaImage& image, const std::string& path, const AtomicWriteFault& fault) {
    Result<std::string> bytes = encodePng(image);
    if (!bytes) {
        Error error = bytes.error();
        error.file = path;
        return error;
    }
    return writeFileAtomically(path, *bytes, fault);
}

}  // namespace polar

namespace polar::render {

Result<Canvas> loadCanvas(const std::string& path) {
    Result<RgbaImage> image = loadRgbaImage(path);
    if (!image) return image.error();
    Canvas canvas(image->width, image->height);
    for (int y = 0; y < image->height; ++y)
        std::memcpy(canvas.row(y), image->pixels.data() + std::size_t(y) * image->width,
                    std::size_t(image->width) * 4);
    return canvas;
}

Result<Image> loadImage(const std::string& path) {
    Result<Canvas> canvas = loadCanvas(path);
    if (!canvas) return canvas.error();
    return Image::fromCanvas(*canvas);
}

std::optional<Error> savePng(const Canvas& canvas, const std::string& path) {
    RgbaImage image{canvas.width(), canvas.height(), {}};
    image.pixels.resize(std::size_t(canvas.width()) * canvas.height());
    for (int y = 0; y < canvas.height(); ++y)
        std::memcpy(image.pixels.data() + std::size_t(y) * canvas.width(), canvas.row(y),
                    std::size_t(canvas.width()) * 4);
    return polar::savePng(image, path);
}

}  // namespace polar::render
