// The committed sprites and their bounds: enclosure (or, for the cave, avoidance) checked
// independently, the reported slack recomputed, and both the art and the bounds reproducible.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "pixel_truth.h"
#include "polar/authoring/bounds_gen.h"
#include "polar/bounds_file.h"
#include "polar/platform/png_io.h"
#include "sprites.h"

namespace polar {
namespace {

namespace fs = std::filesystem;

// Every committed sprite and the options its bounds were generated with (tools/art/main.cpp).
struct SpriteCase {
    const char* name;
    bool container = false;
    int radii = 1;
};

void PrintTo(const SpriteCase& c, std::ostream* out) {
    *out << c.name;
}

const std::vector<SpriteCase>& sprites() {
    static const std::vector<SpriteCase> cases = {
        {"ship"},          {"rock-large-1"},  {"rock-large-2"}, {"rock-large-3"},    {"rock-medium-1"},
        {"rock-medium-2"}, {"rock-medium-3"}, {"rock-small-1"}, {"rock-small-2"},    {"rock-small-3"},
        {"bullet"},        {"pickup-shield"}, {"pickup-life"},  {"comet", false, 2}, {"cave", true, 1},
        {"saucer"},        {"saucer-small"},  {"mine"},         {"mine-shard"},      {"hunter"},
        {"foe-shot"},      {"pickup-spread"}, {"pickup-rapid"}, {"pickup-barrier"},
    };
    return cases;
}

std::string spritePath(const std::string& name) {
    return std::string(POLAR_ASSET_DIR) + "/sprites/" + name + ".png";
}
std::string boundsPath(const std::string& name) {
    return std::string(POLAR_ASSET_DIR) + "/sprites/" + name + ".bounds.json";
}

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

class CommittedSprite : public ::testing::TestWithParam<SpriteCase> {
  protected:
    void SetUp() override {
        Result<RgbaImage> image = loadPng(spritePath(GetParam().name));
        ASSERT_TRUE(image.ok()) << image.error().message();
        mask_ = alphaMaskOf(*image);
        // Exactly the game's loader.
        Result<BoundsPtr> bounds = loadBounds(boundsPath(GetParam().name), diskReader());
        ASSERT_TRUE(bounds.ok()) << bounds.error().message();
        bounds_ = **bounds;
        Result<BoundsSpec> spec =
            parseBounds(SourceFile{boundsPath(GetParam().name), readText(boundsPath(GetParam().name))});
        ASSERT_TRUE(spec.ok());
        spec_ = *spec;
    }
    AlphaMask mask_;
    Bounds bounds_;
    BoundsSpec spec_;
};

TEST_P(CommittedSprite, BoundsEncloseEveryOpaquePixelOrAvoidEveryWall) {
    PixelSet opaque = PixelSet::opaque(mask_);
    ASSERT_EQ(bounds_.size(), static_cast<std::size_t>(GetParam().radii));
    for (const Bound& r : bounds_) EXPECT_TRUE(r.interpolate());
    if (GetParam().container) {
        EXPECT_TRUE(truth::avoidsEveryWall(opaque, bounds_[0]));
    } else {
        EXPECT_TRUE(truth::enclosesEveryPixel(opaque, bounds_));
    }
}

TEST_P(CommittedSprite, ReportedSlackMatchesAnIndependentMeasure) {
    PixelSet opaque = PixelSet::opaque(mask_);
    std::vector<PixelSet> parts = GetParam().container ? std::vector<PixelSet>{opaque}
                                                       : splitAlongPrincipalAxis(opaque, GetParam().radii);
    ASSERT_EQ(parts.size(), bounds_.size());
    for (std::size_t k = 0; k < parts.size(); ++k) {
        // What `gen` prints for these bounds.
        FitQuality reported = measureFit(parts[k], bounds_[k], GetParam().container);
        truth::Slack slack = truth::slackOf(parts[k], bounds_[k], GetParam().container);
        EXPECT_NEAR(reported.worstSlack, slack.worst, 1e-9) << "radii " << k;
        EXPECT_NEAR(reported.meanSlack, slack.mean, 1e-9) << "radii " << k;
        EXPECT_EQ(reported.worstMiss, 0.0);
        EXPECT_GE(slack.worst, 0.0);
        // Tight: pixel art is square, so a straight-edge outline cannot follow it closer than this.
        EXPECT_LT(slack.mean, GetParam().container ? 1.0 : 1.2) << "radii " << k;
    }
}

TEST_P(CommittedSprite, RegeneratingGivesTheCommittedFile) {
    BoundsGenOptions options;
    options.container = GetParam().container;
    options.radii = GetParam().radii;
    Result<GeneratedBounds> generated = generateBounds(mask_, options);
    ASSERT_TRUE(generated.ok()) << generated.error().message();
    EXPECT_EQ(boundsToJson(generated->spec), readText(boundsPath(GetParam().name)));
}

INSTANTIATE_TEST_SUITE_P(Assets, CommittedSprite, ::testing::ValuesIn(sprites()),
                         [](const ::testing::TestParamInfo<SpriteCase>& info) {
                             std::string name = info.param.name;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

TEST(CommittedSprites, EverySpriteHasBoundsAndIsCovered) {
    std::set<std::string> listed;
    for (const SpriteCase& c : sprites()) listed.insert(c.name);
    int pngs = 0;
    for (const auto& entry : fs::directory_iterator(std::string(POLAR_ASSET_DIR) + "/sprites")) {
        if (entry.path().extension() != ".png") continue;
        ++pngs;
        std::string name = entry.path().stem().string();
        EXPECT_TRUE(listed.count(name)) << name << ".png is not covered by these tests";
        EXPECT_TRUE(fs::exists(boundsPath(name))) << name << ".png has no bounds beside it";
    }
    EXPECT_EQ(pngs, static_cast<int>(sprites().size()));
}

TEST(CommittedSprites, ArtIsReproducible) {
    for (const art::NamedSprite& s : art::drawAll(1979)) {
        Result<RgbaImage> committed = loadPng(spritePath(s.name));
        ASSERT_TRUE(committed.ok()) << committed.error().message();
        RgbaImage drawn = s.canvas.image();
        ASSERT_EQ(drawn.width, committed->width) << s.name;
        ASSERT_EQ(drawn.height, committed->height) << s.name;
        EXPECT_TRUE(drawn.pixels == committed->pixels)
            << s.name << ".png differs from what polarcade-art draws";
    }
}

TEST(CommittedSprites, CaveInteriorIsStarShapedFromTheCentre) {
    Result<RgbaImage> cave = loadPng(spritePath("cave"));
    ASSERT_TRUE(cave.ok());
    AlphaMask mask = alphaMaskOf(*cave);
    ASSERT_EQ(mask.width, 640);
    ASSERT_EQ(mask.height, 360);
    PixelSet walls = PixelSet::opaque(mask);
    truth::RayOracle oracle(walls, Vec2::Zero(), 1e-6);
    // Every free pixel's centre is in plain sight of the image centre: no wall square's interior
    // (shrunk by 1e-6 px, so that grazing a corner does not count) nearer on its ray.
    int free = 0, hidden = 0;
    for (int y = 0; y < mask.height; ++y)
        for (int x = 0; x < mask.width; ++x) {
            if (walls.has(x, y)) continue;
            ++free;
            Vec2 p = mask.pixelCentre(x, y);
            if (p.norm() > oracle.nearestWall(std::atan2(p.y(), p.x())) + 1e-9) ++hidden;
        }
    EXPECT_EQ(hidden, 0);
    // A real arena: most of the screen, walls all round.
    EXPECT_GT(free, 640 * 360 / 2);
    for (int x = 0; x < mask.width; ++x) EXPECT_TRUE(walls.has(x, 0) && walls.has(x, mask.height - 1));
    for (int y = 0; y < mask.height; ++y) EXPECT_TRUE(walls.has(0, y) && walls.has(mask.width - 1, y));
}

TEST(CommittedSprites, ShipFacesPlusX) {
    // Angle 0 faces right: the ship's opaque pixels reach farther right of its centroid than left.
    Result<RgbaImage> ship = loadPng(spritePath("ship"));
    ASSERT_TRUE(ship.ok());
    AlphaMask mask = alphaMaskOf(*ship);
    PixelSet opaque = PixelSet::opaque(mask);
    Vec2 c = opaque.centroid();
    double right = 0, left = 0;
    for (int y = 0; y < opaque.height; ++y)
        for (int x = 0; x < opaque.width; ++x)
            if (opaque.has(x, y)) {
                double dx = mask.pixelCentre(x, y).x() - c.x();
                right = std::max(right, dx), left = std::max(left, -dx);
            }
    EXPECT_GT(right, left + 3.0);
}

}  // namespace
}  // namespace polar
