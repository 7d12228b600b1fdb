// polarcade-collide --accuracy, run as a user runs it: the level overrides the scene's, and a bad
// level is one line on stderr with exit code 2.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct Outcome {
    int exitCode = -1;
    std::string out;
    std::string err;
};

std::string slurp(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

Outcome collide(const std::vector<std::string>& args) {
    static int counter = 0;
    fs::path dir = fs::path(testing::TempDir()) /
                   ("polar-accuracy-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    fs::create_directories(dir);
    std::string command = "'" + std::string(POLARCADE_COLLIDE) + "'";
    for (const std::string& a : args) command += " '" + a + "'";
    command += " >'" + (dir / "out").string() + "' 2>'" + (dir / "err").string() + "'";
    int status = std::system(command.c_str());
    Outcome run{WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir / "out"), slurp(dir / "err")};
    fs::remove_all(dir);
    return run;
}

const std::string kScene = std::string(POLAR_TEST_DATA) + "/accuracy/crossed_rods.json";

std::vector<std::string> hitPairs(const Outcome& r) {
    std::vector<std::string> pairs;
    nlohmann::json doc = nlohmann::json::parse(r.out);  // kept alive for the loop
    for (const auto& p : doc["pairs"])
        if (p["hit"].get<bool>())
            pairs.push_back(p["a"].get<std::string>() + "-" + p["b"].get<std::string>());
    return pairs;
}

TEST(CollideAccuracy, TheLevelDecidesWhatHits) {
    Outcome byDefault = collide({kScene});
    ASSERT_EQ(byDefault.exitCode, 0) << byDefault.err;
    EXPECT_TRUE(hitPairs(byDefault).empty());
    // Read by nearest, each rod's four samples of radius 100 make a disc: that level hits too.
    for (const char* level : {"exact", "circle", "nearest"}) {
        Outcome r = collide({"--accuracy", level, kScene});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(hitPairs(r), std::vector<std::string>{"rod-a-rod-b"}) << level;
    }
    for (const char* level : {"bounds", "chord", "all-radii"}) {
        Outcome r = collide({"--all", "--accuracy", level, kScene});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_TRUE(hitPairs(r).empty()) << level;
        EXPECT_EQ(nlohmann::json::parse(r.out)["pairs"].size(), 3u) << level;
    }
}

TEST(CollideAccuracy, ABadLevelIsOneLineAndExitCodeTwo) {
    Outcome r = collide({"--accuracy", "precise", kScene});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("unknown accuracy level \"precise\""), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("\"all-radii\""), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(r.out.empty());
}

}  // namespace
