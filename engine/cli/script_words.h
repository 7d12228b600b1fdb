#pragma once
#include <string>
#include <vector>

namespace polar::cli {

// One word of a script line and where it starts, for file:line:column errors.
struct ScriptWord {
    std::string text;
    int column = 0;  // 1-based
};

// The words of one line of a script (the game's `--script` and the bounds editor's both): split
// at spaces, tabs and a '\r' left by a CRLF file; '#' starts a comment to the end of the line.
inline std::vector<ScriptWord> scriptWords(const std::string& line) {
    std::vector<ScriptWord> out;
    std::size_t i = 0;
    while (i < line.size() && line[i] != '#') {
        if (line[i] == ' ' || line[i] == '\t' || line[i] == '\r') {
            ++i;
            continue;
        }
        std::size_t j = i;
        while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') ++j;
        out.push_back({line.substr(i, j - i), static_cast<int>(i) + 1});
        i = j;
    }
    return out;
}

}  // namespace polar::cli
