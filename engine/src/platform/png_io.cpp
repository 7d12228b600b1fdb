#include "polar/platform/png_io.h"

#include <SDL.h>
#include <SDL_image.h>

#include <array>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>

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

// CRC-32 as PNG uses it (ISO 3309, reflected polynomial 0xEDB88320) over `size` bytes.
std::uint32_t crc32(const unsigned char* data, std::size_t size) {
    static const auto table = [] {
        std::array<std::uint32_t, 256> t{};
        for (std::uint32_t n = 0; n < 256; ++n) {
            std::uint32_t c = n;
            for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
            t[n] = c;
        }
        return t;
    }();
    std::uint32_t c = 0xFFFFFFFFu;
    for (std::size_t i = 0; i < size; ++i) c = table[(c ^ data[i]) & 0xff] ^ (c >> 8);
    return c ^ 0xFFFFFFFFu;
}

std::uint32_t bigEndian32(const unsigned char* p) {
    return (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[2]) << 8) | p[3];
}

// Walks a PNG's chunks (length, type, data, CRC) up to IEND. A cut-off or damaged file is found
// here, with where it goes wrong, before libpng sees it: libpng would print its own line to stderr
// besides the error SDL2_image returns. Files that are not PNGs are left to SDL2_image.
std::optional<Error> checkPngChunks(const std::string& path, const std::string& bytes) {
    static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (bytes.size() < 8 || std::memcmp(bytes.data(), kSignature, 8) != 0) return std::nullopt;
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    std::size_t at = 8;
    while (true) {
        if (bytes.size() - at < 12) {
            return imageError(path,
                              "cannot decode the image: the file ends at byte " +
                                  std::to_string(bytes.size()) + " before its IEND chunk",
                              "a complete PNG image (was it cut off?)");
        }
        std::uint32_t length = bigEndian32(data + at);
        std::string type(bytes, at + 4, 4);
        for (char& c : type)
            if (!std::isalpha(static_cast<unsigned char>(c))) c = '?';  // garbage where a type should be
        if (length > 0x7fffffffu || bytes.size() - at - 12 < length)
            return imageError(path,
                              "cannot decode the image: the file ends at byte " +
                                  std::to_string(bytes.size()) + ", inside the " + type +
                                  " chunk that starts at byte " + std::to_string(at),
                              "a complete PNG image (was it cut off?)");
        if (crc32(data + at + 4, 4 + std::size_t(length)) != bigEndian32(data + at + 8 + length))
            return imageError(path,
                              "cannot decode the image: the " + type + " chunk at byte " +
                                  std::to_string(at) + " is damaged (its checksum differs)",
                              "a valid PNG image");
        at += 12 + std::size_t(length);
        if (type == "IEND") return std::nullopt;
    }
}

}  // namespace

Result<RgbaImage> loadPng(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return imageError(path, "no such file", "a PNG image");
    if (!std::filesystem::is_regular_file(path, ec))
        return imageError(path, "not a regular file", "a PNG image");
    std::string bytes;
    {
        std::ifstream in(path, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        if (!in && !in.eof()) return imageError(path, "cannot read the file", "a readable PNG image");
        bytes = text.str();
    }
    if (bytes.size() > 0x7fffffffu) return imageError(path, "the file is over 2 GB", "a PNG image");
    if (std::optional<Error> damaged = checkPngChunks(path, bytes)) return *damaged;
    SurfacePtr loaded(IMG_Load_RW(SDL_RWFromConstMem(bytes.data(), static_cast<int>(bytes.size())), 1));
    if (!loaded)
        return imageError(path, std::string("cannot decode the image (") + IMG_GetError() + ")",
                          "a valid PNG image");
    if (loaded->w > kMaxSide || loaded->h > kMaxSide)
        return imageError(
            path, "image is " + std::to_string(loaded->w) + "×" + std::to_string(loaded->h) + " pixels",
            "at most " + std::to_string(kMaxSide) + " pixels a side");
    SurfacePtr argb(SDL_ConvertSurfaceFormat(loaded.get(), SDL_PIXELFORMAT_ARGB8888, 0));
    if (!argb)
        return imageError(path, std::string("cannot convert the image (") + SDL_GetError() + ")",
                          "a PNG image");
    RgbaImage image{argb->w, argb->h, {}};
    image.pixels.resize(static_cast<std::size_t>(argb->w) * argb->h);
    for (int y = 0; y < argb->h; ++y)
        std::memcpy(
            image.pixels.data() + static_cast<std::size_t>(y) * argb->w,
            static_cast<const std::uint8_t*>(argb->pixels) + static_cast<std::size_t>(y) * argb->pitch,
            static_cast<std::size_t>(argb->w) * 4);
    return image;
}

Result<std::string> encodePng(const RgbaImage& image) {
    SurfacePtr surface(SDL_CreateRGBSurfaceWithFormatFrom(const_cast<std::uint32_t*>(image.pixels.data()),
                                                          image.width, image.height, 32, image.width * 4,
                                                          SDL_PIXELFORMAT_ARGB8888));
    if (!surface) return imageError("", std::string("cannot wrap the image (") + SDL_GetError() + ")", "");
    std::string bytes;
    SDL_RWops* sink = StringSink::open(bytes);
    if (!sink || IMG_SavePNG_RW(surface.get(), sink, 1) != 0)
        return imageError("", std::string("cannot encode the PNG (") + IMG_GetError() + ")", "");
    return bytes;
}

std::optional<Error> savePng(const RgbaImage& image, const std::string& path, const AtomicWriteFault& fault) {
    Result<std::string> bytes = encodePng(image);
    if (!bytes) {
        Error error = bytes.error();
        error.file = path;
        return error;
    }
    return writeFileAtomically(path, *bytes, fault);
}

std::optional<Error> savePng(const std::string& path, const RgbaImage& image, const AtomicWriteFault& fault) {
    return savePng(image, path, fault);
}

}  // namespace polar
