#include "polar/bounds_file.h"

#include <gtest/gtest.h>

#include <map>

namespace polar {
namespace {

Result<BoundsSpec> parse(const std::string& text) {
    return parseBounds(SourceFile{"rock.bounds.json", text});
}

// Asserts that `text` fails to load with an error at exactly `where` ("line:column") whose message
// contains each of `fragments` (what is wrong, then what was expected).
void expectError(const std::string& text, const std::string& where, std::vector<std::string> fragments) {
    Result<BoundsSpec> r = parse(text);
    ASSERT_FALSE(r.ok()) << "loaded but should not have:\n" << text;
    const Error& e = r.error();
    EXPECT_EQ(e.file, "rock.bounds.json");
    EXPECT_EQ(std::to_string(e.line) + ":" + std::to_string(e.column), where) << e.message();
    EXPECT_FALSE(e.what.empty());
    EXPECT_FALSE(e.expected.empty()) << e.message();
    for (const std::string& f : fragments)
        EXPECT_NE(e.message().find(f), std::string::npos) << e.message() << "\n  lacks: " << f;
    EXPECT_EQ(e.message().find('\n'), std::string::npos);
    EXPECT_EQ(e.message().rfind("rock.bounds.json:" + where + ": ", 0), 0u) << e.message();
}

const char* kExample =
    R"({"format": 1, "radii": [{"centre": [0, 0], "interpolate": true, "samples": [[0, 30], [90, 24.5], [180, 31], [270, 22]]}]})";

TEST(BoundsFile, ReadsTheDocumentedExample) {
    Result<BoundsSpec> r = parse(kExample);
    ASSERT_TRUE(r.ok()) << r.error().message();
    ASSERT_EQ(r->radii.size(), 1u);
    const BoundSpec& s = r->radii[0];
    EXPECT_EQ(s.centre, Vec2(0, 0));
    EXPECT_TRUE(s.interpolate);
    ASSERT_EQ(s.samples.size(), 4u);
    EXPECT_EQ(s.samples[1], (DegreeSample{90, 24.5}));
    EXPECT_EQ(s.samples[3], (DegreeSample{270, 22}));
    Bounds b = buildBounds(*r);
    ASSERT_EQ(b.size(), 1u);
    EXPECT_TRUE(b[0].interpolate());
    EXPECT_DOUBLE_EQ(b[0].radius(kHalfPi), 24.5);
}

TEST(BoundsFile, DefaultsCommentsAndSeveralRadii) {
    Result<BoundsSpec> r = parse(R"(// two circles and a star
{
  "format": 1, /* always 1 */
  "radii": [
    {"samples": [[0, 5]]},                      // centre [0, 0], no interpolation
    {"centre": [-3.5, 2], "samples": [[0, 1], [90, 2]]}
  ]
})");
    ASSERT_TRUE(r.ok()) << r.error().message();
    ASSERT_EQ(r->radii.size(), 2u);
    EXPECT_EQ(r->radii[0].centre, Vec2(0, 0));
    EXPECT_FALSE(r->radii[0].interpolate);
    EXPECT_EQ(r->radii[1].centre, Vec2(-3.5, 2));
    Bounds b = buildBounds(*r);
    ASSERT_EQ(b.size(), 2u);  // file order kept
    EXPECT_EQ(b[0].radius(1.0), 5);
    EXPECT_EQ(b[1].centre(), Vec2(-3.5, 2));
}

TEST(BoundsFile, AnglesOutsideTheCircleAreAcceptedAndReduced) {
    Result<BoundsSpec> r = parse(R"({"format": 1, "radii": [{"interpolate": true,
        "samples": [[-90, 5], [720, 7], [45, 6], [500, 3]]}]})");
    ASSERT_TRUE(r.ok()) << r.error().message();
    EXPECT_EQ(r->radii[0].samples[0][0], -90);  // the spec keeps what the file said
    Bounds b = buildBounds(*r);
    const auto& s = b[0].samples();
    ASSERT_EQ(s.size(), 4u);
    EXPECT_EQ(s[0].angle, 0.0);
    EXPECT_EQ(s[0].radius, 7);
    EXPECT_DOUBLE_EQ(s[1].angle, degToRad(45));
    EXPECT_DOUBLE_EQ(s[2].angle, degToRad(140));  // 500
    EXPECT_EQ(s[2].radius, 3);
    EXPECT_DOUBLE_EQ(s[3].angle, degToRad(270));  // −90
    EXPECT_EQ(s[3].radius, 5);
    EXPECT_DOUBLE_EQ(b[0].radius(degToRad(-90)), 5);
}

