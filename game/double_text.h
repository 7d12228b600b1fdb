#pragma once
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace polar::game {

// Doubles as replay files write them: the shortest text that reads back as exactly the same
// double, as std::to_chars(double) gives it (fixed or scientific, whichever is shorter; fixed on a
// tie). Standard libraries without floating-point <charconv> (emscripten's libc++) get the same
// text from the shortest "%.*e" that reads back, laid out the same way.
inline std::string shortestDouble(double v) {
#if defined(__cpp_lib_to_chars)
    char buffer[32];
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
    return std::string(buffer, end);
#else
    if (v == 0) return std::signbit(v) ? "-0" : "0";
    char buffer[40];
    for (int precision = 0; precision <= 17; ++precision) {
        std::snprintf(buffer, sizeof buffer, "%.*e", precision, v);
        if (std::strtod(buffer, nullptr) == v) break;
    }
    // buffer is [-]d[.ddd]e±XX: the digits, and the exponent of the first one.
    std::string text = buffer, sign, digits;
    std::size_t at = 0;
    if (text[0] == '-') sign = "-", at = 1;
    const std::size_t e = text.find('e');
    for (std::size_t i = at; i < e; ++i)
        if (text[i] != '.') digits += text[i];
    const int exponent = std::atoi(text.c_str() + e + 1);
    std::string scientific = sign + digits.substr(0, 1) + (digits.size() > 1 ? "." + digits.substr(1) : "") +
                             (exponent < 0 ? "e-" : "e+") + (std::abs(exponent) < 10 ? "0" : "") +
                             std::to_string(std::abs(exponent));
    std::string fixed = sign;
    const int count = static_cast<int>(digits.size());
    if (exponent < 0) {
        fixed += "0." + std::string(static_cast<std::size_t>(-exponent - 1), '0') + digits;
    } else if (exponent + 1 >= count) {
        fixed += digits + std::string(static_cast<std::size_t>(exponent + 1 - count), '0');
    } else {
        fixed += digits.substr(0, static_cast<std::size_t>(exponent + 1)) + "." +
                 digits.substr(static_cast<std::size_t>(exponent + 1));
    }
    return fixed.size() <= scientific.size() ? fixed : scientific;
#endif
}

// Reads a whole field as a finite double, as std::from_chars does: no leading '+', no spaces, no
// hexadecimal, nothing after the number. False when it is not one.
inline bool parseFiniteDouble(std::string_view text, double& out) {
    if (text.empty() || text[0] == '+') return false;
#if defined(__cpp_lib_to_chars)
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return ec == std::errc() && end == text.data() + text.size() && std::isfinite(out);
#else
    for (char c : text)
        if (!((c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-'))
            return false;
    const std::string copy(text);
    char* end = nullptr;
    out = std::strtod(copy.c_str(), &end);
    return end == copy.c_str() + copy.size() && std::isfinite(out);
#endif
}

}  // namespace polar::game
