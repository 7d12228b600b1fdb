#include "platform/png_file.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace polar {

Result<std::string> readPngFile(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return imageError(path, "no such file", "a PNG image");
    if (!std::filesystem::is_regular_file(path, ec))
        return imageError(path, "not a regular file", "a PNG image");
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in && !in.eof()) return imageError(path, "cannot read the file", "a readable PNG image");
    std::string bytes = text.str();
    if (bytes.size() > 0x7fffffffu) return imageError(path, "the file is over 2 GB", "a PNG image");
    return bytes;
}

}  // namespace polar