// One test per error kind of part 7 that a bounds file can have.

TEST(BoundsFileErrors, NonFiniteNumber) {
    expectError("{\"format\": 1, \"radii\": [{\"samples\": [[0, 1e400]]}]}", "1:42",
                {"non-finite", "expected a finite number"});
}

TEST(BoundsFileErrors, WrongType) {
    expectError("{\"format\": 1,\n \"radii\": [{\"samples\": [[\"90\", 1]]}]}", "2:26",
                {"found a string", "expected an angle in degrees"});
    expectError("{\"format\": 1,\n \"radii\": [{\"samples\": [[90, 1]], \"interpolate\": 1}]}", "2:50",
                {"found a number", "expected true or false"});
    expectError("{\"format\": 1,\n \"radii\": [{\"centre\": [1], \"samples\": [[90, 1]]}]}", "2:23",
                {"found an array of 1 items", "expected a centre [x, y]"});
    expectError("{\"format\": 1,\n \"radii\": {\"samples\": []}}", "2:11",
                {"found an object", "expected an array of radii objects"});
    expectError("{\"format\": 1, \"radii\": [{\"samples\": [[0, 1, 2]]}]}", "1:38",
                {"found an array of 3 items", "expected a sample [angle in degrees, radius]"});
    expectError("{\"format\": 1, \"radii\": [{\"samples\": [[0]]}]}", "1:38",
                {"found an array of 1 items", "expected a sample [angle in degrees, radius]"});
    expectError("[1, 2]", "1:1", {"found an array", "expected an object"});
}

TEST(BoundsFileErrors, RadiusNotPositive) {
    expectError("{\"format\": 1, \"radii\": [{\"samples\": [\n  [0, 3],\n  [90, 0]]}]}", "3:3",
                {"radius 0 is not positive", "expected a radius > 0"});
    expectError("{\"format\": 1, \"radii\": [{\"samples\": [[0, -2.5]]}]}", "1:38",
                {"radius -2.5 is not positive", "expected a radius > 0"});
}

TEST(BoundsFileErrors, SameAngleAfterReducingModulo360) {
    expectError("{\"format\": 1, \"radii\": [{\"samples\": [\n  [-90, 3],\n  [90, 1],\n  [270, 2]]}]}", "4:3",
                {"angle 270 is the same direction as -90 (sample 1) modulo 360",
                 "expected one sample per direction"});
    expectError("{\"format\": 1, \"radii\": [{\"samples\": [[0, 3], [720, 1]]}]}", "1:46",
                {"angle 720 is the same direction as 0", "one sample per direction"});
}

TEST(BoundsFileErrors, InterpolateWithFewerThanThreeSamples) {
    expectError(
        "{\"format\": 1, \"radii\": [{\"interpolate\": true,\n  \"samples\": [[0, 3], [120, 1]]}]}", "2:14",
        {"interpolate needs at least 3 samples, found 2", "3 or more samples, or \"interpolate\": false"});
}

TEST(BoundsFileErrors, InterpolateWithAGapOf180OrMore) {
    expectError(
        "{\"format\": 1, \"radii\": [{\"interpolate\": true, \"samples\": [\n  [90, 3],\n  [270, 1],\n  "
        "[0, 2]]}]}",
        "2:3", {"a gap of 180 degrees from angle 90 to the next sample at 270", "star-shaped"});
    // Across the wrap: 300 → 100 is a gap of 160, 100 → 200 is 100, 200 → 300 is 100: fine.
    EXPECT_TRUE(
        parse(R"({"format": 1, "radii": [{"interpolate": true, "samples": [[300, 3], [100, 1], [200, 2]]}]})")
            .ok());
    // 10 → 200 is 190.
    expectError(
        "{\"format\": 1, \"radii\": [{\"interpolate\": true, \"samples\": [[200, 3], [10, 1], [300, 2]]}]}",
        "1:69", {"a gap of 190 degrees from angle 10", "gaps under 180 degrees"});
}

TEST(BoundsFileErrors, EmptySamples) {
    expectError("{\"format\": 1, \"radii\": [{\"samples\": []}]}", "1:37",
                {"no samples", "at least one sample"});
}

