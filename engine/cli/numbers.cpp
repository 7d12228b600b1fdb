#include "numbers.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <type_traits>

namespace polar::cli {

template <class Number>
std::string numberText(Number value) {
    if constexpr (std::is_integral_v<Number>) {
        return std::to_string(value);
    } else {
        char text[64];
        if (std::isfinite(value) && value == std::trunc(value) && std::fabs(value) < 1e15) {
            std::snprintf(text, sizeof text, "%.0f", value);
            return text;
        }
        for (int digits = 1; digits <= 17; ++digits) {
            std::snprintf(text, sizeof text, "%.*g", digits, value);
            if (std::strtod(text, nullptr) == value) break;
        }
        return text;
    }
}

template <class Number>
std::string rangeWords(const Range<Number>& range) {
    const std::string low = numberText(range.low), high = numberText(range.high);
    if constexpr (std::is_integral_v<Number>) {
        // An open end of a whole number is the next one: above 0 is from 1.
        const Number first = range.lowOpen ? static_cast<Number>(range.low + 1) : range.low;
        return "a whole number from " + numberText(first) + " to " + high;
    } else {
        constexpr Number kLowest = std::numeric_limits<Number>::lowest(),
                         kMax = std::numeric_limits<Number>::max();
        if (range.lowOpen)
            return "a number above " + low + (range.high == kMax ? "" : " and at most " + high);
        if (range.low == kLowest && range.high == kMax) return "a finite number";
        if (range.high == kMax) return "a number of " + low + " or more";
        if (range.low == kLowest) return "a number of " + high + " or less";
        return "a number from " + low + " to " + high;
    }
}

namespace {

// Whether `text` has the shape of a decimal number: an optional sign, digits with at most one
// point, an optional exponent. strtod alone would also take spaces, "inf", "nan" and hex.
bool looksDecimal(std::string_view text) {
    std::size_t i = 0;
    if (i < text.size() && (text[i] == '-' || text[i] == '+')) ++i;
    std::size_t digits = 0, points = 0;
    for (; i < text.size() && (std::isdigit(static_cast<unsigned char>(text[i])) || text[i] == '.'); ++i)
        (text[i] == '.' ? points : digits) += 1;
    if (digits == 0 || points > 1) return false;
    if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
        ++i;
        if (i < text.size() && (text[i] == '-' || text[i] == '+')) ++i;
        const std::size_t start = i;
        while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
        if (i == start) return false;
    }
    return i == text.size();
}

}  // namespace

template <class Number>
std::optional<Number> parseNumber(std::string_view text, const Range<Number>& range, std::string& problem) {
    Number value{};
    bool read = false;
    if constexpr (std::is_integral_v<Number>) {
        const char* end = text.data() + text.size();
        const std::from_chars_result r = std::from_chars(text.data(), end, value);
        read = r.ec == std::errc() && r.ptr == end;
    } else {
        if (looksDecimal(text)) {
            const std::string copy(text);
            value = std::strtod(copy.c_str(), nullptr);
            read = std::isfinite(value);
        }
    }
    if (read && range.contains(value)) return value;
    problem = "expected " + rangeWords(range) + ", got " + (text.empty() ? "nothing" : std::string(text));
    return std::nullopt;
}

#define POLAR_CLI_DEFINE(T)                              \
    template std::string numberText<T>(T);               \
    template std::string rangeWords<T>(const Range<T>&); \
    template std::optional<T> parseNumber<T>(std::string_view, const Range<T>&, std::string&);
POLAR_CLI_NUMBER_TYPES(POLAR_CLI_DEFINE)
#undef POLAR_CLI_DEFINE

}  // namespace polar::cli
