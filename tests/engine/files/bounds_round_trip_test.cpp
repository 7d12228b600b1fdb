#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "polar/bounds_file.h"
#include "scratch_folder.h"

namespace polar {
namespace {

namespace fs = std::filesystem;

BoundsSpec parse(const std::string& text) {
    Result<BoundsSpec> spec = parseBounds(SourceFile{"test.bounds.json", text});
    EXPECT_TRUE(spec.ok()) << (spec.ok() ? "" : spec.error().message());
    return spec.ok() ? *spec : BoundsSpec{};
}

// Bitwise equality of every number, in file order.
void expectIdentical(const BoundsSpec& a, const BoundsSpec& b) {
    ASSERT_EQ(a.radii.size(), b.radii.size());
    for (std::size_t i = 0; i < a.radii.size(); ++i) {
        EXPECT_EQ(a.radii[i].centre.x(), b.radii[i].centre.x());
        EXPECT_EQ(a.radii[i].centre.y(), b.radii[i].centre.y());
        EXPECT_EQ(std::signbit(a.radii[i].centre.x()), std::signbit(b.radii[i].centre.x()));
        EXPECT_EQ(a.radii[i].interpolate, b.radii[i].interpolate);
        ASSERT_EQ(a.radii[i].samples.size(), b.radii[i].samples.size());
        for (std::size_t k = 0; k < a.radii[i].samples.size(); ++k) {
            EXPECT_EQ(a.radii[i].samples[k][0], b.radii[i].samples[k][0]) << "radii " << i << " sample " << k;
            EXPECT_EQ(a.radii[i].samples[k][1], b.radii[i].samples[k][1]) << "radii " << i << " sample " << k;
        }
    }
}

// A modder's file: comments, samples out of angle order, angles outside [0, 360), numbers that need
// all 17 digits, a default centre, two radii, one without interpolation.
const char* kModdersFile = R"({
  // hand-edited
  "format": 1,
  "radii": [
    {"interpolate": true,
     "samples": [[720, 30], [-90, 24.5], [90.125, 0.1], [180, 31.000000000000004], [45, 1e-3]]},
    {"centre": [-0.0, 3.0000000000000004], "samples": [[359.99999999999994, 12345.678901234567]]}
  ]
})";

TEST(BoundsRoundTrip, LoadSaveLoadIsIdenticalAndKeepsTheModdersOrder) {
    BoundsSpec first = parse(kModdersFile);
    std::string saved = boundsToJson(first);
    BoundsSpec second = parse(saved);
    expectIdentical(first, second);
    // The order and values are the modder's, not sorted or reduced.
    EXPECT_EQ(second.radii[0].samples[0][0], 720.0);
    EXPECT_EQ(second.radii[0].samples[1][0], -90.0);
    EXPECT_EQ(second.radii[0].samples[3][1], 31.000000000000004);
    EXPECT_EQ(second.radii[1].samples[0][1], 12345.678901234567);
    // Saving what was loaded from a saved file gives the same text again.
    EXPECT_EQ(boundsToJson(second), saved);
    // And the runtime radii built from both agree.
    Bounds a = buildBounds(first), b = buildBounds(second);
    ASSERT_EQ(a.size(), b.size());
    for (double phi = 0.0; phi < kTwoPi; phi += 0.01) EXPECT_EQ(a[0].radius(phi), b[0].radius(phi));
}

class BoundsSave : public ::testing::Test {
  protected:
    void SetUp() override { folder_ = polar::testing::freshTestFolder("polar-bounds-save"); }
    void TearDown() override { fs::remove_all(folder_); }
    static std::string read(const fs::path& p) {
        std::ifstream in(p, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        return text.str();
    }
    fs::path folder_;
};

TEST_F(BoundsSave, SavedFileLoadsBackIdentical) {
    BoundsSpec spec = parse(kModdersFile);
    std::string path = (folder_ / "rock.bounds.json").string();
    ASSERT_FALSE(saveBounds(path, spec));
    Result<BoundsSpec> loaded = parseBounds(SourceFile{path, read(path)});
    ASSERT_TRUE(loaded.ok()) << loaded.error().message();
    expectIdentical(spec, *loaded);
    EXPECT_TRUE(loadBounds(path, diskReader()).ok());
}

TEST_F(BoundsSave, AFailedSaveLeavesTheOldFileIntact) {
    std::string path = (folder_ / "rock.bounds.json").string();
    { std::ofstream(path) << kModdersFile; }
    BoundsSpec replacement = parse(R"({"format": 1, "radii": [{"samples": [[0, 5]]}]})");
    std::optional<Error> error =
        saveBounds(path, replacement, [](AtomicWriteStep s) { return s == AtomicWriteStep::kWrite; });
    ASSERT_TRUE(error);
    EXPECT_EQ(read(path), kModdersFile);
    EXPECT_FALSE(fs::exists(path + ".tmp"));
    // The modder's file is still what the game loads.
    expectIdentical(parse(read(path)), parse(kModdersFile));
}

}  // namespace
}  // namespace polar
