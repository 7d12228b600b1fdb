#include "platform/image_format.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace polar {
namespace {

bool startsWith(std::string_view bytes, std::string_view prefix, std::size_t at = 0) {
    return bytes.size() >= at + prefix.size() && bytes.compare(at, prefix.size(), prefix) == 0;
}

unsigned byteAt(std::string_view bytes, std::size_t at) {
    return static_cast<unsigned char>(bytes[at]);
}

std::uint32_t little16(std::string_view b, std::size_t at) {
    return byteAt(b, at) | byteAt(b, at + 1) << 8;
}
std::uint32_t big16(std::string_view b, std::size_t at) {
    return byteAt(b, at) << 8 | byteAt(b, at + 1);
}
std::uint32_t little32(std::string_view b, std::size_t at) {
    return little16(b, at) | little16(b, at + 2) << 16;
}
std::uint32_t big32(std::string_view b, std::size_t at) {
    return big16(b, at) << 16 | big16(b, at + 2);
}

// A TGA file has no signature. Version 2 files end with a footer; older ones are taken for TGA
// when their 18-byte header is plausible: a colour-map flag of 0 or 1, a known image type (a
// colour-mapped one only with a colour map), a usual pixel depth and non-zero sides.
bool looksLikeTga(std::string_view bytes) {
    if (bytes.size() < 18) return false;
    const unsigned mapType = byteAt(bytes, 1), type = byteAt(bytes, 2), depth = byteAt(bytes, 16);
    if (mapType > 1) return false;
    const bool mapped = type == 1 || type == 9;
    if (!(mapped || type == 2 || type == 3 || type == 10 || type == 11) || (mapped && mapType != 1))
        return false;
    if (depth != 8 && depth != 15 && depth != 16 && depth != 24 && depth != 32) return false;
    return little16(bytes, 12) != 0 && little16(bytes, 14) != 0;
}

bool hasTgaFooter(std::string_view bytes) {
    static constexpr char kFooter[] = "TRUEVISION-XFILE.";  // with its NUL, the last 18 bytes
    return bytes.size() >= 18 + 26 && std::memcmp(bytes.data() + bytes.size() - 18, kFooter, 18) == 0;
}

// SVG is XML text: an optional byte-order mark and white space, then a declaration, a comment, a
// doctype or the <svg> element itself, with "<svg" somewhere in the first 4 KiB.
bool looksLikeSvg(std::string_view bytes) {
    std::string_view head = bytes.substr(0, 4096);
    if (startsWith(head, "\xef\xbb\xbf")) head.remove_prefix(3);
    while (!head.empty() && std::isspace(static_cast<unsigned char>(head.front()))) head.remove_prefix(1);
    if (!startsWith(head, "<?xml") && !startsWith(head, "<svg") && !startsWith(head, "<!--") &&
        !startsWith(head, "<!DOCTYPE svg"))
        return false;
    return head.find("<svg") != std::string_view::npos;
}

// The sides of an ICO or CUR directory: a zero reserved word, the type (1 icon, 2 cursor), and at
// least one image.
bool isIconDirectory(std::string_view bytes, unsigned type) {
    return bytes.size() >= 6 && little16(bytes, 0) == 0 && little16(bytes, 2) == type &&
           little16(bytes, 4) != 0;
}

// A PNM's width and height, read as SDL2_image 2.6 reads them (its ReadNumber), so the size
// checked is the size it allocates: from byte 2, each number after white space and '#' comments
// (each to the end of its line), its digits ended by any one byte, which is taken with them
// ("77R7" is 77 and 7). A number that would pass 2³¹ / 10 is none (SDL2_image refuses it).
std::optional<DeclaredSize> pnmSides(std::string_view bytes) {
    std::size_t at = 2;
    auto next = [&](unsigned char& ch) {
        if (at >= bytes.size()) return false;
        ch = static_cast<unsigned char>(bytes[at++]);
        return true;
    };
    auto number = [&]() -> std::optional<std::int64_t> {
        unsigned char ch = 0;
        do {
            if (!next(ch)) return std::nullopt;
            if (ch == '#') do {
                    if (!next(ch)) return std::nullopt;
                } while (ch != '\r' && ch != '\n');
        } while (std::isspace(ch));
        if (!std::isdigit(ch)) return std::nullopt;
        std::int64_t value = 0;
        do {
            if (value >= INT32_MAX / 10) return std::nullopt;
            value = value * 10 + (ch - '0');
            if (!next(ch)) return std::nullopt;
        } while (std::isdigit(ch));
        return value;
    };
    const std::optional<std::int64_t> width = number();
    const std::optional<std::int64_t> height = width ? number() : std::nullopt;
    if (!height) return std::nullopt;
    return DeclaredSize{*width, *height};
}

// An XV thumbnail's width and height, where SDL2_image 2.6 reads them: lines (a '\r' dropped)
// after the "P7 332" line up to one starting "#END_OF_COMMENTS" (none if "#BUILTIN:" comes first),
// then "WIDTH HEIGHT" at the start of the next line.
std::optional<DeclaredSize> xvSides(std::string_view bytes) {
    std::size_t at = 0;
    auto line = [&]() -> std::optional<std::string> {
        const std::size_t end = bytes.find('\n', at);
        if (end == std::string_view::npos) return std::nullopt;
        std::string text(bytes.substr(at, end - at));
        std::erase(text, '\r');
        at = end + 1;
        return text;
    };
    if (!line()) return std::nullopt;  // "P7 332", which the signature holds
    while (std::optional<std::string> text = line()) {
        if (text->starts_with("#BUILTIN:")) return std::nullopt;
        if (!text->starts_with("#END_OF_COMMENTS")) continue;
        const std::optional<std::string> sides = line();
        long long width = 0, height = 0;
        if (!sides || std::sscanf(sides->c_str(), "%lld %lld", &width, &height) != 2) return std::nullopt;
        return DeclaredSize{width, height};
    }
    return std::nullopt;
}

}  // namespace