TEST(BoundsFileErrors, UnknownKey) {
    expectError("{\"format\": 1, \"radii\": [{\"samples\": [[0, 1]],\n    \"interpolated\": true}]}", "2:5",
                {"unknown key \"interpolated\"", "expected one of \"centre\", \"interpolate\", \"samples\""});
    expectError("{\"format\": 1, \"radius\": []}", "1:15",
                {"unknown key \"radius\"", "\"format\", \"radii\""});
}

TEST(BoundsFileErrors, UnsupportedOrMissingFormat) {
    expectError("{\"format\": 2, \"radii\": []}", "1:12", {"unsupported format 2", "expected \"format\": 1"});
    expectError("{\"format\": 0, \"radii\": []}", "1:12", {"unsupported format 0", "expected \"format\": 1"});
    expectError("{\"format\": 1.5, \"radii\": []}", "1:12", {"found 1.5", "the format number 1"});
    expectError("{\"radii\": []}", "1:1", {"missing key \"format\"", "\"format\": 1"});
    expectError("{\"format\": 1}", "1:1", {"missing key \"radii\"", "\"radii\""});
}

TEST(BoundsFileErrors, SyntaxError) {
    expectError("{\"format\": 1, \"radii\": [{\"samples\": [[0 1]]}]}", "1:41", {"syntax error", "expected"});
}

TEST(BoundsFileErrors, DuplicateKey) {
    expectError("{\"format\": 1, \"radii\": [{\"samples\": [[0, 1]],\n \"samples\": [[0, 2]]}]}", "2:2",
                {"duplicate key \"samples\"", "each key once"});
}

TEST(BoundsFileErrors, MissingFile) {
    Result<BoundsPtr> r = loadBounds("no/such.bounds.json", [](const std::string&) { return std::nullopt; });
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().file, "no/such.bounds.json");
    EXPECT_NE(r.error().message().find("cannot read"), std::string::npos);
    Result<BoundsPtr> disk =
        loadBounds(std::string(POLAR_TEST_DATA) + "/bounds/not-there.bounds.json", diskReader());
    ASSERT_FALSE(disk.ok());
    EXPECT_EQ(
        disk.error().message().rfind(std::string(POLAR_TEST_DATA) + "/bounds/not-there.bounds.json: ", 0),
        0u);
}

TEST(BoundsFile, LoadsFromDisk) {
    Result<BoundsPtr> r = loadBounds(std::string(POLAR_TEST_DATA) + "/bounds/rock.bounds.json", diskReader());
    ASSERT_TRUE(r.ok()) << r.error().message();
    ASSERT_EQ((*r)->size(), 1u);
    EXPECT_DOUBLE_EQ((**r)[0].radius(kPi), 31);
}

TEST(BoundsFile, SaveThenLoadChangesNothing) {
    const char* text = R"({"format": 1, "radii": [
        {"centre": [0.1, -2e-7], "interpolate": true,
         "samples": [[270, 22], [-90.25, 1e-3], [720, 30.000000000000004], [123.456789012345678, 0.1], [45, 1e6]]},
        {"samples": [[0, 5]]}]})";
    Result<BoundsSpec> first = parse(text);
    ASSERT_TRUE(first.ok()) << first.error().message();
    std::string saved = boundsToJson(*first);
    Result<BoundsSpec> second = parse(saved);
    ASSERT_TRUE(second.ok()) << second.error().message() << "\n" << saved;
    ASSERT_EQ(second->radii.size(), first->radii.size());
    for (std::size_t i = 0; i < first->radii.size(); ++i) {
        EXPECT_EQ(second->radii[i].centre, first->radii[i].centre);  // bit for bit
        EXPECT_EQ(second->radii[i].interpolate, first->radii[i].interpolate);
        EXPECT_EQ(second->radii[i].samples, first->radii[i].samples);  // order and values
    }
    EXPECT_EQ(second->radii[0].samples[1][0], -90.25);  // not reduced, not reordered
    EXPECT_EQ(second->radii[0].samples[2][1], 30.000000000000004);
    EXPECT_EQ(boundsToJson(*second), saved);  // a fixed point
    EXPECT_NE(saved.find("\"format\": 1"), std::string::npos);
    // An empty list of radii round-trips too.
    Result<BoundsSpec> none = parse(boundsToJson(BoundsSpec{}));
    ASSERT_TRUE(none.ok()) << none.error().message();
    EXPECT_TRUE(none->radii.empty());
}

}  // namespace
}  // namespace polar
