// The range rule of every numeric flag (engine/cli/numbers.h) and the output file rule
// (engine/cli/output_file.h), as functions; tests/game/flag_table_test.cpp runs the executables.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>

#include "numbers.h"
#include "output_file.h"
#include "scratch_folder.h"

namespace polar::cli {
namespace {

// The value read, or the problem said.
template <class Number>
std::string readBack(const std::string& text, const Range<Number>& range = {}) {
    std::string problem;
    std::optional<Number> value = parseNumber(text, range, problem);
    return value ? "= " + numberText(*value) : problem;
}

TEST(CliNumbers, UnsignedRefusesSignsOverflowAndAnythingButDecimalDigits) {
    using U64 = std::uint64_t;
    const std::string words = "expected a whole number from 0 to 18446744073709551615, got ";
    EXPECT_EQ(readBack<U64>("0"), "= 0");
    EXPECT_EQ(readBack<U64>("18446744073709551615"), "= 18446744073709551615");
    EXPECT_EQ(readBack<U64>("010"), "= 10") << "decimal, never octal";
    for (const char* bad : {"-5", "-0", "+5", "18446744073709551616", "99999999999999999999999", "0x10", " 5",
                            "5 ", "5x", "1e3", "1.0", "five"})
        EXPECT_EQ(readBack<U64>(bad), words + bad) << bad;
    EXPECT_EQ(readBack<U64>(""), words + "nothing");
    EXPECT_EQ(readBack<unsigned>("4294967296"),
              "expected a whole number from 0 to 4294967295, got 4294967296");
}

TEST(CliNumbers, SignedWholeNumbersHoldTheirRangeAtBothEnds) {
    const Range<int> lives{1, 99};
    EXPECT_EQ(readBack("1", lives), "= 1");
    EXPECT_EQ(readBack("99", lives), "= 99");
    EXPECT_EQ(readBack("0", lives), "expected a whole number from 1 to 99, got 0");
    EXPECT_EQ(readBack("100", lives), "expected a whole number from 1 to 99, got 100");
    EXPECT_EQ(readBack("-1", lives), "expected a whole number from 1 to 99, got -1");
    EXPECT_EQ(readBack<long long>("-9223372036854775808"), "= -9223372036854775808");
    EXPECT_EQ(readBack<long long>("9223372036854775808"),
              "expected a whole number from -9223372036854775808 to 9223372036854775807, got "
              "9223372036854775808");
    // An open low end of a whole number is stated as the next whole number.
    EXPECT_EQ(readBack("0", above(0, 10)), "expected a whole number from 1 to 10, got 0");
    EXPECT_EQ(readBack("1", above(0, 10)), "= 1");
}

TEST(CliNumbers, NumbersAreFiniteDecimalsWithinTheirRange) {
    const Range<double> noise{0.0, 1.0};
    EXPECT_EQ(readBack("0", noise), "= 0");
    EXPECT_EQ(readBack("1", noise), "= 1");
    EXPECT_EQ(readBack(".25", noise), "= 0.25");
    EXPECT_EQ(readBack("2.5e-1", noise), "= 0.25");
    for (const char* bad :
         {"1.0000001", "-0.1", "nan", "inf", "-inf", "0x1p-2", "1e", "1.2.3", ".", "", " 0.5", "0.5 ", "1,5"})
        EXPECT_NE(readBack(bad, noise).find("expected a number from 0 to 1, got "), std::string::npos) << bad;
    EXPECT_EQ(readBack<double>("1e999"), "expected a finite number, got 1e999");
    // Above zero: zero itself is refused, the smallest positive number is not.
    EXPECT_EQ(readBack("0", above(0.0)), "expected a number above 0, got 0");
    EXPECT_EQ(readBack("-2", above(0.0)), "expected a number above 0, got -2");
    EXPECT_EQ(readBack("1e-300", above(0.0)), "= 1e-300");
    EXPECT_EQ(readBack("201", above(0.0, 200.0)), "expected a number above 0 and at most 200, got 201");
}

TEST(CliNumbers, RangesInWords) {
    EXPECT_EQ(rangeWords(Range<int>{1, 16}), "a whole number from 1 to 16");
    EXPECT_EQ(rangeWords(Range<double>{0.5, 60.0}), "a number from 0.5 to 60");
    EXPECT_EQ(rangeWords(Range<double>{0.0, 1e9}), "a number from 0 to 1000000000");
    EXPECT_EQ(rangeWords(Range<double>{}), "a finite number");
    EXPECT_EQ(rangeWords(Range<double>{2.0}), "a number of 2 or more");
    EXPECT_EQ(rangeWords(Range<double>{std::numeric_limits<double>::lowest(), 2.0}), "a number of 2 or less");
    EXPECT_EQ(numberText(0.1), "0.1");
    EXPECT_EQ(numberText(1e-7), "1e-07");
    EXPECT_EQ(numberText(-3.0), "-3");
}

class CliOutputFile : public ::testing::Test {
  protected:
    void SetUp() override { folder_ = polar::testing::freshTestFolder("polar-cli-output"); }
    void TearDown() override { std::filesystem::remove_all(folder_); }
    std::filesystem::path folder_;
};

TEST_F(CliOutputFile, AFileInAnExistingFolderIsFineAndEverythingElseSaysWhy) {
    const std::string f = folder_.string();
    std::ofstream(folder_ / "a-file") << "x";
    std::filesystem::create_directories(folder_ / "a-folder");
    EXPECT_EQ(outputFileProblem(f + "/new.replay"), "");
    EXPECT_EQ(outputFileProblem(f + "/a-file"), "") << "an existing file is replaced";
    EXPECT_EQ(outputFileProblem(f + "/a-folder"), "it is a folder");
    EXPECT_EQ(outputFileProblem(f + "/a-folder/"), "it names a folder, not a file");
    EXPECT_EQ(outputFileProblem(f + "/missing/x"), "the folder " + f + "/missing does not exist");
    EXPECT_EQ(outputFileProblem(f + "/a-file/x"), f + "/a-file is not a folder");
    EXPECT_EQ(outputFileProblem("/proc/nope/x"), "the folder /proc/nope does not exist");
    EXPECT_EQ(outputFileProblem(""), "no file named");
}

}  // namespace
}  // namespace polar::cli