std::optional<GifImage> firstGifImage(std::string_view bytes) {
    if (bytes.size() < 13) return std::nullopt;
    auto table = [&](unsigned flags) -> std::size_t { return flags & 0x80 ? 3u << ((flags & 7) + 1) : 0; };
    std::size_t at = 13 + table(byteAt(bytes, 10));
    while (at < bytes.size()) {
        const unsigned c = byteAt(bytes, at++);
        if (c == ';') break;
        if (c == '!') {
            ++at;  // the label
            while (at < bytes.size() && byteAt(bytes, at) != 0) at += 1 + byteAt(bytes, at);
            ++at;  // the empty sub-block
        } else if (c == ',') {
            if (bytes.size() - at < 9) break;
            const GifImage image{little16(bytes, at + 4), little16(bytes, at + 6),
                                 (byteAt(bytes, at + 8) & 0x40) != 0, at + 9 + table(byteAt(bytes, at + 8))};
            at = image.codeSizeAt;
            if (at >= bytes.size()) break;
            if (byteAt(bytes, at++) <= 12 && image.width > 0 && image.height > 0) return image;
        }
    }
    return std::nullopt;
}

namespace {

// A JPEG's size is in its start-of-frame segment (SOF0 to SOF15 but DHT, JPG and DAC), found by
// walking the segments from the start.
std::optional<DeclaredSize> jpegSides(std::string_view bytes) {
    std::size_t at = 2;
    while (at + 9 <= bytes.size()) {
        if (byteAt(bytes, at) != 0xff) return std::nullopt;
        const unsigned marker = byteAt(bytes, at + 1);
        if (marker == 0xff) {  // fill byte
            ++at;
            continue;
        }
        if (marker == 0x01 || (marker >= 0xd0 && marker <= 0xd8)) {  // segments without a length
            at += 2;
            continue;
        }
        if (marker >= 0xc0 && marker <= 0xcf && marker != 0xc4 && marker != 0xc8 && marker != 0xcc)
            return DeclaredSize{big16(bytes, at + 7), big16(bytes, at + 5)};
        if (marker == 0xda || marker == 0xd9) return std::nullopt;  // pixel data before any frame
        at += 2 + big16(bytes, at + 2);
    }
    return std::nullopt;
}

// A TIFF's size is in the ImageWidth (256) and ImageLength (257) entries of its first directory.
std::optional<DeclaredSize> tiffSides(std::string_view bytes) {
    const bool little = bytes[0] == 'I';
    auto read16 = [&](std::size_t at) { return little ? little16(bytes, at) : big16(bytes, at); };
    auto read32 = [&](std::size_t at) { return little ? little32(bytes, at) : big32(bytes, at); };
    if (bytes.size() < 8) return std::nullopt;
    const std::size_t directory = read32(4);
    if (directory > bytes.size() || bytes.size() - directory < 2) return std::nullopt;
    const std::size_t entries = read16(directory);
    std::int64_t sides[2] = {-1, -1};
    for (std::size_t k = 0; k < entries; ++k) {
        const std::size_t entry = directory + 2 + 12 * k;
        if (entry + 12 > bytes.size()) break;
        const std::uint32_t tag = read16(entry), type = read16(entry + 2);
        if (tag != 256 && tag != 257) continue;
        sides[tag - 256] = type == 3 ? read16(entry + 8) : read32(entry + 8);  // SHORT or LONG
    }
    if (sides[0] < 0 || sides[1] < 0) return std::nullopt;
    return DeclaredSize{sides[0], sides[1]};
}

std::optional<DeclaredSize> webpSides(std::string_view bytes) {
    if (startsWith(bytes, "VP8X", 12) && bytes.size() >= 30)
        return DeclaredSize{1 + (little32(bytes, 24) & 0xffffff), 1 + (little32(bytes, 27) & 0xffffff)};
    if (startsWith(bytes, "VP8L", 12) && bytes.size() >= 25) {
        const std::uint32_t bits = little32(bytes, 21);
        return DeclaredSize{1 + (bits & 0x3fff), 1 + ((bits >> 14) & 0x3fff)};
    }
    if (startsWith(bytes, "VP8 ", 12) && bytes.size() >= 30)
        return DeclaredSize{little16(bytes, 26) & 0x3fff, little16(bytes, 28) & 0x3fff};
    return std::nullopt;
}

// An SVG's size is its <svg> element's width and height (each else its viewBox's), which the
// rasteriser makes pixels of. Units other than pixels count at 96 a unit, the largest factor the
// rasteriser uses (inches), so the size is never under-estimated.
std::optional<DeclaredSize> svgSides(std::string_view bytes) {
    const std::size_t open = bytes.substr(0, 4096).find("<svg");
    if (open == std::string_view::npos) return std::nullopt;
    const std::size_t close = bytes.find('>', open);
    const std::string_view tag = bytes.substr(open, close == std::string_view::npos ? 4096 : close - open);
    auto number = [&](std::string_view text, std::size_t& at) -> std::optional<double> {
        while (at < text.size() && (text[at] == ' ' || text[at] == ',')) ++at;
        const std::size_t start = at;
        while (at < text.size() && (std::isdigit(static_cast<unsigned char>(text[at])) || text[at] == '.' ||
                                    text[at] == '-' || text[at] == '+' || text[at] == 'e' || text[at] == 'E'))
            ++at;
        if (at == start) return std::nullopt;
        return std::strtod(std::string(text.substr(start, at - start)).c_str(), nullptr);
    };
    auto attribute = [&](std::string_view name) -> std::optional<std::string_view> {
        for (std::size_t at = tag.find(name); at != std::string_view::npos; at = tag.find(name, at + 1)) {
            const std::size_t value = at + name.size();
            if (at > 0 && tag[at - 1] != ' ' && tag[at - 1] != '\n' && tag[at - 1] != '\t') continue;
            if (value + 1 >= tag.size() || tag[value] != '=' ||
                (tag[value + 1] != '"' && tag[value + 1] != '\''))
                continue;
            const std::size_t end = tag.find(tag[value + 1], value + 2);
            return tag.substr(value + 2,
                              end == std::string_view::npos ? std::string_view::npos : end - value - 2);
        }
        return std::nullopt;
    };
    auto length = [&](std::string_view name) -> std::optional<double> {
        std::optional<std::string_view> text = attribute(name);
        if (!text) return std::nullopt;
        std::size_t at = 0;
        std::optional<double> v = number(*text, at);
        if (!v) return std::nullopt;
        const std::string_view unit = text->substr(at);
        return unit.empty() || unit.substr(0, 2) == "px" ? *v : *v * 96;
    };
    std::optional<double> width = length("width"), height = length("height");
    if (std::optional<std::string_view> box = attribute("viewBox")) {
        std::size_t at = 0;
        std::optional<double> x = number(*box, at), y = number(*box, at), w = number(*box, at),
                              h = number(*box, at);
        if (x && y && w && h) {
            if (!width) width = *w;
            if (!height) height = *h;
        }
    }
    if (!width || !height) return std::nullopt;
    auto side = [](double v) -> std::int64_t {
        return v > 1e12 || !(v == v) ? std::int64_t(1e12) : std::int64_t(std::ceil(std::max(v, 0.0)));
    };
    return DeclaredSize{side(*width), side(*height)};
}

}  // namespace

