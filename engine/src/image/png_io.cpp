#include "polar/png_io.h"

#include <SDL.h>
#include <SDL_image.h>

#include <cstring>
#include <filesystem>
#include <memory>

#include "polar/atomic_file.h"

namespace polar {
namespace {

// The renderer's fixed-point sprite code assumes sides below 2¹⁵, and nothing in the game is larger.
constexpr int kMaxSide = 32767;

struct SurfaceDeleter {
    void operator()(SDL_Surface* s) const { SDL_FreeSurface(s); }
};
using SurfacePtr = std::unique_ptr<SDL_Surface, SurfaceDeleter>;

Error imageError(const std::string& path, std::string what, std::string expected) {
    return Error{path, 0, 0, std::move(what), std::move(expected)};
}

// An SDL_RWops that appends everything written to a std::string, so SDL2_image can encode a PNG
// into memory and the bytes can go through writeFileAtomically like every other file.
struct StringSink {
    static SDL_RWops* open(std::string& out) {
        SDL_RWops* rw = SDL_AllocRW();
        if (!rw) return nullptr;
        rw->type = SDL_RWOPS_UNKNOWN;
        rw->hidden.unknown.data1 = &out;
        rw->size = [](SDL_RWops* self) -> Sint64 { return static_cast<Sint64>(text(self).size()); };
        rw->seek = [](SDL_RWops* self, Sint64 offset, int whence) -> Sint64 {
            // Only "where am I" is needed; an encoder writes straight through.
            if (offset == 0 && (whence == RW_SEEK_CUR || whence == RW_SEEK_END))
                return static_cast<Sint64>(text(self).size());
            return SDL_SetError("seeking in a PNG being encoded");
        };
        rw->read = [](SDL_RWops*, void*, size_t, size_t) -> size_t { return 0; };
        rw->write = [](SDL_RWops* self, const void* data, size_t size, size_t count) -> size_t {
            text(self).append(static_cast<const char*>(data), size * count);
            return count;
        };
        rw->close = [](SDL_RWops* self) -> int {
            SDL_FreeRW(self);
            return 0;
        };
        return rw;
    }
    static std::string& text(SDL_RWops* rw) { return *static_cast<std::string*>(rw->hidden.unknown.data1); }
};

}  // namespace

AlphaMask RgbaImage::alphaMask() const {
    AlphaMask mask{width, height, {}};
    mask.alpha.reserve(pixels.size());
    for (std::uint32_t p : pixels) mask.alpha.push_back(static_cast<std::uint8_t>(p >> 24));
    return mask;
}

Result<RgbaImage> loadPng(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return imageError(path, "no such file", "a PNG image");
    if (!std::filesystem::is_regular_file(path, ec)) return imageError(path, "not a regular file", "a PNG image");
    SurfacePtr loaded(IMG_Load(path.c_str()));
    if (!loaded) return imageError(path, std::string("cannot decode the image (") + IMG_GetError() + ")", "a valid PNG image");
    if (loaded->w > kMaxSide || loaded->h > kMaxSide)
        return imageError(path, "image is " + std::to_string(loaded->w) + "×" + std::to_string(loaded->h) + " pixels",
                          "at most " + std::to_string(kMaxSide) + " pixels a side");
    SurfacePtr argb(SDL_ConvertSurfaceFormat(loaded.get(), SDL_PIXELFORMAT_ARGB8888, 0));
    if (!argb) return imageError(path, std::string("cannot convert the image (") + SDL_GetError() + ")", "a PNG image");
    RgbaImage image{argb->w, argb->h, {}};
    image.pixels.resize(static_cast<std::size_t>(argb->w) * argb->h);
    for (int y = 0; y < argb->h; ++y)
        std::memcpy(image.pixels.data() + static_cast<std::size_t>(y) * argb->w,
                    static_cast<const std::uint8_t*>(argb->pixels) + static_cast<std::size_t>(y) * argb->pitch,
                    static_cast<std::size_t>(argb->w) * 4);
    return image;
}

Result<std::string> encodePng(const RgbaImage& image) {
    SurfacePtr surface(SDL_CreateRGBSurfaceWithFormatFrom(const_cast<std::uint32_t*>(image.pixels.data()), image.width,
                                                          image.height, 32, image.width * 4, SDL_PIXELFORMAT_ARGB8888));
    if (!surface) return imageError("", std::string("cannot wrap the image (") + SDL_GetError() + ")", "");
    std::string bytes;
    SDL_RWops* sink = StringSink::open(bytes);
    if (!sink || IMG_SavePNG_RW(surface.get(), sink, 1) != 0)
        return imageError("", std::string("cannot encode the PNG (") + IMG_GetError() + ")", "");
    return bytes;
}

std::optional<Error> savePng(const std::string& path, const RgbaImage& image, const AtomicWriteFault& fault) {
    Result<std::string> bytes = encodePng(image);
    if (!bytes) {
        Error error = bytes.error();
        error.file = path;
        return error;
    }
    return writeFileAtomically(path, *bytes, fault);
}

}  // namespace polar
