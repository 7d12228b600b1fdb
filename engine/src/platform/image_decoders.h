#pragma once
#include <string>

#include "platform/image_format.h"
#include "polar/error.h"
#include "polar/rgba_image.h"

namespace polar {

// The two decoders behind loadRgbaImage, one pair for each platform layer. Both take a file's
// bytes whose signature said which format they are, give straight-alpha RGBA8, and fail with one
// Error naming `path`, printing nothing.

// A PNG: libpng natively (exact, every colour type, bit depth, interlacing and tRNS), stb_image
// in a browser.
Result<RgbaImage> decodePngBytes(const std::string& path, const std::string& bytes);

// Any other format: SDL2_image natively, stb_image in a browser (BMP, GIF, JPEG, TGA and PNM).
Result<RgbaImage> decodeOtherImage(const std::string& path, const std::string& bytes, ImageFormat format);

}  // namespace polar

namespace polar {

// loadRgbaImage after reading the file: the signature picks the decoder, never the name (a GIF
// called ship.png is read as a GIF), and a header that declares more than kMaxImageSide a side is
// refused before a decoder allocates. `path` only names the file in errors.
Result<RgbaImage> decodeImageBytes(const std::string& path, const std::string& bytes);

// The formats this platform layer reads, for messages: "PNG, BMP, GIF, …".
std::string readableImageFormats();

}  // namespace polar