ImageFormat imageFormatOf(std::string_view bytes) {
    if (startsWith(bytes, "\x89PNG\r\n\x1a\n")) return ImageFormat::png;
    if (startsWith(bytes, "GIF87a") || startsWith(bytes, "GIF89a")) return ImageFormat::gif;
    if (startsWith(bytes, "\xff\xd8\xff")) return ImageFormat::jpeg;
    if (startsWith(bytes, "\xff\x0a") || startsWith(bytes, std::string_view("\0\0\0\x0cJXL ", 8)))
        return ImageFormat::jxl;
    if (startsWith(bytes, "qoif")) return ImageFormat::qoi;
    if (startsWith(bytes, "RIFF") && startsWith(bytes, "WEBP", 8)) return ImageFormat::webp;
    if (startsWith(bytes, std::string_view("II*\0", 4)) || startsWith(bytes, std::string_view("MM\0*", 4)))
        return ImageFormat::tiff;
    if (startsWith(bytes, "gimp xcf ")) return ImageFormat::xcf;
    if (startsWith(bytes, "FORM") && (startsWith(bytes, "ILBM", 8) || startsWith(bytes, "PBM ", 8)))
        return ImageFormat::lbm;
    if (startsWith(bytes, "/* XPM */")) return ImageFormat::xpm;
    if (startsWith(bytes, "P7 332")) return ImageFormat::xv;
    if (bytes.size() >= 3 && bytes[0] == 'P' && bytes[1] >= '1' && bytes[1] <= '6' &&
        std::isspace(static_cast<unsigned char>(bytes[2])))
        return ImageFormat::pnm;
    if (startsWith(bytes, "8BPS")) return ImageFormat::psd;
    if (startsWith(bytes, "ftyp", 4)) {
        if (startsWith(bytes, "avif", 8) || startsWith(bytes, "avis", 8)) return ImageFormat::avif;
        if (startsWith(bytes, "heic", 8) || startsWith(bytes, "heix", 8) || startsWith(bytes, "mif1", 8))
            return ImageFormat::heif;
    }
    if (startsWith(bytes, "BM")) return ImageFormat::bmp;
    if (startsWith(bytes, "\x0a\x05\x01")) return ImageFormat::pcx;  // ZSoft, version 5, run-length coded
    if (hasTgaFooter(bytes)) return ImageFormat::tga;
    if (isIconDirectory(bytes, 1)) return ImageFormat::ico;
    if (isIconDirectory(bytes, 2)) return ImageFormat::cur;
    if (looksLikeSvg(bytes)) return ImageFormat::svg;
    if (looksLikeTga(bytes)) return ImageFormat::tga;
    return ImageFormat::unknown;
}

