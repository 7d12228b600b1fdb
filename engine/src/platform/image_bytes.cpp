#include "platform/image_bytes.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace polar {

Result<std::string> readImageBytes(const std::string& path, const std::string& expected) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return imageError(path, "no such file", expected);
    if (!std::filesystem::is_regular_file(path, ec)) return imageError(path, "not a regular file", expected);
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in && !in.eof()) return imageError(path, "cannot read the file", expected);
    std::string bytes = text.str();
    if (bytes.size() > 0x7fffffffu) return imageError(path, "the file is over 2 GB", expected);
    return bytes;
}

}  // namespace polar
