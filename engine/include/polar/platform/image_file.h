#pragma once
#include <optional>
#include <string>

#include "polar/error.h"
#include "polar/render/canvas.h"
#include "polar/render/image.h"

namespace polar::render {

// Loads a PNG (any colour type, bit depth or interlacing; see loadPng) as a premultiplied Image.
// A missing, unreadable or corrupt file is an Error naming the file, never a crash.
Result<Image> loadImage(const std::string& path);
// Loads a PNG as a Canvas holding its straight-alpha pixels (for comparing pictures exactly).
Result<Canvas> loadCanvas(const std::string& path);
// Writes the canvas as a PNG atomically: into a temporary file in the same folder, then renamed
// over `path`, so `path` is either the old file or the whole new one. Returns the Error, if any.
std::optional<Error> savePng(const Canvas& canvas, const std::string& path);

}  // namespace polar::render
