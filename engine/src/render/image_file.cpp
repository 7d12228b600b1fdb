#include "polar/render/image_file.h"

#include <SDL.h>
#include <SDL_image.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <system_error>

namespace polar::render {

namespace {

// The renderer's fixed-point sprite code assumes sides below 2¹⁵ (see sprite.cpp).
constexpr int kMaxSide = 32767;

struct SurfaceDeleter {
    void operator()(SDL_Surface* s) const { SDL_FreeSurface(s); }
};
using SurfacePtr = std::unique_ptr<SDL_Surface, SurfaceDeleter>;

Error fileError(const std::string& path, std::string what, std::string expected) {
    Error e;
    e.file = path;
    e.what = std::move(what);
    e.expected = std::move(expected);
    return e;
}

// Reads any image SDL2_image knows and converts it to ARGB8888 (straight alpha).
Result<SurfacePtr> loadArgb8888(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return fileError(path, "no such file", "a PNG image");
    if (!std::filesystem::is_regular_file(path, ec)) return fileError(path, "not a regular file", "a PNG image");
    SurfacePtr loaded(IMG_Load(path.c_str()));
    if (!loaded) return fileError(path, std::string("cannot decode the image (") + IMG_GetError() + ")", "a valid PNG image");
    if (loaded->w > kMaxSide || loaded->h > kMaxSide)
        return fileError(path, "image is " + std::to_string(loaded->w) + "×" + std::to_string(loaded->h) + " pixels",
                         "at most " + std::to_string(kMaxSide) + " pixels a side");
    SurfacePtr argb(SDL_ConvertSurfaceFormat(loaded.get(), SDL_PIXELFORMAT_ARGB8888, 0));
    if (!argb) return fileError(path, std::string("cannot convert the image (") + SDL_GetError() + ")", "a PNG image");
    return argb;
}

}  // namespace

Result<Canvas> loadCanvas(const std::string& path) {
    Result<SurfacePtr> argb = loadArgb8888(path);
    if (!argb) return argb.error();
    SDL_Surface* s = argb->get();
    Canvas canvas(s->w, s->h);
    for (int y = 0; y < s->h; ++y)
        std::memcpy(canvas.row(y), static_cast<const std::uint8_t*>(s->pixels) + std::size_t(y) * s->pitch,
                    std::size_t(s->w) * 4);
    return canvas;
}

Result<Image> loadImage(const std::string& path) {
    Result<Canvas> canvas = loadCanvas(path);
    if (!canvas) return canvas.error();
    return Image::fromCanvas(*canvas);
}

std::optional<Error> savePng(const Canvas& canvas, const std::string& path) {
    namespace fs = std::filesystem;
    fs::path target(path);
    // The temporary file lives beside the target so the final rename stays on one file system.
    fs::path temp = target.parent_path() / ("." + target.filename().string() + ".tmp" + std::to_string(::getpid()));
    std::FILE* file = std::fopen(temp.c_str(), "wb");
    if (!file) return fileError(path, std::string("cannot create ") + temp.string() + " (" + std::strerror(errno) + ")",
                                "a writable folder");
    SDL_RWops* rw = SDL_RWFromFP(file, SDL_FALSE);
    bool ok = rw && IMG_SavePNG_RW(canvas.surface(), rw, 0) == 0;
    std::string why = ok ? "" : IMG_GetError();
    if (rw) SDL_RWclose(rw);
    // Flush to the disk before the rename, so a crash leaves the old file or the whole new one.
    ok = ok && std::fflush(file) == 0 && ::fsync(::fileno(file)) == 0;
    if (std::fclose(file) != 0) ok = false;
    int savedErrno = errno;
    std::error_code renameError;
    if (ok) fs::rename(temp, target, renameError);
    if (!ok || renameError) {
        if (why.empty()) why = renameError ? renameError.message() : std::strerror(savedErrno);
        std::error_code ignored;
        fs::remove(temp, ignored);
        return fileError(path, "cannot write the PNG (" + why + ")", "a writable folder with free space");
    }
    return std::nullopt;
}

}  // namespace polar::render
