#pragma once
#include <string>

#include "polar/error.h"

namespace polar {

// An image-loading error with no line or column: what is wrong with `path`, and what was expected.
inline Error imageError(const std::string& path, std::string what, std::string expected) {
    return Error{path, 0, 0, std::move(what), std::move(expected)};
}

// The bytes of an image file, for a decoder: one clear error when the file is missing, not a
// regular file, unreadable, or over 2 GB (the decoders count bytes in an int). `expected` ends the
// message ("a PNG image").
Result<std::string> readImageBytes(const std::string& path, const std::string& expected);

}  // namespace polar
