#include "polar/platform/png_io.h"

#include "platform/image_bytes.h"
#include "platform/image_decoders.h"
#include "platform/image_format.h"

#include <png.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <cctype>
#include <climits>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <new>
#include <optional>
#include <string_view>
#include <vector>

namespace polar {
namespace {

constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

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

// Walks a PNG's chunks (length, type, data, CRC) up to IEND, so a cut-off file or a damaged chunk
// is reported with the byte where it goes wrong (libpng names only the chunk, and drops an
// ancillary chunk whose CRC is wrong without failing).
std::optional<Error> checkPngChunks(const std::string& path, const std::string& bytes) {
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

// What libpng's callbacks share with the decoder or the encoder: the bytes being read or written,
// and what went wrong. Plain data only, because libpng leaves its frames by longjmp.
struct PngStream {
    const unsigned char* data = nullptr;  // reading: the file's bytes
    std::size_t size = 0;
    std::size_t at = 0;
    std::string* out = nullptr;  // writing: where the PNG's bytes go
    char error[256] = {};        // libpng's message when it gives up
    char pixelDamage[256] = {};  // libpng's first warning about the pixel data (IDAT)
};

// libpng's error handler: keeps the message (instead of printing it) and returns to the setjmp
// in decodePng.
[[noreturn]] void onPngError(png_structp png, png_const_charp message) {
    auto* stream = static_cast<PngStream*>(png_get_error_ptr(png));
    std::snprintf(stream->error, sizeof stream->error, "%s", message);
    png_longjmp(png, 1);
}

// libpng's warning handler: prints nothing. A fault in the compressed pixel data found after the
// last row (a wrong Adler-32, say) is only a warning to libpng; it is kept, and decodePng fails on
// it, because the pixels cannot be trusted. Other warnings (an odd ancillary chunk) are dropped.
void onPngWarning(png_structp png, png_const_charp message) {
    auto* stream = static_cast<PngStream*>(png_get_error_ptr(png));
    if (std::strncmp(message, "IDAT", 4) == 0 && stream->pixelDamage[0] == '\0')
        std::snprintf(stream->pixelDamage, sizeof stream->pixelDamage, "%s", message);
}

void readPngBytes(png_structp png, png_bytep out, std::size_t count) {
    auto* stream = static_cast<PngStream*>(png_get_io_ptr(png));
    if (stream->size - stream->at < count) png_error(png, "the file ends inside the image");
    std::memcpy(out, stream->data + stream->at, count);
    stream->at += count;
}

void writePngBytes(png_structp png, png_bytep data, std::size_t count) {
    auto* stream = static_cast<PngStream*>(png_get_io_ptr(png));
    bool appended = false;
    try {
        stream->out->append(reinterpret_cast<const char*>(data), count);
        appended = true;
    } catch (const std::bad_alloc&) {
    }
    if (!appended) png_error(png, "out of memory");
}

void flushPngBytes(png_structp) {}  // the bytes are in memory: nothing to flush

enum class Decoded { ok, tooLarge, failed };

// Decodes the PNG in `stream` to 8-bit RGBA bytes, four a pixel, row after row. Every colour type
// and bit depth ends as RGBA8: palette entries are looked up, grey is copied to R, G and B, samples
// under 8 bits are scaled up by repeating their bits (the exact v·255/(2ⁿ−1)), tRNS gives its
// colour or palette entries their alpha, a missing alpha is 255, and Adam7 passes are merged.
// 16-bit samples become round(v·255/65535) (libpng's scale_16): the spec's rescaling formula,
// which keeps 16-bit images made from 8-bit ones exact (v = 257·k gives k); taking the high byte
// would turn 0x01FF into 1 where the nearest 8-bit value is 2. No gamma is applied: sprite
// values are used as stored. Only trivially destructible objects live in this frame, since
// libpng's errors return to the setjmp below by longjmp, skipping destructors.
Decoded decodePng(PngStream& stream, std::vector<unsigned char>& rgba, std::vector<png_bytep>& rows,
                  int& width, int& height) {
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &stream, onPngError, onPngWarning);
    if (!png) {
        std::snprintf(stream.error, sizeof stream.error, "out of memory");
        return Decoded::failed;
    }
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_read_struct(&png, nullptr, nullptr);
        std::snprintf(stream.error, sizeof stream.error, "out of memory");
        return Decoded::failed;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        return Decoded::failed;
    }
    png_set_read_fn(png, &stream, readPngBytes);
    png_read_info(png, info);
    const png_uint_32 w = png_get_image_width(png, info);
    const png_uint_32 h = png_get_image_height(png, info);
    if (w > png_uint_32(kMaxImageSide) || h > png_uint_32(kMaxImageSide)) {
        width = int(std::min<png_uint_32>(w, INT_MAX));
        height = int(std::min<png_uint_32>(h, INT_MAX));
        png_destroy_read_struct(&png, &info, nullptr);
        return Decoded::tooLarge;
    }
    png_set_expand(png);  // palette to RGB, grey under 8 bits to 8 bits, tRNS to alpha
    png_set_scale_16(png);
    png_set_gray_to_rgb(png);
    png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);  // only where there is no alpha yet
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    if (png_get_rowbytes(png, info) != std::size_t(w) * 4 || png_get_bit_depth(png, info) != 8)
        png_error(png, "the decoder did not produce 8-bit RGBA");
    width = int(w);
    height = int(h);
    bool allocated = false;
    try {  // up to 4 GiB at 32767 pixels a side
        rgba.resize(std::size_t(w) * h * 4);
        rows.resize(h);
        allocated = true;
    } catch (const std::bad_alloc&) {
    }
    if (!allocated) png_error(png, "out of memory for the pixels");
    for (png_uint_32 y = 0; y < h; ++y) rows[y] = rgba.data() + std::size_t(y) * w * 4;
    png_read_image(png, rows.data());
    png_read_end(png, nullptr);
    png_destroy_read_struct(&png, &info, nullptr);
    if (stream.pixelDamage[0] != '\0') {
        std::snprintf(stream.error, sizeof stream.error, "%s", stream.pixelDamage);
        return Decoded::failed;
    }
    return Decoded::ok;
}

