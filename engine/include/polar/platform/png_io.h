#pragma once
#include <string>

#include "polar/atomic_file.h"
#include "polar/error.h"
#include "polar/rgba_image.h"

namespace polar {

// Reads a PNG of any colour type (grey, grey+alpha, palette, RGB, RGBA), bit depth (1 to 16) and
// interlacing, with tRNS transparency, as straight-alpha 8-bit RGBA: 16-bit samples become
// round(v·255/65535), no gamma is applied. A missing, unreadable, cut-off or corrupt file (wrong
// CRC or Adler-32), or one over 32767 pixels a side, is an Error naming it, never a crash, and
// nothing is printed.
Result<RgbaImage> loadPng(const std::string& path);
// The PNG file's bytes for an image, encoded in memory.
Result<std::string> encodePng(const RgbaImage& image);
// Writes a PNG through writeFileAtomically (temporary file, flush, rename), so a crash leaves the
// old file or the new one, never a torn one. `fault` injects I/O failures in tests.
std::optional<Error> savePng(const RgbaImage& image, const std::string& path,
                             const AtomicWriteFault& fault = {});
}  // namespace polar