const char* imageFormatName(ImageFormat format) {
    switch (format) {
        case ImageFormat::unknown:
            return "unknown";
        case ImageFormat::png:
            return "PNG";
        case ImageFormat::bmp:
            return "BMP";
        case ImageFormat::gif:
            return "GIF";
        case ImageFormat::jpeg:
            return "JPEG";
        case ImageFormat::pnm:
            return "PNM";
        case ImageFormat::qoi:
            return "QOI";
        case ImageFormat::webp:
            return "WebP";
        case ImageFormat::tiff:
            return "TIFF";
        case ImageFormat::xcf:
            return "GIMP XCF";
        case ImageFormat::pcx:
            return "PCX";
        case ImageFormat::lbm:
            return "LBM";
        case ImageFormat::xpm:
            return "XPM";
        case ImageFormat::xv:
            return "XV thumbnail";
        case ImageFormat::svg:
            return "SVG";
        case ImageFormat::ico:
            return "ICO";
        case ImageFormat::cur:
            return "CUR";
        case ImageFormat::tga:
            return "TGA";
        case ImageFormat::avif:
            return "AVIF";
        case ImageFormat::heif:
            return "HEIF";
        case ImageFormat::jxl:
            return "JPEG XL";
        case ImageFormat::psd:
            return "Photoshop PSD";
    }
    return "unknown";
}

