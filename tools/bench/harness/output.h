#pragma once
// What a benchmark writes besides its table: CSV, written atomically. (Its output paths are
// checked as the command line is read: cli::Option::outputFile.)
#include <sstream>
#include <string>
#include <string_view>

namespace polar::bench {

// A number with a fixed count of decimals in a CSV cell ("%.4f").
struct Fixed {
    double value;
    int decimals;
};

// A CSV file gathered row by row and written at the end through a temporary file and a rename, so
// an interrupted run leaves any earlier file whole. Numbers are written as a stream writes them
// (6 significant digits) unless given as Fixed; a text cell is quoted when it holds a comma, a
// quote or a line break, or starts or ends with a space.
class Csv {
  public:
    explicit Csv(std::string_view header) { text_ << header << '\n'; }

    template <class... Cells>
    void row(const Cells&... cells) {
        bool first = true;
        ((text_ << (first ? "" : ","), first = false, cell(cells)), ...);
        text_ << '\n';
    }
    std::string text() const { return text_.str(); }
    // Writes the file and says so on stdout; false after a message on stderr when it cannot.
    bool write(const std::string& path) const;

  private:
    void cell(std::string_view text);
    void cell(const std::string& text) { cell(std::string_view(text)); }
    void cell(const char* text) { cell(std::string_view(text)); }
    void cell(Fixed number);
    template <class Number>
    void cell(const Number& number) {
        text_ << number;
    }
    std::ostringstream text_;
};

}  // namespace polar::bench
