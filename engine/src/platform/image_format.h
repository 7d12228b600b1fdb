#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace polar {

// The largest side an image may have: the renderer's fixed-point sprite code assumes sides below
// 2¹⁵, and nothing in a game is larger. Every decoder refuses a larger image before its pixels.
constexpr int kMaxImageSide = 32767;

// An image file format, as told by the file's first bytes (never by its name). `unknown` is a file
// whose bytes match none; the formats after `tga` are named in messages but read by no decoder here.
enum class ImageFormat {
    unknown,
    png,
    bmp,
    gif,
    jpeg,
    pnm,
    qoi,
    webp,
    tiff,
    xcf,
    pcx,
    lbm,
    xpm,
    xv,
    svg,
    ico,
    cur,
    tga,  // no signature: tried last, on its header's plausibility or its footer
    avif,
    heif,
    jxl,
    psd,
};

// The format a file's bytes start like.
ImageFormat imageFormatOf(std::string_view bytes);

// The format's usual name in messages ("PNG", "JPEG", "GIMP XCF").
const char* imageFormatName(ImageFormat format);

// The width and height a file's header declares, where the header states them at a fixed place
// (read before any decoder allocates pixels); nothing when the header is too short or the format
// says it only deep inside (ICO's entries). An SVG's is an upper bound (its units counted as inches).
struct DeclaredSize {
    std::int64_t width = 0;
    std::int64_t height = 0;
};
std::optional<DeclaredSize> declaredSize(ImageFormat format, std::string_view bytes);

// The first image of a GIF that SDL2_image 2.6 decodes, found as it finds it: after the screen
// descriptor and its colour table, blocks are read one byte at a time: ';' ends the file, '!'
// starts an extension (a label, then sub-blocks to an empty one), ',' an image (left, top, width,
// height, flags, its colour table, then its LZW code size); any other byte is skipped. An image
// whose code size is over 12, or a side 0, is given up and the scan goes on after it.
struct GifImage {
    std::int64_t width = 0;
    std::int64_t height = 0;
    bool interlaced = false;
    std::size_t codeSizeAt = 0;  // where its LZW code size is; its data's sub-blocks follow
};
std::optional<GifImage> firstGifImage(std::string_view bytes);

}  // namespace polar
