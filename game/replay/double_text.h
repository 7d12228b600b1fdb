#pragma once
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace polar::game {

// Doubles as replay files write them, and back.
//
// Why two ways? std::to_chars and std::from_chars for double are the rule (the shortest text that
// reads back as exactly the same double; fixed or scientific, whichever is shorter, fixed on a
// tie). Emscripten's libc++ lacks them, so there the same text comes from the shortest "%.*e"
// that reads back, laid out as to_chars lays it out; tests/game/double_text_test.cpp holds the
// two equal on the native build.
namespace detail {

inline std::string shortestDoubleByPrintf(double v) {
    if (v == 0) return std::signbit(v) ? "-0" : "0";
    char buffer[320];  // "%.0f" of the largest double has 309 digits
    for (int precision = 0; precision <= 17; ++precision) {
        std::snprintf(buffer, sizeof buffer, "%.*e", precision, v);
        if (std::strtod(buffer, nullptr) == v) break;
    }
    // buffer is [-]d[.ddd]e±XX: the digits, and the exponent of the first one.
    const std::string text = buffer;
    std::string sign, digits;
    std::size_t at = 0;
    if (text[0] == '-') sign = "-", at = 1;
    const std::size_t e = text.find('e');
    for (std::size_t i = at; i < e; ++i)
        if (text[i] != '.') digits += text[i];
    const int exponent = std::atoi(text.c_str() + e + 1);
    const std::string scientific = sign + digits.substr(0, 1) +
                                   (digits.size() > 1 ? "." + digits.substr(1) : "") +
                                   (exponent < 0 ? "e-" : "e+") + (std::abs(exponent) < 10 ? "0" : "") +
                                   std::to_string(std::abs(exponent));
    std::string fixed = sign;
    const int count = static_cast<int>(digits.size());
    if (exponent < 0) {
        fixed += "0." + std::string(static_cast<std::size_t>(-exponent - 1), '0') + digits;
    } else if (exponent + 1 >= count) {
        // A whole number: to_chars writes its exact digits (as "%.0f"), not the shortest ones
        // padded with zeros; the length is the same.
        std::snprintf(buffer, sizeof buffer, "%.0f", std::fabs(v));
        fixed += buffer;
    } else {
        fixed += digits.substr(0, static_cast<std::size_t>(exponent + 1)) + "." +
                 digits.substr(static_cast<std::size_t>(exponent + 1));
    }
    return fixed.size() <= scientific.size() ? fixed : scientific;
}

// A whole field as a finite double through strtod: only digits, '.', 'e', signs (no spaces, no
// hexadecimal, no inf or nan), nothing after the number, no overflow or underflow.
inline bool parseFiniteDoubleByStrtod(std::string_view text, double& out) {
    if (text.empty() || text[0] == '+') return false;
    for (char c : text)
        if (!((c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-'))
            return false;
    const std::string copy(text);
    char* end = nullptr;
    errno = 0;
    out = std::strtod(copy.c_str(), &end);
    return errno == 0 && end == copy.c_str() + copy.size() && std::isfinite(out);
}

}  // namespace detail

// The shortest text that reads back as exactly `v`.
inline std::string shortestDouble(double v) {
#if defined(__cpp_lib_to_chars)
    char buffer[32];
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
    return std::string(buffer, end);
#else
    return detail::shortestDoubleByPrintf(v);
#endif
}

// Reads a whole field as a finite double, as std::from_chars does (no leading '+'). False when it
// is not one.
inline bool parseFiniteDouble(std::string_view text, double& out) {
#if defined(__cpp_lib_to_chars)
    if (text.empty() || text[0] == '+') return false;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return ec == std::errc() && end == text.data() + text.size() && std::isfinite(out);
#else
    return detail::parseFiniteDoubleByStrtod(text, out);
#endif
}

}  // namespace polar::game
