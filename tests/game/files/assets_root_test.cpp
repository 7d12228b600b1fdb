// Where the game finds its asset folder: POLARCADE_ASSETS, beside an installed executable, or the
// source tree from the build tree; and one message naming every place tried when none is right.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "files/assets.h"
#include "run_command.h"
#include "scratch_folder.h"

namespace polar::game {
namespace {

namespace fs = std::filesystem;
using polar::testing::CommandOutcome;
using polar::testing::runShell;
using polar::testing::shellQuote;

class AssetRoot : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = polar::testing::freshTestFolder("polar-asset-root");
        makeAssets(dir_ / "prefix/share/polarcade");
        makeAssets(dir_ / "source/assets");
        fs::create_directories(dir_ / "prefix/bin");
        fs::create_directories(dir_ / "build/bin");
    }
    void TearDown() override { fs::remove_all(dir_); }
    static void makeAssets(const fs::path& folder) {
        fs::create_directories(folder / "scenes");
        fs::create_directories(folder / "sprites");
    }
    AssetPlaces places(const fs::path& exe) const {
        AssetPlaces p;
        p.executableFolder = exe.string();
        p.buildBinFolder = (dir_ / "build/bin").string();
        p.sourceAssets = (dir_ / "source/assets").string();
        return p;
    }
    fs::path dir_;
};

TEST_F(AssetRoot, AnInstalledExecutableFindsTheAssetsBesideIt) {
    Result<std::string> root = findAssetRoot(places(dir_ / "prefix/bin"));
    ASSERT_TRUE(root.ok()) << root.error().message();
    EXPECT_EQ(*root, (dir_ / "prefix/share/polarcade").string());
    // Moved as a whole, it still does.
    fs::rename(dir_ / "prefix", dir_ / "moved");
    root = findAssetRoot(places(dir_ / "moved/bin"));
    ASSERT_TRUE(root.ok()) << root.error().message();
    EXPECT_EQ(*root, (dir_ / "moved/share/polarcade").string());
}

TEST_F(AssetRoot, TheBuildTreeUsesTheSourceTreeAndNothingElseDoes) {
    Result<std::string> root = findAssetRoot(places(dir_ / "build/bin"));
    ASSERT_TRUE(root.ok()) << root.error().message();
    EXPECT_EQ(*root, (dir_ / "source/assets").string());
    // An executable elsewhere, with nothing beside it, never reaches into the source tree.
    fs::create_directories(dir_ / "elsewhere/bin");
    root = findAssetRoot(places(dir_ / "elsewhere/bin"));
    ASSERT_FALSE(root.ok());
    EXPECT_EQ(root.error().message(), "no asset folder found; tried " +
                                          (dir_ / "elsewhere/share/polarcade").string() +
                                          " (no such folder); expected a folder with scenes/ and sprites/ "
                                          "(POLARCADE_ASSETS=DIR chooses one)");
}

TEST_F(AssetRoot, TheOverrideIsTheOnlyPlaceWhenSet) {
    AssetPlaces p = places(dir_ / "build/bin");
    p.override = (dir_ / "prefix/share/polarcade").string();
    Result<std::string> root = findAssetRoot(p);
    ASSERT_TRUE(root.ok());
    EXPECT_EQ(*root, *p.override);
    p.override = (dir_ / "source").string();  // a folder, but not an asset folder
    root = findAssetRoot(p);
    ASSERT_FALSE(root.ok()) << "a wrong override is an error, not a quiet fall-back";
    EXPECT_NE(root.error().message().find("tried POLARCADE_ASSETS=" + (dir_ / "source").string() +
                                          " (no scenes/ in it)"),
              std::string::npos)
        << root.error().message();
}

TEST_F(AssetRoot, EveryPlaceTriedIsNamedWithWhyItWasRefused) {
    fs::remove_all(dir_ / "source/assets/sprites");
    std::ofstream(dir_ / "build/share") << "a file";
    Result<std::string> root = findAssetRoot(places(dir_ / "build/bin"));
    ASSERT_FALSE(root.ok());
    EXPECT_EQ(root.error().what, "no asset folder found; tried " + (dir_ / "build/share/polarcade").string() +
                                     " (no such folder), " + (dir_ / "source/assets").string() +
                                     " (no sprites/ in it)");
    AssetPlaces unknown = places("");
    EXPECT_EQ(findAssetRoot(unknown).error().what,
              "no asset folder found; tried nowhere (the executable's folder is unknown)");
}

TEST_F(AssetRoot, TheGameSaysWhereItLookedAndExitsTwo) {
    const std::string missing = (dir_ / "no-such-folder").string();
    CommandOutcome r = runShell("POLARCADE_ASSETS=" + shellQuote(missing) + " " + shellQuote(POLARCADE_EXE) +
                                " --headless --ticks 1");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err,
              "polarcade: no asset folder found; tried POLARCADE_ASSETS=" + missing +
                  " (no such folder); expected a folder with scenes/ and sprites/ (POLARCADE_ASSETS=DIR "
                  "chooses one)\n");
    r = runShell("POLARCADE_ASSETS=" + shellQuote(missing) + " " + shellQuote(POLARCADE_REPLAY_EXE) + " " +
                 shellQuote(POLAR_REPLAY_DIR));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err.rfind("polarcade-replay: no asset folder found; tried POLARCADE_ASSETS=", 0), 0u)
        << r.err;
    // The real asset folder through the override plays as usual.
    r = runShell("POLARCADE_ASSETS=" + shellQuote(POLAR_ASSET_DIR) + " " + shellQuote(POLARCADE_EXE) +
                 " --headless --ticks 1");
    EXPECT_EQ(r.exitCode, 0) << r.err;
}

}  // namespace
}  // namespace polar::game
