#include "output.h"

#include <cstdio>
#include <filesystem>
#include <optional>

#include "polar/atomic_file.h"

namespace polar::bench {

std::string outputPathProblem(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path absolute = fs::absolute(path, ec);
    const fs::path folder = absolute.parent_path();
    if (ec || !fs::is_directory(folder, ec))
        return path + ": no folder " + folder.string() + "; expected a path in an existing folder";
    if (fs::is_directory(absolute, ec)) return path + ": is a folder; expected a file name";
    return "";
}

CLI::Option* addOutputOption(CLI::App& sub, const std::string& name, std::string& path,
                             const std::string& description) {
    return sub.add_option(name, path, description)
        ->check(CLI::Validator([](std::string& value) { return outputPathProblem(value); }, "FILE"));
}

void Csv::cell(std::string_view text) {
    const bool padded = !text.empty() && (text.front() == ' ' || text.back() == ' ');
    if (!padded && text.find_first_of(",\"\n") == std::string_view::npos) {
        text_ << text;
        return;
    }
    text_ << '"';
    for (char c : text) text_ << (c == '"' ? "\"\"" : std::string_view(&c, 1));
    text_ << '"';
}

void Csv::cell(Fixed number) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", number.decimals, number.value);
    text_ << text;
}

bool Csv::write(const std::string& path) const {
    if (std::optional<Error> error = writeFileAtomically(path, text())) {
        std::fprintf(stderr, "%s\n", error->message().c_str());
        return false;
    }
    std::fflush(stdout);
    std::printf("wrote %s\n", path.c_str());
    return true;
}

}  // namespace polar::bench
