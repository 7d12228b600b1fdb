#include "polar/error.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace polar {

std::string Error::message() const {
    std::ostringstream out;
    if (!file.empty()) {
        out << file;
        if (line > 0) out << ':' << line << ':' << column;
        out << ": ";
    }
    out << what;
    if (!expected.empty()) out << "; expected " << expected;
    return out.str();
}

FileReader diskReader() {
    return [](const std::string& path) -> std::optional<SourceFile> {
        std::error_code ec;
        if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
        std::ifstream in(path, std::ios::binary);
        if (!in) return std::nullopt;
        std::ostringstream text;
        text << in.rdbuf();
        if (in.bad()) return std::nullopt;
        return SourceFile{path, text.str()};
    };
}

std::string resolveRelative(const std::string& file, const std::string& relative) {
    std::filesystem::path rel(relative);
    if (rel.is_absolute()) return rel.lexically_normal().generic_string();
    std::filesystem::path joined = std::filesystem::path(file).parent_path() / rel;
    return joined.lexically_normal().generic_string();
}

}  // namespace polar
