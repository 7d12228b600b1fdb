#pragma once
#include <cstddef>
#include <string>
#include <utility>
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

// One line of a script that holds words: its 1-based number, its text, its words, and the column an
// error about word `at` names (past the last word: just past the line's end).
struct ScriptLine {
    int number = 0;
    std::string text;
    std::vector<ScriptWord> words;

    int columnOf(std::size_t at) const {
        return at < words.size() ? words[at].column : static_cast<int>(text.size()) + 1;
    }
};

// The lines of a script that hold words, in order (blank and comment-only lines left out).
inline std::vector<ScriptLine> scriptLines(const std::string& text) {
    std::vector<ScriptLine> out;
    int number = 0;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(start, end - start);
        ++number;
        std::vector<ScriptWord> words = scriptWords(line);
        if (!words.empty()) out.push_back({number, std::move(line), std::move(words)});
        start = end + 1;
    }
    return out;
}

}  // namespace polar::cli
