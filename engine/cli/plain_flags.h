#pragma once
// Flags read without CLI11, for a program whose size counts more than its --help: the web page,
// whose arguments come from its address (?lives=1&seed=5&mute) and whose files must gzip to 600 KB.
// CLI11 is about a seventh of the page's code. The rules are the command line's: numbers through
// numbers.h (the same range words), one line for the first problem, naming the flag.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "numbers.h"

namespace polar::cli {

class PlainFlags {
  public:
    // `--name` alone sets `target`.
    void flag(std::string name, bool& target);
    // `--name TEXT`.
    void text(std::string name, std::string& target);
    // `--name NUMBER` within `range`; `given` (when set) says whether it was.
    template <class Number>
    void number(std::string name, Number& target, Range<Number> range = {}, bool* given = nullptr) {
        add(std::move(name), true, [&target, range, given](std::string_view value, std::string& problem) {
            std::optional<Number> read = parseNumber(value, range, problem);
            if (!read) return false;
            target = *read;
            if (given) *given = true;
            return true;
        });
    }

    // Reads `args` (without the program's name). Nothing on success; else one line: "--lives:
    // expected a whole number from 1 to 99, got 0", "--lives: expected a value", "unknown flag
    // --x; expected one of --scene, --seed".
    std::optional<std::string> parse(const std::vector<std::string>& args) const;

  private:
    using Take = std::function<bool(std::string_view value, std::string& problem)>;
    struct Entry {
        std::string name;  // with its dashes
        bool takesValue = false;
        Take take;
    };
    void add(std::string name, bool takesValue, Take take);

    std::vector<Entry> entries_;
};

}  // namespace polar::cli
