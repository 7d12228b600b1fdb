#include "polar/png_io.h"

#include <SDL.h>
#include <SDL_image.h>

#include <cstdio>
#include <filesystem>

namespace polar {

AlphaMask RgbaImage::alphaMask() const {
    AlphaMask mask{width, height, {}};
    mask.alpha.reserve(pixels.size());
    for (std::uint32_t p : pixels) mask.alpha.push_back(static_cast<std::uint8_t>(p >> 24));
    return mask;
}

Result<RgbaImage> loadPng(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        return Error{path, 0, 0, "cannot read the image: no such file", "an existing PNG file"};
    SDL_Surface* loaded = IMG_Load(path.c_str());
    if (!loaded) return Error{path, 0, 0, std::string("cannot decode the image: ") + IMG_GetError(), "a valid PNG file"};
    SDL_Surface* argb = SDL_ConvertSurfaceFormat(loaded, SDL_PIXELFORMAT_ARGB8888, 0);
    SDL_FreeSurface(loaded);
    if (!argb) return Error{path, 0, 0, std::string("cannot convert the image: ") + SDL_GetError(), "an RGBA PNG"};
    RgbaImage image{argb->w, argb->h, {}};
    image.pixels.resize(static_cast<std::size_t>(argb->w) * argb->h);
    SDL_LockSurface(argb);
    for (int y = 0; y < argb->h; ++y) {
        const auto* row = reinterpret_cast<const std::uint32_t*>(static_cast<const std::uint8_t*>(argb->pixels) +
                                                                  static_cast<std::size_t>(y) * argb->pitch);
        std::copy(row, row + argb->w, image.pixels.begin() + static_cast<std::ptrdiff_t>(y) * argb->w);
    }
    SDL_UnlockSurface(argb);
    SDL_FreeSurface(argb);
    return image;
}

std::optional<Error> savePng(const std::string& path, const RgbaImage& image) {
    SDL_Surface* surface = SDL_CreateRGBSurfaceWithFormatFrom(
        const_cast<std::uint32_t*>(image.pixels.data()), image.width, image.height, 32, image.width * 4,
        SDL_PIXELFORMAT_ARGB8888);
    if (!surface) return Error{path, 0, 0, std::string("cannot wrap the image: ") + SDL_GetError(), ""};
    std::string temp = path + ".tmp";
    int failed = IMG_SavePNG(surface, temp.c_str());
    SDL_FreeSurface(surface);
    if (failed != 0) {
        std::remove(temp.c_str());
        return Error{path, 0, 0, std::string("cannot write the image: ") + IMG_GetError(), "a writable folder"};
    }
    std::error_code ec;
    std::filesystem::rename(temp, path, ec);
    if (ec) {
        std::remove(temp.c_str());
        return Error{path, 0, 0, "cannot replace the image: " + ec.message(), "a writable folder"};
    }
    return std::nullopt;
}

}  // namespace polar
