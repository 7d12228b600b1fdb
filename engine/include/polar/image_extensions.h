#pragma once
#include <string>
#include <string_view>

namespace polar {

// The file name endings of the image formats a sprite may be in, PNG first. Only for finding a
// sprite beside its bounds file and naming the bounds beside a sprite: a file's format is always
// told by its first bytes (loadRgbaImage), never by its name.
inline constexpr std::string_view kImageExtensions[] = {
    ".png", ".gif", ".webp", ".tga", ".bmp", ".jpg", ".jpeg", ".tif", ".tiff", ".qoi", ".xcf",
    ".pcx", ".lbm", ".iff",  ".ppm", ".pgm", ".pbm", ".pnm",  ".xpm", ".xv",   ".svg", ".ico"};

// `name` without its image-format ending ("ship.gif" → "ship"), or nothing when it has none.
inline std::string_view withoutImageExtension(std::string_view name) {
    for (std::string_view ext : kImageExtensions)
        if (name.size() > ext.size()) {
            std::string_view end = name.substr(name.size() - ext.size());
            bool same = true;
            for (std::size_t i = 0; i < ext.size(); ++i)
                same = same && (end[i] | 0x20) == ext[i];  // the endings are lower case; files may not be
            if (same) return name.substr(0, name.size() - ext.size());
        }
    return {};
}

}  // namespace polar