std::optional<DeclaredSize> declaredSize(ImageFormat format, std::string_view bytes) {
    switch (format) {
        case ImageFormat::png:
            if (bytes.size() < 24) return std::nullopt;
            return DeclaredSize{big32(bytes, 16), big32(bytes, 20)};
        case ImageFormat::bmp: {
            if (bytes.size() < 26) return std::nullopt;
            if (little32(bytes, 14) == 12) return DeclaredSize{little16(bytes, 18), little16(bytes, 20)};
            const std::int64_t height = static_cast<std::int32_t>(little32(bytes, 22));
            return DeclaredSize{static_cast<std::int32_t>(little32(bytes, 18)),
                                height < 0 ? -height : height};
        }
        case ImageFormat::gif: {  // the first image's: SDL2_image allocates it alone, not the screen
            if (std::optional<GifImage> image = firstGifImage(bytes))
                return DeclaredSize{image->width, image->height};
            if (bytes.size() < 10) return std::nullopt;
            return DeclaredSize{little16(bytes, 6), little16(bytes, 8)};
        }
        case ImageFormat::jpeg:
            return jpegSides(bytes);
        case ImageFormat::pnm:
            return pnmSides(bytes);
        case ImageFormat::xv:
            return xvSides(bytes);
        case ImageFormat::qoi:
            if (bytes.size() < 12) return std::nullopt;
            return DeclaredSize{big32(bytes, 4), big32(bytes, 8)};
        case ImageFormat::webp:
            return webpSides(bytes);
        case ImageFormat::tiff:
            return tiffSides(bytes);
        case ImageFormat::xcf:
            if (bytes.size() < 22) return std::nullopt;
            return DeclaredSize{big32(bytes, 14), big32(bytes, 18)};
        case ImageFormat::pcx:
            if (bytes.size() < 12) return std::nullopt;
            return DeclaredSize{std::int64_t(little16(bytes, 8)) - little16(bytes, 4) + 1,
                                std::int64_t(little16(bytes, 10)) - little16(bytes, 6) + 1};
        case ImageFormat::lbm:
            if (bytes.size() < 24 || !startsWith(bytes, "BMHD", 12)) return std::nullopt;
            return DeclaredSize{big16(bytes, 20), big16(bytes, 22)};
        case ImageFormat::xpm: {  // the first string's first two numbers, as SDL2_image reads them
            const std::size_t open = bytes.find('"');
            const std::size_t close = open == std::string_view::npos ? open : bytes.find('"', open + 1);
            if (close == std::string_view::npos) return std::nullopt;
            long long width = 0, height = 0;
            if (std::sscanf(std::string(bytes.substr(open + 1, close - open - 1)).c_str(), "%lld %lld",
                            &width, &height) != 2)
                return std::nullopt;
            return DeclaredSize{width, height};
        }
        case ImageFormat::tga:
            if (bytes.size() < 18) return std::nullopt;
            return DeclaredSize{little16(bytes, 12), little16(bytes, 14)};
        case ImageFormat::svg:
            return svgSides(bytes);
        default:
            return std::nullopt;
    }
}

}  // namespace polar
