#pragma once
#include <optional>
#include <string>

#include "polar/error.h"
#include "polar/render/canvas.h"
#include "polar/render/image.h"
#include "polar/rgba_image.h"

namespace polar {

// Loads an image file of any format the platform reads, as straight-alpha RGBA8. The format is
// told by the file's first bytes, not its name. PNG goes through libpng (see loadPng); every other
// format through SDL2_image natively (BMP, GIF, JPEG, LBM, PCX, PNM, QOI, SVG, TGA, TIFF, WebP,
// XCF, XPM, XV, ICO, CUR) and stb_image in a browser (BMP, GIF, JPEG, TGA, PNM). The alpha rules:
// a format without alpha is opaque; a colour key (GIF's transparent index, XPM's None) is alpha 0
// and every other pixel opaque; a format with alpha keeps it as stored, straight (TIFF's, which
// libtiff hands over premultiplied, is divided back). A missing, unsupported, cut-off or corrupt
// file, or one over 32767 pixels a side, is one Error naming it, never a crash, and nothing is
// printed.
Result<RgbaImage> loadRgbaImage(const std::string& path);

}  // namespace polar

namespace polar::render {

// Loads an image file (any format loadRgbaImage reads) as a premultiplied Image.
// A missing, unreadable or corrupt file is an Error naming the file, never a crash.
Result<Image> loadImage(const std::string& path);
// Loads an image file as a Canvas holding its straight-alpha pixels (for comparing pictures exactly).
Result<Canvas> loadCanvas(const std::string& path);
// Writes the canvas as a PNG atomically: into a temporary file in the same folder, then renamed
// over `path`, so `path` is either the old file or the whole new one. Returns the Error, if any.
std::optional<Error> savePng(const Canvas& canvas, const std::string& path);

}  // namespace polar::render
