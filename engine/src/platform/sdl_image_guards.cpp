#include "platform/sdl_image_guards.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <set>
#include <vector>

#include "platform/image_format.h"

namespace polar {

// SDL2_image 2.6's XPM reader crashes on a pixel whose character its colour table does not
// define (a NULL read, with one character a pixel; found by polar-fuzz-image), and trusts the
// header's counts. So an XPM is first read here as that reader reads it, and refused unless every
// pixel it would look up is defined. The reader knows no comments: each string starts at the next
// '"' (one inside a comment too). The header "W H NCOLORS CPP" and the NCOLORS colour lines (each
// its CPP-character key and more) end at the next '"'; a pixel row is the W·CPP bytes after its
// opening '"', and the reader then skips 3 more (the closing '"', ',' and a line break) before
// looking for the next row. The reason, or nothing for a well-formed file.
std::optional<std::string> xpmProblem(std::string_view bytes) {
    std::size_t at = 0;  // where the reader looks for the next string's opening '"'
    auto nextString = [&]() -> std::optional<std::string_view> {
        const std::size_t open = bytes.find('"', at);
        if (open == std::string_view::npos) return std::nullopt;
        const std::size_t close = bytes.find('"', open + 1);
        if (close == std::string_view::npos) return std::nullopt;
        at = close + 1;
        return bytes.substr(open + 1, close - open - 1);
    };
    const std::optional<std::string_view> header = nextString();
    if (!header) return "it has no header string";
    long long w = 0, h = 0, colours = 0, cpp = 0;
    if (std::sscanf(std::string(*header).c_str(), "%lld %lld %lld %lld", &w, &h, &colours, &cpp) != 4 ||
        w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide || colours < 1 || colours > 1 << 24 ||
        cpp < 1 || cpp > 8)
        return "its header is not \"WIDTH HEIGHT COLOURS CHARS-PER-PIXEL\"";
    std::set<std::string_view> keys;
    for (long long k = 1; k <= colours; ++k) {
        const std::optional<std::string_view> line = nextString();
        if (!line)
            return "it ends after " + std::to_string(k - 1) + " colour lines where its header says " +
                   std::to_string(colours);
        if (static_cast<long long>(line->size()) <= cpp)
            return "colour line " + std::to_string(k) + " has no colour after its key";
        keys.insert(line->substr(0, std::size_t(cpp)));
    }
    const std::size_t rowLength = std::size_t(w * cpp);
    for (long long y = 1; y <= h; ++y) {
        const std::size_t open = bytes.find('"', at);
        if (open == std::string_view::npos)
            return "it ends after " + std::to_string(y - 1) + " pixel rows where its header says " +
                   std::to_string(h);
        const std::size_t close = bytes.find('"', open + 1);
        const std::size_t length = (close == std::string_view::npos ? bytes.size() : close) - open - 1;
        if (length != rowLength)
            return "pixel row " + std::to_string(y) + " has " + std::to_string(length) +
                   " characters where its header says " + std::to_string(rowLength);
        if (bytes.size() - close < 3) return "it ends right after pixel row " + std::to_string(y);
        const std::string_view row = bytes.substr(open + 1, rowLength);
        for (std::size_t x = 0; x < rowLength; x += std::size_t(cpp))
            if (!keys.count(row.substr(x, std::size_t(cpp))))
                return "pixel row " + std::to_string(y) + " uses a colour its table does not define";
        at = close + 3;
    }
    return std::nullopt;
}

// SDL2_image 2.6's XCF reader allocates what the file's numbers say and reads into it unchecked:
// a colour map of NUM entries (PROP_COLORMAP, 3·NUM bytes, up to 12 GB; a second of 0 entries
// frees the first twice), and each tile the
// distance to the next tile's offset. Where malloc fails it writes through NULL; an indexed image
// without a colour map it reads through NULL; a layer without PROP_OFFSETS or PROP_VISIBLE it
// places by uninitialised memory (a read far out of bounds in SDL's blit). So the file is followed here as
// that reader follows it: the header (a 14-byte signature, "gimp xcf vNNN" giving the version: offsets 64-bit
// from 11, a precision word from 4), width, height and type, the property list to PROP_END, the layer offsets
// to 0, then each layer (sides, type, name, properties, hierarchy and mask offsets), its hierarchy (sides,
// bytes a pixel, level offsets) and first level (sides, tile offsets), and the channels (sides, name,
// properties). A read past the end gives what SDL's memory reader gives (the bytes there were, then zeros)
// and a seek past it stops at the end.
namespace {

// What a property list held, of what the reader uses.
struct XcfProperties {
    std::uint32_t colourMap = 0;     // PROP_COLORMAP's entries
    std::uint32_t seen = 0;          // bit k: a property of id k (below 32) was there
    std::uint32_t colourLength = 0;  // PROP_COLOR's length
};

class XcfReader {
  public:
    explicit XcfReader(std::string_view bytes) : bytes_(bytes) {}
    std::uint32_t word() {
        std::uint32_t value = 0;
        for (int k = 0; k < 4; ++k, ++at_)
            value = value << 8 | (at_ < bytes_.size() ? static_cast<unsigned char>(bytes_[at_]) : 0u);
        at_ = std::min(at_, bytes_.size());
        return value;
    }
    std::uint64_t offset(unsigned version) {
        const std::uint64_t high = version >= 11 ? word() : 0;
        return high << 32 | word();
    }
    void seek(std::uint64_t to) {  // SDL_RWseek from the start: a negative place is the start
        at_ = to > std::uint64_t(INT64_MAX) ? 0 : std::size_t(std::min<std::uint64_t>(to, bytes_.size()));
    }
    void skip(std::uint64_t count) { at_ = std::size_t(std::min<std::uint64_t>(at_ + count, bytes_.size())); }
    std::size_t left() const { return bytes_.size() - at_; }
    // read_string: a length, then that many bytes if the file holds them; but a length from 2³¹
    // passes its check as negative, and is allocated (up to 4 GB).
    std::optional<std::string> name(const char* whose) {
        const std::uint32_t length = word();
        if (std::int32_t(length) < 0)
            return std::string(whose) + " name of " + std::to_string(length) +
                   " bytes runs past the file's end";
        if (length > 0 && length <= left()) skip(length);
        return std::nullopt;
    }
    // A property list to PROP_END (id 0), or the reason it is refused.
    std::optional<std::string> properties(XcfProperties& found) {
        for (;;) {
            const std::uint32_t id = word(), length = word();
            if (id < 32) found.seen |= 1u << id;
            switch (id) {
                case 1: {  // PROP_COLORMAP: NUM, then 3·NUM bytes (its length is not used)
                    const std::uint64_t entries = word();
                    if (entries == 0)  // the reader reallocs its map to 0 bytes, then frees it again
                        return std::string("it has a colour map of no entries");
                    if (entries * 3 > left())
                        return "its colour map of " + std::to_string(entries) +
                               " entries runs past the file's end";
                    skip(entries * 3);
                    found.colourMap = std::uint32_t(entries);
                    break;
                }
                case 15:  // PROP_OFFSETS: x, y
                    word();
                    word();
                    break;
                case 6:  // PROP_OPACITY
                case 8:  // PROP_VISIBLE
                    word();
                    break;
                case 16:  // PROP_COLOR
                    found.colourLength = length;
                    skip(std::min<std::uint32_t>(length, 24));
                    break;
                case 17:  // PROP_COMPRESSION: read into a 24-byte union, at most
                    skip(std::min<std::uint32_t>(length, 24));
                    break;
                default:
                    skip(length);
            }
            if (id == 0) return std::nullopt;
        }
    }