// Encodes `height` rows of `width` RGBA8 pixels into stream.out as an 8-bit RGBA, non-interlaced
// PNG (zlib's default level, libpng's default filters). False with stream.error set on failure.
// As in decodePng, no object with a destructor lives across the setjmp.
bool encodeRgbaRows(PngStream& stream, png_bytep* rows, int width, int height) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &stream, onPngError, onPngWarning);
    if (!png) {
        std::snprintf(stream.error, sizeof stream.error, "out of memory");
        return false;
    }
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        std::snprintf(stream.error, sizeof stream.error, "out of memory");
        return false;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_set_write_fn(png, &stream, writePngBytes, flushPngBytes);
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8, PNG_COLOR_TYPE_RGB_ALPHA,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    png_write_image(png, rows);
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return true;
}

// What a file that is not a PNG looks like, from its first bytes.
std::string notPngReason(const std::string& bytes) {
    auto startsWith = [&](std::string_view prefix) { return bytes.compare(0, prefix.size(), prefix) == 0; };
    if (startsWith("\xff\xd8\xff")) return "it is a JPEG image, not a PNG";
    if (startsWith("GIF87a") || startsWith("GIF89a")) return "it is a GIF image, not a PNG";
    if (startsWith("BM")) return "it looks like a BMP image, not a PNG";
    if (startsWith("RIFF") && bytes.size() >= 12 && bytes.compare(8, 4, "WEBP") == 0)
        return "it is a WebP image, not a PNG";
    if (startsWith("\x8aMNG") || startsWith("\x8bJNG")) return "it is an MNG or JNG file, not a PNG";
    return "it does not start with the PNG signature (89 50 4E 47 0D 0A 1A 0A)";
}

// libpng's message as a reader understands it.
std::string explainPngError(const std::string& message) {
    if (message.rfind("IDAT: ", 0) == 0)
        return "its compressed pixel data is damaged (" + message.substr(6) + ")";
    if (message == "Not enough image data" || message == "IDAT: Not enough image data")
        return "its compressed pixel data ends before the last row";
    return message;
}

}  // namespace

Result<RgbaImage> loadPng(const std::string& path) {
    Result<std::string> file = readImageBytes(path, "a PNG image");
    if (!file) return file.error();
    return decodePngBytes(path, *file);
}

Result<RgbaImage> decodePngBytes(const std::string& path, const std::string& bytes) {
    if (bytes.empty()) return imageError(path, "cannot decode the image: the file is empty", "a PNG image");
    if (bytes.size() < 8 || std::memcmp(bytes.data(), kSignature, 8) != 0)
        return imageError(path, "cannot decode the image: " + notPngReason(bytes), "a PNG image");
    if (std::optional<Error> damaged = checkPngChunks(path, bytes)) return *damaged;

    PngStream stream;
    stream.data = reinterpret_cast<const unsigned char*>(bytes.data());
    stream.size = bytes.size();
    std::vector<unsigned char> rgba;
    std::vector<png_bytep> rows;
    int width = 0;
    int height = 0;
    switch (decodePng(stream, rgba, rows, width, height)) {
        case Decoded::ok:
            break;
        case Decoded::tooLarge:
            return imageError(path,
                              "image is " + std::to_string(width) + "×" + std::to_string(height) + " pixels",
                              "at most " + std::to_string(kMaxImageSide) + " pixels a side");
        case Decoded::failed:
            return imageError(path, "cannot decode the image: " + explainPngError(stream.error),
                              "a valid PNG image");
    }
    RgbaImage image{width, height, {}};
    image.pixels.resize(std::size_t(width) * height);
    const unsigned char* p = rgba.data();
    for (std::uint32_t& pixel : image.pixels) {
        pixel = std::uint32_t(p[3]) << 24 | std::uint32_t(p[0]) << 16 | std::uint32_t(p[1]) << 8 | p[2];
        p += 4;
    }
    return image;
}

Result<std::string> encodePng(const RgbaImage& image) {
    assert(image.pixels.size() == std::size_t(image.width) * image.height);
    std::vector<unsigned char> rgba(image.pixels.size() * 4);
    unsigned char* p = rgba.data();
    for (std::uint32_t pixel : image.pixels) {
        p[0] = std::uint8_t(pixel >> 16);
        p[1] = std::uint8_t(pixel >> 8);
        p[2] = std::uint8_t(pixel);
        p[3] = std::uint8_t(pixel >> 24);
        p += 4;
    }
    std::vector<png_bytep> rows(std::size_t(std::max(image.height, 0)));
    for (std::size_t y = 0; y < rows.size(); ++y) rows[y] = rgba.data() + y * std::size_t(image.width) * 4;
    std::string bytes;
    PngStream stream;
    stream.out = &bytes;
    if (!encodeRgbaRows(stream, rows.data(), image.width, image.height))
        return imageError("", std::string("cannot encode the PNG (") + stream.error + ")", "");
    return bytes;
}

}  // namespace polar
