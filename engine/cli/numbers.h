#pragma once
// Numbers on the command line. Every numeric flag has a range; anything else (a negative for an
// unsigned value, an overflow, a non-number, a value outside the range) is refused with one message
// that states the range in words: "expected a whole number from 1 to 16, got 17".
#include <limits>
#include <optional>
#include <string>
#include <string_view>

namespace polar::cli {

// The values a numeric flag accepts: `low` to `high`, both included, or only above `low` (lowOpen)
// where `low` itself means nothing (a scale of 0). The default is everything the type holds; for a
// floating-point type, every finite value.
template <class Number>
struct Range {
    Number low = std::numeric_limits<Number>::lowest();
    Number high = std::numeric_limits<Number>::max();
    bool lowOpen = false;

    bool contains(Number value) const { return (lowOpen ? value > low : value >= low) && value <= high; }
};

// The numbers above `low`, up to `high`.
template <class Number>
Range<Number> above(Number low, Number high = std::numeric_limits<Number>::max()) {
    return {low, high, true};
}

// A number as messages and --help write it: a whole number in full, any other in the fewest
// digits that read back as the same value (0.5, 1e-07).
template <class Number>
std::string numberText(Number value);

// The range in words: "a whole number from 1 to 16", "a number from 0.5 to 60", "a number above 0",
// "a finite number".
template <class Number>
std::string rangeWords(const Range<Number>& range);

// `text` read as a decimal Number within `range` (no sign on an unsigned type, no spaces, no hex,
// nothing left over), or nothing with `problem` set to "expected <range in words>, got <text>".
template <class Number>
std::optional<Number> parseNumber(std::string_view text, const Range<Number>& range, std::string& problem);

// The types numeric flags hold (numbers.cpp instantiates each).
#define POLAR_CLI_NUMBER_TYPES(X) \
    X(int)                        \
    X(long)                       \
    X(long long)                  \
    X(unsigned)                   \
    X(unsigned long)              \
    X(unsigned long long)         \
    X(double)
#define POLAR_CLI_DECLARE(T)                                    \
    extern template std::string numberText<T>(T);               \
    extern template std::string rangeWords<T>(const Range<T>&); \
    extern template std::optional<T> parseNumber<T>(std::string_view, const Range<T>&, std::string&);
POLAR_CLI_NUMBER_TYPES(POLAR_CLI_DECLARE)
#undef POLAR_CLI_DECLARE

}  // namespace polar::cli
