#pragma once
#include <optional>
#include <string>
#include <string_view>

namespace polar {

// Checks before SDL2_image 2.6 reads a file, for what its readers trust: each reads the bytes as
// that reader does and gives the reason it would crash or allocate past the file (one phrase, to
// follow "cannot decode the FORMAT image: "), or nothing. No library is used.

// An XPM's strings, found as its reader finds them: every pixel must be in the colour table.
std::optional<std::string> xpmProblem(std::string_view bytes);

// An XCF's structure, followed as its reader follows it: colour maps and tiles inside the file,
// and a colour map where the image is indexed.
std::optional<std::string> xcfProblem(std::string_view bytes);

// A GIF's first image, decoded as its reader decodes it: no LZW code may loop back on itself.
std::optional<std::string> gifProblem(std::string_view bytes);

}  // namespace polar
