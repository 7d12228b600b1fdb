#include "replay/double_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace polar::game {
namespace {

double fromBits(std::uint64_t bits) {
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
}

std::uint64_t bitsOf(double v) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    return bits;
}

// The doubles where the layout changes (fixed ↔ scientific), the ends of the range, and the
// numbers replays hold (tick rates, tunings).
std::vector<double> edgeValues() {
    std::vector<double> values = {0.0,
                                  -0.0,
                                  1.0,
                                  -1.0,
                                  100.0,
                                  1e15,
                                  1e16,
                                  1e20,
                                  1e21,
                                  1e22,
                                  1e23,
                                  0.1,
                                  0.01,
                                  1e-4,
                                  1e-5,
                                  1.5e-7,
                                  123.456,
                                  4.2,
                                  260.0,
                                  0.35,
                                  0.85,
                                  0.14,
                                  60.0,
                                  12345678.0,
                                  1234567890123456789.0,
                                  5e-324,
                                  2.2250738585072014e-308,
                                  std::numeric_limits<double>::max(),
                                  std::numeric_limits<double>::lowest()};
    for (double p = 1; p < 1e25; p *= 10)
        values.push_back(p), values.push_back(p * 1.25), values.push_back(1 / p);
    return values;
}

TEST(DoubleText, ThePrintfLayoutIsToCharsOnEdgeValues) {
    for (double v : edgeValues()) EXPECT_EQ(detail::shortestDoubleByPrintf(v), shortestDouble(v)) << v;
}

TEST(DoubleText, ThePrintfLayoutIsToCharsOnRandomBitPatterns) {
    std::mt19937_64 random(20);
    for (int i = 0; i < 3000; ++i) {
        const double v = fromBits(random());
        if (!std::isfinite(v)) continue;
        ASSERT_EQ(detail::shortestDoubleByPrintf(v), shortestDouble(v)) << bitsOf(v);
    }
}

TEST(DoubleText, ThePrintfLayoutIsToCharsOnGameSizedValues) {
    std::mt19937_64 random(22);
    std::uniform_real_distribution<double> exponent(-12, 22), mantissa(1, 10);
    for (int i = 0; i < 5000; ++i) {
        const double v = mantissa(random) * std::pow(10.0, std::floor(exponent(random)));
        ASSERT_EQ(detail::shortestDoubleByPrintf(v), shortestDouble(v)) << bitsOf(v);
        const double rounded = std::round(v * 1000) / 1000;  // a few decimals, as in tunings
        ASSERT_EQ(detail::shortestDoubleByPrintf(rounded), shortestDouble(rounded)) << bitsOf(rounded);
    }
}

TEST(DoubleText, StrtodReadsWhatFromCharsReads) {
    std::mt19937_64 random(21);
    for (int i = 0; i < 50000; ++i) {
        const double v = fromBits(random());
        if (!std::isfinite(v) || std::fpclassify(v) == FP_SUBNORMAL) continue;
        const std::string text = shortestDouble(v);
        double a = 0, b = 0;
        ASSERT_TRUE(parseFiniteDouble(text, a)) << text;
        ASSERT_TRUE(detail::parseFiniteDoubleByStrtod(text, b)) << text;
        ASSERT_EQ(bitsOf(a), bitsOf(v)) << text;
        ASSERT_EQ(bitsOf(b), bitsOf(v)) << text;
    }
}

TEST(DoubleText, StrtodRefusesWhatFromCharsRefuses) {
    for (const char* text : {"", "+1", " 1", "1 ", "0x10", "1e", "e5", "inf", "-inf", "nan", "1.0.0", "1e400",
                             "--1", "1,5", "."}) {
        double a = 0, b = 0;
        EXPECT_FALSE(parseFiniteDouble(text, a)) << text;
        EXPECT_FALSE(detail::parseFiniteDoubleByStrtod(text, b)) << text;
    }
}

}  // namespace
}  // namespace polar::game
