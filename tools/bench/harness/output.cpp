#include "output.h"

#include <cstdio>
#include <optional>

#include "polar/atomic_file.h"

namespace polar::bench {

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
