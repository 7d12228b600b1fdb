#include "platform/image_bytes.h"
#include "platform/image_decoders.h"
#include "platform/sdl_image_guards.h"

#include <SDL.h>
#include <SDL_image.h>
#include <tiffio.h>

#include <algorithm>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <optional>
#include <string_view>

namespace polar {
namespace {

using Loader = SDL_Surface* (*)(SDL_RWops*);

// SDL2_image's own loader for each format this layer hands it. Calling it directly (rather than
// IMG_Load_RW, which guesses from the bytes again) keeps the signature test in one place,
// imageFormatOf, and lets a TGA, which has no signature, be read at all.
Loader loaderFor(ImageFormat format) {
    switch (format) {
        case ImageFormat::bmp:
            return IMG_LoadBMP_RW;
        case ImageFormat::gif:
            return IMG_LoadGIF_RW;
        case ImageFormat::jpeg:
            return IMG_LoadJPG_RW;
        case ImageFormat::pnm:
            return IMG_LoadPNM_RW;
        case ImageFormat::qoi:
            return IMG_LoadQOI_RW;
        case ImageFormat::webp:
            return IMG_LoadWEBP_RW;
        case ImageFormat::tiff:
            return IMG_LoadTIF_RW;
        case ImageFormat::xcf:
            return IMG_LoadXCF_RW;
        case ImageFormat::pcx:
            return IMG_LoadPCX_RW;
        case ImageFormat::lbm:
            return IMG_LoadLBM_RW;
        case ImageFormat::xpm:
            return IMG_LoadXPM_RW;
        case ImageFormat::xv:
            return IMG_LoadXV_RW;
        case ImageFormat::svg:
            return IMG_LoadSVG_RW;
        case ImageFormat::ico:
            return IMG_LoadICO_RW;
        case ImageFormat::cur:
            return IMG_LoadCUR_RW;
        case ImageFormat::tga:
            return IMG_LoadTGA_RW;
        default:
            return nullptr;
    }
}

// libtiff, which SDL2_image reads TIFF through, prints its errors and warnings to stderr unless
// told otherwise. Its handlers are process-wide: installed once, they keep the thread's first
// error (to follow the file's name in the Error) and drop warnings.
thread_local char tiffMessage[256];

void keepTiffError(const char* module, const char* format, va_list args) {
    if (tiffMessage[0] != '\0') return;
    char text[200];
    std::vsnprintf(text, sizeof text, format, args);
    if (module && *module && std::strcmp(module, "SDL_image") != 0)
        std::snprintf(tiffMessage, sizeof tiffMessage, "%s: %s", module, text);
    else
        std::snprintf(tiffMessage, sizeof tiffMessage, "%s", text);
}

void dropTiffWarning(const char*, const char*, va_list) {}

void silenceLibtiff() {
    static std::once_flag once;
    std::call_once(once, [] {
        TIFFSetErrorHandler(keepTiffError);
        TIFFSetWarningHandler(dropTiffWarning);
    });
}

// libtiff's RGBA reader (TIFFReadRGBAImage, what SDL2_image uses) premultiplies a TIFF's
// unassociated alpha as round(c·a/255). Dividing back, c = round(p·255/a), gives a colour that
// premultiplies to the same p again, so the premultiplied image the game draws is exact.
std::uint32_t unpremultiply(std::uint32_t argb) {
    const std::uint32_t a = argb >> 24;
    if (a == 0 || a == 255) return argb;
    auto channel = [&](int shift) {
        const std::uint32_t p = (argb >> shift) & 0xff;
        return std::min<std::uint32_t>(255, (p * 255 + a / 2) / a) << shift;
    };
    return a << 24 | channel(16) | channel(8) | channel(0);
}

// SDL2_image reports some faults only through SDL_Log, which prints to stderr, and returns an
// image anyway (an XCF layer of an unknown depth is left out, blank). SDL's log output is
// process-wide: installed once, this one keeps the first message of a thread that is decoding (to
// follow the file's name in the Error, which refuses the file) and passes every other message on
// to the output that was there before.
thread_local bool decodingHere = false;
thread_local char logMessage[256];
SDL_LogOutputFunction previousLogOutput = nullptr;
void* previousLogData = nullptr;

void keepSdlLog(void*, int category, SDL_LogPriority priority, const char* message) {
    if (!decodingHere) {
        if (previousLogOutput) previousLogOutput(previousLogData, category, priority, message);
        return;
    }
    if (logMessage[0] == '\0') std::snprintf(logMessage, sizeof logMessage, "%s", message);
}

void catchSdlLog() {
    static std::once_flag once;
    std::call_once(once, [] {
        SDL_LogGetOutputFunction(&previousLogOutput, &previousLogData);
        SDL_LogSetOutputFunction(keepSdlLog, nullptr);
    });
}

// SDL2_image composites an XCF's visible layers onto a transparent image with SDL's blend,
// d = s·a + d·(1 − a): onto transparent black that multiplies a translucent pixel's colours by its
// alpha, and each layer blended over such pixels is then premultiplied "over", so the image comes
// back premultiplied. SDL's blitters round their own way (x86-64's: c·a >> 8, and alpha too,
// (a·255) >> 8, one lower). So the blend is measured once, every colour at every alpha onto
// transparent black, and undone: each alpha it gives maps back to the alpha that gave it, and each
// colour to the middle of the colours that blend to it. Once premultiplied, a layer's translucent
// pixels come back within 1 of what was saved (three in four exactly, the test sprite's all);
// alpha 1 blends to 0 and stays transparent.
struct BlendInverse {
    std::uint8_t alpha[256];        // by the blended alpha: the alpha before
    std::uint8_t colour[256][256];  // by the blended alpha and colour: the colour before
};

const BlendInverse& sdlBlendInverse() {
    static BlendInverse inverse;
    static std::once_flag once;
    std::call_once(once, [] {
        for (int a = 0; a < 256; ++a) {
            inverse.alpha[a] = std::uint8_t(a);
            for (int c = 0; c < 256; ++c)
                inverse.colour[a][c] = std::uint8_t(a == 0 ? c : std::min(255, (c * 255 + a / 2) / a));
        }
        SDL_Surface* from = SDL_CreateRGBSurfaceWithFormat(0, 256, 256, 32, SDL_PIXELFORMAT_ARGB8888);
        SDL_Surface* onto = SDL_CreateRGBSurfaceWithFormat(0, 256, 256, 32, SDL_PIXELFORMAT_ARGB8888);
        if (from && onto) {
            for (int a = 0; a < 256; ++a)  // row a: alpha a, column c: grey c
                for (int c = 0; c < 256; ++c)
                    static_cast<std::uint32_t*>(from->pixels)[a * from->pitch / 4 + c] =
                        std::uint32_t(a) << 24 | std::uint32_t(c) * 0x010101u;
            SDL_SetSurfaceBlendMode(from, SDL_BLENDMODE_BLEND);
            SDL_FillRect(onto, nullptr, 0);
            if (SDL_BlitSurface(from, nullptr, onto, nullptr) == 0)
                for (int a = 1; a < 255; ++a) {
                    const std::uint32_t* row =
                        static_cast<const std::uint32_t*>(onto->pixels) + a * onto->pitch / 4;
                    const int blended = int(row[255] >> 24);
                    if (blended == 0 || blended == 255) continue;  // a transparent or opaque pixel stays so
                    inverse.alpha[blended] = std::uint8_t(a);
                    for (int c = 0; c < 256;) {  // the run of colours that blend to the same value
                        const int value = int(row[c] & 0xff);
                        int end = c;
                        while (end + 1 < 256 && int(row[end + 1] & 0xff) == value) ++end;
                        inverse.colour[blended][value] = std::uint8_t((c + end) / 2);
                        c = end + 1;
                    }
                }
        }
        SDL_FreeSurface(from);
        SDL_FreeSurface(onto);
    });
    return inverse;
}

std::uint32_t unblend(std::uint32_t argb, const BlendInverse& inverse) {
    const std::uint32_t a = argb >> 24;
    if (a == 0 || a == 255) return argb;
    const std::uint8_t* colour = inverse.colour[a];
    return std::uint32_t(inverse.alpha[a]) << 24 | std::uint32_t(colour[(argb >> 16) & 0xff]) << 16 |
           std::uint32_t(colour[(argb >> 8) & 0xff]) << 8 | colour[argb & 0xff];
}

}  // namespace

std::string readableImageFormats() {
    return "PNG, BMP, GIF, JPEG, TGA, TIFF, WebP, QOI, PNM, PCX, LBM, XCF, XPM, XV, SVG, ICO or CUR";
}

Result<RgbaImage> decodeOtherImage(const std::string& path, const std::string& bytes, ImageFormat format) {
    const std::string name = imageFormatName(format);
    const Loader load = loaderFor(format);
    if (!load)
        return imageError(path, "cannot decode the " + name + " image here",
                          "an image in one of " + readableImageFormats());
    if (format == ImageFormat::xpm)
        if (std::optional<std::string> problem = xpmProblem(bytes))
            return imageError(path, "cannot decode the XPM image: " + *problem, "a valid XPM image");
    if (format == ImageFormat::gif)
        if (std::optional<std::string> problem = gifProblem(bytes))
            return imageError(path, "cannot decode the GIF image: " + *problem, "a valid GIF image");
    if (format == ImageFormat::xcf)
        if (std::optional<std::string> problem = xcfProblem(bytes))
            return imageError(path, "cannot decode the GIMP XCF image: " + *problem,
                              "a valid GIMP XCF image");
    silenceLibtiff();
    catchSdlLog();
    tiffMessage[0] = '\0';
    logMessage[0] = '\0';
    SDL_ClearError();
    SDL_RWops* source = SDL_RWFromConstMem(bytes.data(), static_cast<int>(bytes.size()));
    if (!source) return imageError(path, "out of memory reading the image", "a smaller " + name + " image");
    decodingHere = true;
    SDL_Surface* surface = load(source);
    decodingHere = false;
    SDL_RWclose(source);
    if (!surface || logMessage[0] != '\0') {
        SDL_FreeSurface(surface);
        const char* text = tiffMessage[0] != '\0'  ? tiffMessage
                           : logMessage[0] != '\0' ? logMessage
                                                   : SDL_GetError();
        std::string reason = text && *text ? text : "no reason given";
        for (char& c : reason)  // a library's message may hold line breaks; the Error is one line
            if (static_cast<unsigned char>(c) < 0x20) c = ' ';
        while (!reason.empty() && reason.back() == ' ') reason.pop_back();
        return imageError(path, "cannot decode the " + name + " image (SDL_image: " + reason + ")",
                          "a valid " + name + " image (was it cut off?)");
    }
    if (surface->w > kMaxImageSide || surface->h > kMaxImageSide || surface->w < 1 || surface->h < 1) {
        RgbaImage sides{surface->w, surface->h, {}};
        SDL_FreeSurface(surface);
        return sides;  // loadRgbaImage refuses it, with its sides
    }
    // To 0xAARRGGBB in native order. SDL turns a colour key into alpha 0 on the way, gives a
    // format without alpha 255 and copies a stored alpha as it is.
    SDL_Surface* argb = SDL_ConvertSurfaceFormat(surface, SDL_PIXELFORMAT_ARGB8888, 0);
    SDL_FreeSurface(surface);
    if (!argb)
        return imageError(path, "out of memory for the " + name + " image's pixels", "a smaller image");
    RgbaImage image{argb->w, argb->h, {}};
    image.pixels.resize(std::size_t(argb->w) * argb->h);
    for (int y = 0; y < argb->h; ++y)
        std::memcpy(image.pixels.data() + std::size_t(y) * argb->w,
                    static_cast<const unsigned char*>(argb->pixels) + std::size_t(y) * argb->pitch,
                    std::size_t(argb->w) * 4);
    SDL_FreeSurface(argb);
    if (format == ImageFormat::tiff)
        for (std::uint32_t& pixel : image.pixels) pixel = unpremultiply(pixel);
    if (format == ImageFormat::xcf)
        for (std::uint32_t& pixel : image.pixels) pixel = unblend(pixel, sdlBlendInverse());
    return image;
}

}  // namespace polar