  private:
    std::string_view bytes_;
    std::size_t at_ = 0;
};

}  // namespace

std::optional<std::string> xcfProblem(std::string_view bytes) {
    if (bytes.size() < 26) return "the file ends inside its header";  // a cut one would come back 0×0
    XcfReader file(bytes);
    const auto digit = [&](std::size_t k) { return bytes[k] >= '0' && bytes[k] <= '9'; };
    const unsigned version =
        bytes[9] == 'v' && digit(10) && digit(11) && digit(12)
            ? unsigned(bytes[10] - '0') * 100 + unsigned(bytes[11] - '0') * 10 + unsigned(bytes[12] - '0')
            : 0;
    file.skip(14);
    file.word();  // width and height: declaredSize's
    file.word();
    const std::uint32_t type = file.word();
    if (version >= 4) file.word();  // precision
    XcfProperties image;
    if (std::optional<std::string> problem = file.properties(image)) return problem;
    std::vector<std::uint64_t> layers;
    while (const std::uint64_t at = file.offset(version)) layers.push_back(at);
    std::vector<std::uint64_t> channels;
    while (const std::uint64_t at = file.offset(version)) channels.push_back(at);
    for (auto at = layers.rbegin(); at != layers.rend(); ++at) {  // the reader goes from the last
        file.seek(std::uint32_t(*at));                            // it keeps a layer's offset in 32 bits
        file.word();
        file.word();
        file.word();
        if (std::optional<std::string> problem = file.name("a layer's")) return problem;
        XcfProperties layer;
        if (std::optional<std::string> problem = file.properties(layer)) return problem;
        // Without these the reader places and shows the layer by uninitialised memory (GIMP
        // always writes both).
        if (!(layer.seen & 1u << 15) || !(layer.seen & 1u << 8))
            return std::string("a layer has no ") + (layer.seen & 1u << 15 ? "PROP_VISIBLE" : "PROP_OFFSETS");
        const std::uint64_t hierarchy = file.offset(version);
        file.seek(hierarchy);
        const std::uint32_t width = file.word(), height = file.word(), depth = file.word();
        if (depth > 4 || width > 20000 || height > 20000) continue;  // the reader says so and skips it
        if (type == 2 && (depth == 1 || depth == 2) && image.colourMap == 0)
            return "it is an indexed image without a colour map";
        const std::uint64_t level = file.offset(version);
        if (level == 0) continue;
        file.seek(level);
        const std::uint32_t levelWidth = file.word(), levelHeight = file.word();
        std::vector<std::uint64_t> tiles;
        while (const std::uint64_t at = file.offset(version)) tiles.push_back(at);
        std::uint64_t tx = 0, ty = 0;
        for (std::size_t j = 0; j < tiles.size(); ++j) {
            const std::uint64_t next = j + 1 < tiles.size() ? tiles[j + 1] : 0;
            if (next > tiles[j] && next - tiles[j] > bytes.size())
                return "tile " + std::to_string(j + 1) + " of a layer would be " +
                       std::to_string(next - tiles[j]) + " bytes in a file of " +
                       std::to_string(bytes.size());
            tx += 64;
            if (tx >= levelWidth) {
                tx = 0;
                ty += 64;
            }
            if (ty >= levelHeight) break;
        }
    }
    for (const std::uint64_t at : channels) {
        file.seek(at);
        file.word();
        file.word();
        if (std::optional<std::string> problem = file.name("a channel's")) return problem;
        XcfProperties channel;
        if (std::optional<std::string> problem = file.properties(channel)) return problem;
        // Without these the reader blends a channel of uninitialised colour and opacity (GIMP
        // always writes them), its colour 3 bytes.
        if (!(channel.seen & 1u << 6) || !(channel.seen & 1u << 8) || !(channel.seen & 1u << 16) ||
            channel.colourLength < 3)
            return "a channel lacks PROP_OPACITY, PROP_VISIBLE or a 3-byte PROP_COLOR";
    }
    return std::nullopt;
}

// SDL2_image 2.6's GIF reader (ReadImage, LWZReadByte) walks each LZW code's prefixes onto a
// stack of 8192 entries without a bound. Its table takes each new entry's prefix from the code
// read before, which may be one not yet defined, so a file can link entries in a loop (it catches
// only a loop of one), and the walk then writes past the stack over the heap (found by
// polar-fuzz-image: an invalid free in IMG_LoadGIF_RW). So the image it decodes is decoded here as
// it decodes it, for as many pixels as it reads, and refused if a walk would pass the stack. Only
// what steers the reader is kept: the prefixes, not the colours.
std::optional<std::string> gifProblem(std::string_view bytes) {
    const std::optional<GifImage> image = firstGifImage(bytes);
    if (!image) return std::nullopt;
    std::size_t at = image->codeSizeAt;
    auto byte = [&](std::size_t k) { return static_cast<unsigned char>(bytes[k]); };
    const int setCodeSize = byte(at++);  // at most 12: firstGifImage gives no other

    // GetDataBlock: a count, then that many bytes (as many as there are, if cut); -1 at the end.
    unsigned char buffer[280] = {};
    auto dataBlock = [&](unsigned char* into) -> int {
        if (at >= bytes.size()) return -1;
        const std::size_t count = byte(at++);
        const std::size_t there = std::min(count, bytes.size() - at);
        std::memcpy(into, bytes.data() + at, there);
        at += there;
        return there == count ? int(count) : -1;
    };
    // GetCode: codes LSB first across the sub-blocks, each refill keeping the two bytes before;
    // a code that would end at or past the bits held reads the next block first, and after the
    // last block (an empty or cut one) there are no more codes. Before the first refill the two
    // bytes kept are those before its buffer, zeros.
    int bit = 0, bitsHeld = 0, bytesHeld = 0;
    bool last = false;
    auto code = [&](int size) -> int {
        if (bit + size >= bitsHeld) {
            if (last) return -1;
            buffer[0] = bytesHeld >= 2 ? buffer[bytesHeld - 2] : 0;
            buffer[1] = bytesHeld >= 2 ? buffer[bytesHeld - 1] : 0;
            const int read = dataBlock(buffer + 2);
            if (read <= 0) last = true;
            bytesHeld = 2 + std::max(read, 0);
            bit = bit - bitsHeld + 16;
            bitsHeld = bytesHeld * 8;
        }
        int value = 0;
        for (int k = 0; k < size; ++k, ++bit) value |= ((buffer[bit / 8] >> (bit % 8)) & 1) << k;
        return value;
    };

    // LWZReadByte: the pixel, or below 0 at the end; kOverflow where the stack would overflow.
    constexpr int kTable = 1 << 12, kStack = 2 * kTable, kOverflow = -100;
    const int clear = 1 << setCodeSize, end = clear + 1;
    int codeSize = setCodeSize + 1, codeLimit = 2 * clear, next = clear + 2;
    std::vector<int> prefix(kTable, 0);
    int stacked = 0, first = 0, previous = 0;
    bool fresh = true;
    auto pixel = [&]() -> int {
        if (fresh) {
            fresh = false;
            do first = previous = code(codeSize);
            while (first == clear);
            return first;
        }
        if (stacked > 0) return --stacked, 0;
        int read = 0;
        while ((read = code(codeSize)) >= 0) {
            if (read == clear) {
                std::fill(prefix.begin(), prefix.end(), 0);
                codeSize = setCodeSize + 1;
                codeLimit = 2 * clear;
                next = clear + 2;
                stacked = 0;
                first = previous = code(codeSize);
                return first;
            }
            if (read == end) return -2;
            int walk = read;
            if (walk >= next) {
                if (++stacked > kStack) return kOverflow;
                walk = previous;
            }
            while (walk >= clear) {
                if (walk >= kTable) return -3;
                if (++stacked > kStack) return kOverflow;
                if (walk == prefix[walk]) return -3;
                walk = prefix[walk];
            }
            if (walk < 0 || walk >= kTable) return -4;
            if (++stacked > kStack) return kOverflow;
            if (next < kTable) {
                prefix[next++] = previous;
                if (next >= codeLimit && codeLimit < kTable) {
                    codeLimit *= 2;
                    ++codeSize;
                }
            }
            previous = read;
            if (stacked > 0) return --stacked, 0;
        }
        return read;
    };

    // ReadImage: pixels row by row (interlaced: every 8th row from 0, from 4, every 4th from 2,
    // every 2nd from 1) until the rows or the data end.
    std::int64_t x = 0, y = 0;
    int pass = 0;
    for (;;) {
        const int value = pixel();
        if (value == kOverflow)
            return "its LZW codes loop back on themselves (SDL_image would overrun its stack)";
        if (value < 0) break;
        if (++x == image->width) {
            x = 0;
            if (image->interlaced) {
                y += pass <= 1 ? 8 : pass == 2 ? 4 : 2;
                if (y >= image->height) {
                    if (++pass > 3) break;
                    y = pass == 1 ? 4 : pass == 2 ? 2 : 1;
                }
            } else {
                ++y;
            }
        }
        if (y >= image->height) break;
    }
    return std::nullopt;
}

}  // namespace polar
