// polarcade-bounds check --mod: a mod's scene is read as the game reads it, through the overlay.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "scratch_folder.h"

namespace polar {
namespace {

namespace fs = std::filesystem;

class ModCheck : public ::testing::Test {
  protected:
    void SetUp() override {
        folder_ = polar::testing::freshTestFolder("polar-mod-check");
        fs::create_directories(folder_ / "mymod/scenes");
        fs::create_directories(folder_ / "mymod/sprites");
        // Names the cave and ship of assets/ and a rock bounds file the mod replaces.
        write("mymod/scenes/two.json", R"({"format": 1, "effects": ["collisions", "containers"], "objects": [
  {"name": "cave", "sprite": "../sprites/cave.png", "bounds": "../sprites/cave.bounds.json", "flags": ["container"]},
  {"name": "rock", "sprite": "../sprites/rock-small-1.png", "bounds": "../sprites/rock-small-1.bounds.json"}]})");
        write("mymod/sprites/rock-small-1.bounds.json", R"({"format": 1, "radii": [{"samples": [[0, 8]]}]})");
    }
    void TearDown() override { fs::remove_all(folder_); }

    void write(const std::string& name, const std::string& text) const {
        std::ofstream(folder_ / name, std::ios::binary) << text;
    }
    static std::string read(const fs::path& p) {
        std::ifstream in(p, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        return text.str();
    }
    struct Outcome {
        int exitCode = -1;
        std::string out, err;
    };
    Outcome run(const std::string& args) const {
        std::string command = "cd '" + folder_.string() + "' && '" + std::string(POLAR_BOUNDS_EXE) + "' " +
                              args + " >stdout.txt 2>stderr.txt";
        int status = std::system(command.c_str());
        return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read(folder_ / "stdout.txt"),
                read(folder_ / "stderr.txt")};
    }

    fs::path folder_;
};

TEST_F(ModCheck, AModSceneNamingAssetsNeedsTheOverlay) {
    Outcome plain = run("check mymod/scenes/two.json");
    EXPECT_EQ(plain.exitCode, 2);
    EXPECT_NE(plain.err.find("cannot read bounds file \"mymod/sprites/cave.bounds.json\""), std::string::npos)
        << plain.err;
    EXPECT_NE(plain.err.find("--mod MODFOLDER"), std::string::npos) << "the hint: " << plain.err;

    Outcome overlaid = run("check --mod mymod mymod/scenes/two.json");
    EXPECT_EQ(overlaid.exitCode, 0) << overlaid.err;
    EXPECT_EQ(overlaid.out, "mymod/scenes/two.json: ok (scene, 2 objects)\n");
}

TEST_F(ModCheck, AnErrorInAModFileNamesTheFileOnDisk) {
    write("mymod/sprites/rock-small-1.bounds.json",
          "{\"format\": 1,\n \"radii\": [{\"samples\": [[0, 0]]}]}");
    Outcome r = run("check --mod mymod mymod/scenes/two.json");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err.rfind("mymod/sprites/rock-small-1.bounds.json:2:", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("radius 0 is not positive"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace polar
