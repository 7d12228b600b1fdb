// Bad input everywhere: every case gets one clear message, the game goes on where it can,
// and nothing the player had is lost. Most cases run the built executables as a player would.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "files/assets.h"
#include "files/high_scores.h"
#include "polar/platform/png_io.h"
#include "replay/replay.h"
#include "rules/game.h"
#include "run_command.h"
#include "scratch_folder.h"

namespace polar::game {
namespace {

namespace fs = std::filesystem;
using polar::testing::CommandOutcome;
using polar::testing::readFile;
using polar::testing::run;
using polar::testing::runShell;
using polar::testing::shellQuote;

void writeText(const fs::path& p, const std::string& text) {
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
}

std::size_t lineCount(const std::string& text) {
    return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// The temporary files an atomic write or a replay writer would leave in `folder`.
std::vector<std::string> leftovers(const fs::path& folder) {
    std::vector<std::string> out;
    for (const auto& entry : fs::recursive_directory_iterator(folder)) {
        std::string name = entry.path().filename().string();
        if (contains(name, ".tmp") || contains(name, ".part")) out.push_back(name);
    }
    return out;
}

// A scene with the game's cave and ship and one more object whose sprite and bounds a test chooses.
std::string sceneWith(const std::string& sprite, const std::string& bounds) {
    return "{\n"
           "  \"format\": 1,\n"
           "  \"effects\": [\"physics\", \"collisions\", \"response\", \"containers\"],\n"
           "  \"objects\": [\n"
           "    {\"name\": \"cave\", \"sprite\": \"../sprites/cave.png\", \"bounds\": "
           "\"../sprites/cave.bounds.json\",\n"
           "     \"position\": [320, 180], \"flags\": [\"collisions\", \"container\", \"ghost\"]},\n"
           "    {\"name\": \"ship\", \"sprite\": \"../sprites/ship.png\", \"bounds\": "
           "\"../sprites/ship.bounds.json\",\n"
           "     \"position\": [320, 180], \"rotation\": 90, \"flags\": [\"physics\", \"collisions\"]},\n"
           "    {\"name\": \"beacon\", \"sprite\": \"" +
           sprite + "\", \"bounds\": \"" + bounds +
           "\",\n"
           "     \"position\": [560, 300]}\n"
           "  ]\n"
           "}\n";
}

class BadInput : public ::testing::Test {
  protected:
    void SetUp() override { folder_ = polar::testing::freshTestFolder("polar-bad"); }
    void TearDown() override { fs::remove_all(folder_); }

    CommandOutcome game(const std::vector<std::string>& args) const {
        return run(POLARCADE_EXE, args, folder_);
    }
    fs::path mod() const { return folder_ / "mod"; }
    // The mod's beacon scene with a small circle as the beacon's bounds, beside its sprite.
    void writeBeaconMod(const std::string& sprite, const std::string& bounds, bool writeBounds = true) {
        writeText(mod() / "scenes/beacon.json", sceneWith(sprite, bounds));
        if (writeBounds)
            writeText(mod() / "sprites/beacon.bounds.json",
                      "{\"format\": 1, \"radii\": [{\"samples\": [[0, 5]]}]}\n");
    }
    // A copy of a golden replay with one header line replaced.
    fs::path editedReplay(const std::string& from, const std::string& to) const {
        std::string text = readFile(fs::path(POLAR_REPLAY_DIR) / "short.replay");
        std::size_t at = text.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        if (at != std::string::npos) text.replace(at, from.size(), to);
        fs::path copy = folder_ / "edited.replay";
        writeText(copy, text);
        // The golden replay's screenshot lies beside it; the copy needs it too.
        fs::copy_file(fs::path(POLAR_REPLAY_DIR) / "short-600.png", folder_ / "short-600.png",
                      fs::copy_options::overwrite_existing);
        return copy;
    }

    fs::path folder_;
};

// ---- pictures and bounds -----------------------------------------------------------------------

TEST_F(BadInput, AMissingPngInAModIsOneLineAndTheGameRuns) {
    writeBeaconMod("../sprites/beacon.png", "../sprites/beacon.bounds.json");  // no beacon.png anywhere
    CommandOutcome r = game(
        {"--headless", "--mod", "mod", "--scene", "beacon", "--ticks", "30", "--screenshot", "30:shot.png"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(
        r.err,
        "sprites/beacon.png: sprite image not found in assets/ or any mod; expected an image file there\n");
    Result<RgbaImage> shot = loadPng((folder_ / "shot.png").string());
    ASSERT_TRUE(shot.ok()) << "the frame is still drawn, with a magenta box for the beacon";
    int magenta = 0;  // the box drawn at the beacon's place, world (560, 300) = canvas (560, 60)
    for (int y = 40; y < 80; ++y)
        for (int x = 540; x < 580; ++x) {
            std::uint32_t p = shot->at(x, y);  // 0xAARRGGBB; the box is drawn at 200/255 over the cave
            magenta += ((p >> 16) & 0xff) > 150 && ((p >> 8) & 0xff) < 90 && (p & 0xff) > 150;
        }
    EXPECT_GT(magenta, 10);

    // Without any frame drawn, the headless run still reads every picture and says so.
    r = game({"--headless", "--mod", "mod", "--scene", "beacon", "--ticks", "5"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(lineCount(r.err), 1u) << r.err;
    EXPECT_TRUE(contains(r.err, "sprites/beacon.png")) << r.err;
}

TEST_F(BadInput, ACorruptPngInAModNamesTheModsFileAndTheGameRuns) {
    const std::string ship = readFile(fs::path(POLAR_ASSET_DIR) / "sprites/ship.png");
    ASSERT_GT(ship.size(), 100u);
    std::string damaged = ship;
    damaged[damaged.size() / 2] ^= 0x10;
    for (const std::string& bytes : {std::string("this is not a picture\n"), ship.substr(0, ship.size() / 2),
                                     damaged, std::string(ship.size(), '\xff')}) {
        writeText(mod() / "sprites/ship.png", bytes);
        CommandOutcome r =
            game({"--headless", "--mod", "mod", "--ticks", "20", "--screenshot", "20:shot.png"});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(lineCount(r.err), 1u) << r.err;
        EXPECT_EQ(r.err.rfind("mod/sprites/ship.png: ", 0), 0u) << "the file on disk, the mod's: " << r.err;
        EXPECT_TRUE(loadPng((folder_ / "shot.png").string()).ok());
    }
}

TEST_F(BadInput, AMissingBoundsFileInAModIsOneLineWithItsPlace) {
    writeBeaconMod("../sprites/ship.png", "../sprites/beacon.bounds.json", false);
    CommandOutcome r = game({"--headless", "--mod", "mod", "--scene", "beacon", "--ticks", "5"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(lineCount(r.err), 1u) << r.err;
    // The scene names it on line 9: the error points there, in the mod's file.
    EXPECT_EQ(
        r.err.rfind("mod/scenes/beacon.json:9:67: cannot read bounds file \"sprites/beacon.bounds.json\"; "
                    "expected an existing .bounds.json file",
                    0),
        0u)
        << r.err;
}

// ---- the data folder ---------------------------------------------------------------------------

TEST_F(BadInput, AnUnwritableDataFolderIsSaidOnceAndTheGameRuns) {
    writeText(folder_ / "not-a-folder", "a file where the data folder should be\n");
    CommandOutcome file = game({"--headless", "--data", "not-a-folder", "--ticks", "10"});
    EXPECT_EQ(file.exitCode, 0) << file.err;
    EXPECT_EQ(
        file.err,
        "polarcade: high scores and replays will not be saved: not-a-folder/: the data folder is a file, "
        "not a folder; expected a writable folder (choose one with --data DIR or POLARCADE_DATA)\n");
    for (const std::string& data :
         {(folder_ / "not-a-folder").string(), (folder_ / "not-a-folder/sub").string()}) {
        CommandOutcome r =
            game({"--headless", "--data", data, "--ticks", "120", "--screenshot", "120:shot.png"});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(lineCount(r.err), 1u) << r.err;
        EXPECT_EQ(r.err.rfind("polarcade: high scores and replays will not be saved: " + data + "/: ", 0), 0u)
            << r.err;
        EXPECT_TRUE(contains(r.err, "; expected a writable folder")) << r.err;
        EXPECT_TRUE(fs::exists(folder_ / "shot.png")) << "the run went on";
    }
    EXPECT_EQ(readFile(folder_ / "not-a-folder"), "a file where the data folder should be\n") << "untouched";

    // With no display, the attract demo still runs; its screenshot is not attempted.
    std::string env = "env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER POLARCADE_DATA=" +
                      shellQuote((folder_ / "not-a-folder").string()) + " timeout 120 ";
    CommandOutcome r = runShell(env + shellQuote(POLARCADE_EXE) + " --mute", folder_);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(lineCount(r.err), 1u) << r.err;
    EXPECT_TRUE(contains(r.err, "high scores and replays will not be saved")) << r.err;
    EXPECT_FALSE(contains(r.out, "saved a screenshot")) << r.out;
}

TEST_F(BadInput, AWritableDataFolderKeepsTheHeadlessGamesReplay) {
    CommandOutcome r = game({"--headless", "--data", "data", "--ticks", "150"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err, "");
    std::vector<fs::path> replays;
    for (const auto& entry : fs::directory_iterator(folder_ / "data/replays"))
        replays.push_back(entry.path());
    ASSERT_EQ(replays.size(), 1u);
    EXPECT_EQ(replays[0].extension(), ".replay");
    EXPECT_TRUE(contains(r.out, "replay saved to data/replays/" + replays[0].filename().string())) << r.out;
    CommandOutcome verify = run(POLARCADE_REPLAY_EXE, {replays[0].string()}, folder_);
    EXPECT_EQ(verify.exitCode, 0) << verify.out << verify.err;
    EXPECT_TRUE(leftovers(folder_ / "data").empty()) << "no temporary file is left";
    std::vector<std::string> top;
    for (const auto& entry : fs::directory_iterator(folder_ / "data"))
        top.push_back(entry.path().filename().string());
    EXPECT_EQ(top, std::vector<std::string>{"replays"}) << "the write probe is gone too";
}

// A run that could not keep its recording is refused before it starts (a CI job trusts exit 0), and
// nothing is left behind: no picture, no ".part".
TEST_F(BadInput, ARecordFileThatCannotBeCreatedIsOneLineAndTheGameDoesNotStart) {
    writeText(folder_ / "file", "x\n");
    CommandOutcome r = game(
        {"--headless", "--ticks", "100", "--record", "file/game.replay", "--screenshot", "100:shot.png"});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(lineCount(r.err), 1u) << r.err;
    EXPECT_EQ(r.err.rfind("polarcade: --record: file/game.replay: file is not a folder; expected a file in a "
                          "writable folder",
                          0),
              0u)
        << r.err;
    EXPECT_FALSE(fs::exists(folder_ / "shot.png")) << "the game did not start";
    EXPECT_FALSE(fs::exists(folder_ / "file.part"));
}

// ---- a full disk -------------------------------------------------------------------------------

TEST_F(BadInput, AFullDiskAtAnyStepOfSavingHighScoresKeepsTheOldTableByteForByte) {
    const std::string path = (folder_ / "highscores.json").string();
    HighScores table = HighScores::load(path);
    table.insert({"OLD", 500, 2});
    ASSERT_FALSE(table.save());
    const std::string before = readFile(path);
    for (AtomicWriteStep failing : {AtomicWriteStep::kOpen, AtomicWriteStep::kWrite, AtomicWriteStep::kSync,
                                    AtomicWriteStep::kRename}) {
        HighScores again = HighScores::load(path);
        ASSERT_TRUE(again.insert({"NEW", 900, 3}).has_value());
        std::optional<Error> error = again.save([&](AtomicWriteStep step) { return step == failing; });
        ASSERT_TRUE(error.has_value()) << static_cast<int>(failing);
        EXPECT_TRUE(contains(error->message(), "no space left on device")) << error->message();
        EXPECT_EQ(error->message().rfind(path + ": ", 0), 0u) << "names the file: " << error->message();
        EXPECT_EQ(readFile(path), before) << "step " << static_cast<int>(failing);
        EXPECT_TRUE(leftovers(folder_).empty());
    }
}

TEST_F(BadInput, EveryUnreadableHighScoreTableIsKeptAside) {
    const std::string path = (folder_ / "highscores.json").string();
    for (int n = 1; n <= 3; ++n) {
        const std::string broken = "{\"format\": 1, \"scores\": [" + std::to_string(n) + "}\n";
        writeText(path, broken);
        std::optional<Error> problem;
        HighScores table = HighScores::load(path, &problem);
        ASSERT_TRUE(problem.has_value());
        EXPECT_EQ(problem->message().rfind(path + ":1:", 0), 0u) << problem->message();
        table.insert({"NEW", 100 * n, 1});
        ASSERT_FALSE(table.save());
        const std::string aside = path + (n == 1 ? ".bad" : ".bad-" + std::to_string(n));
        EXPECT_EQ(readFile(aside), broken) << "the player's file " << n << " is kept";
    }
    EXPECT_EQ(readFile(path + ".bad"), "{\"format\": 1, \"scores\": [1}\n") << "the first is still there";
}

TEST_F(BadInput, AFullDiskWhileRecordingKeepsTheOldReplayByteForByte) {
    const fs::path path = folder_ / "mine.replay";
    const std::string before = readFile(fs::path(POLAR_REPLAY_DIR) / "short.replay");
    AssetFs assets(POLAR_ASSET_DIR);
    struct Case {
        ReplayWriteStep step;
        int when;  // fail the when-th time that step comes (0: the first)
    };
    for (Case c : {Case{ReplayWriteStep::kOpen, 0}, Case{ReplayWriteStep::kFlush, 0},
                   Case{ReplayWriteStep::kFlush, 2}, Case{ReplayWriteStep::kFinish, 0}}) {
        writeText(path, before);
        int seen = 0;
        GameRecorder::Options options;
        options.recordPath = path.string();
        options.fault = [&](ReplayWriteStep step) { return step == c.step && seen++ == c.when; };
        ::testing::internal::CaptureStderr();
        std::optional<GameRecorder> recorder(options);
        Game::Config config;
        config.reader = assets.reader();
        Result<Game> played = Game::create(config);
        ASSERT_TRUE(played.ok());
        recorder->start(*played, assets);
        for (int t = 0; t < 200; ++t) {
            played->tick(t % 3 ? kFire : kTurnLeft);
            recorder->record(t % 3 ? kFire : kTurnLeft, *played);
        }
        recorder->finish(*played, "quit");
        recorder.reset();
        std::string said = ::testing::internal::GetCapturedStderr();
        EXPECT_EQ(lineCount(said), 1u) << said;
        EXPECT_TRUE(contains(said, path.string() + ": ") && contains(said, "no space left on device"))
            << said;
        EXPECT_EQ(readFile(path), before) << "step " << static_cast<int>(c.step) << " #" << c.when;
        fs::remove(path.string() + ".part");  // what was recorded before the failure, kept for the player
    }
}

// ---- replays of another scene or version -------------------------------------------------------

TEST_F(BadInput, AReplayOfAnotherFormatIsOneLineWithItsPlaceAndExitTwo) {
    fs::path replay = editedReplay("polarcade-replay 1\n", "polarcade-replay 7\n");
    const std::string place = replay.string() + ":1:18: replay format 7 cannot be read";
    CommandOutcome r = game({"--headless", "--replay", replay.string(), "--verify"});
    EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
    EXPECT_EQ(lineCount(r.err), 1u) << r.err;
    EXPECT_EQ(r.err.rfind(place, 0), 0u) << r.err;
    EXPECT_TRUE(contains(r.err, "; expected format 1")) << r.err;
    // polarcade-replay reports on stdout, one entry per replay, the message indented under it.
    r = run(POLARCADE_REPLAY_EXE, {replay.string()}, folder_);
    EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
    EXPECT_TRUE(contains(r.out, "\n  " + place)) << r.out;
    EXPECT_TRUE(contains(r.out, "1 unreadable")) << r.out;
}

TEST_F(BadInput, AReplayOfAnotherSceneIsOneLineWithItsPlaceAndExitTwo) {
    fs::path replay = editedReplay("scene scenes/cave.json\n", "scene scenes/tunnel.json\n");
    const std::string place = replay.string() + ":5:1: the recorded scene scenes/tunnel.json is not here";
    CommandOutcome r = game({"--headless", "--replay", replay.string(), "--verify"});
    EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
    EXPECT_EQ(lineCount(r.err), 1u) << r.err;
    EXPECT_EQ(r.err.rfind(place, 0), 0u) << r.err;
    r = run(POLARCADE_REPLAY_EXE, {replay.string()}, folder_);
    EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
    EXPECT_TRUE(contains(r.out, "\n  " + place)) << r.out;

    // The same scene name with other contents (another version of the scene file).
    replay =
        editedReplay("asset 02d086663a083c1b scenes/cave.json", "asset 02d086663a083c1c scenes/cave.json");
    r = game({"--headless", "--replay", replay.string(), "--verify"});
    EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
    EXPECT_EQ(lineCount(r.err), 1u) << r.err;
    EXPECT_EQ(
        r.err.rfind(replay.string() + ":9:1: scenes/cave.json is not the file this replay was recorded with",
                    0),
        0u)
        << r.err;

    // Another game version is no reason to refuse: it is a note, and the checks decide.
    replay = editedReplay("game 0.1.0\n", "game 0.0.9\n");
    r = game({"--headless", "--replay", replay.string(), "--verify"});
    EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_EQ(r.err, replay.string() + ": note: recorded by polarcade 0.0.9 (line 4), played by " +
                         gameVersion() + ": a change in the game between them can make it differ\n");
}

// ---- command lines -----------------------------------------------------------------------------

TEST_F(BadInput, AnUnknownFlagIsOneLineAndExitTwoForEveryExecutable) {
    struct Tool {
        const char* exe;
        std::vector<std::string> before;  // a subcommand, where the tool has them
    };
    for (const Tool& tool :
         {Tool{POLARCADE_EXE, {}}, Tool{POLARCADE_BOUNDS_EXE, {}}, Tool{POLARCADE_BOUNDS_EXE, {"gen"}},
          Tool{POLARCADE_BOUNDS_EXE, {"check"}}, Tool{POLARCADE_BOUNDS_EXE, {"view"}},
          Tool{POLARCADE_COLLIDE_EXE, {}}, Tool{POLARCADE_REPLAY_EXE, {}}, Tool{POLARCADE_BENCH_EXE, {}},
          Tool{POLARCADE_BENCH_EXE, {"scale"}}, Tool{POLARCADE_BENCH_EXE, {"cores"}},
          Tool{POLARCADE_ART_EXE, {}}}) {
        std::vector<std::string> args = tool.before;
        args.push_back("--no-such-flag");
        CommandOutcome r = run(tool.exe, args, folder_);
        std::string what =
            fs::path(tool.exe).filename().string() + (tool.before.empty() ? "" : " " + tool.before[0]);
        EXPECT_EQ(r.exitCode, 2) << what << ": " << r.err;
        EXPECT_EQ(lineCount(r.err), 1u) << what << ": " << r.err;
        EXPECT_TRUE(contains(r.err, "--no-such-flag")) << what << ": " << r.err;
        EXPECT_TRUE(leftovers(folder_).empty() && fs::is_empty(folder_)) << what << " wrote nothing";
    }
}

// The bench harness checks every output path as the command line is read: one line, exit 2, and
// nothing measured (no table, no progress) for each benchmark.
TEST_F(BadInput, EveryBenchmarkRefusesABadOutputPathBeforeMeasuring) {
    const std::string missing = (folder_ / "no-such-folder" / "out.csv").string();
    for (const char* bench : {"accuracy", "cores", "scale", "render", "replay", "snapshot", "seek", "present",
                              "soak", "difficulty"}) {
        CommandOutcome r = run(POLARCADE_BENCH_EXE, {bench, "--csv", missing}, folder_);
        EXPECT_EQ(r.exitCode, 2) << bench << ": " << r.err;
        EXPECT_EQ(lineCount(r.err), 1u) << bench << ": " << r.err;
        EXPECT_TRUE(contains(r.err, "--csv: " + missing + ": the folder ")) << bench << ": " << r.err;
        EXPECT_TRUE(contains(r.err, " does not exist; expected a file in a writable folder"))
            << bench << ": " << r.err;
        EXPECT_TRUE(r.out.empty()) << bench << " measured before refusing: " << r.out;
    }
    for (const char* bench : {"accuracy", "scale", "soak", "difficulty"}) {
        CommandOutcome r = run(POLARCADE_BENCH_EXE, {bench, "--plot", folder_.string()}, folder_);
        EXPECT_EQ(r.exitCode, 2) << bench << ": " << r.err;
        EXPECT_EQ(lineCount(r.err), 1u) << bench << ": " << r.err;
        EXPECT_TRUE(
            contains(r.err, folder_.string() + ": it is a folder; expected a file in a writable folder"))
            << bench;
        EXPECT_TRUE(r.out.empty()) << bench << " measured before refusing: " << r.out;
    }
    EXPECT_TRUE(leftovers(folder_).empty() && fs::is_empty(folder_)) << "nothing written";
}

TEST_F(BadInput, ASceneAskingForAnUnknownEffectIsOneLineWithItsPlace) {
    std::string scene = readFile(fs::path(POLAR_ASSET_DIR) / "scenes/cave.json");
    const std::string effects = "\"effects\": [\"physics\", \"collisions\"";
    std::size_t at = scene.find(effects);
    ASSERT_NE(at, std::string::npos);
    scene.replace(at, effects.size(), "\"effects\": [\"physics\", \"gravity\"");
    writeText(folder_ / "gravity.json", scene);
    const std::string place =
        (folder_ / "gravity.json").string() + ":5:26: unknown effect \"gravity\"; expected one of ";
    CommandOutcome r = game({"--headless", "--scene", (folder_ / "gravity.json").string(), "--ticks", "5"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(lineCount(r.err), 1u) << r.err;
    EXPECT_EQ(r.err.rfind(place, 0), 0u) << r.err;
    r = run(POLARCADE_COLLIDE_EXE, {(folder_ / "gravity.json").string()}, folder_);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(lineCount(r.err), 1u) << r.err;
    EXPECT_TRUE(contains(r.err, place)) << r.err;
}

// ---- SIGINT during a recording -----------------------------------------------------------------

TEST_F(BadInput, SigintDuringARecordingFinishesAReplayThatPlaysBack) {
    const fs::path replay = folder_ / "long.replay";
    const fs::path part = folder_ / "long.replay.part";
    std::fflush(nullptr);  // or the child would write this process's buffered output again
    pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        ::chdir(folder_.c_str());
        std::freopen("out.txt", "w", stdout);
        std::freopen("err.txt", "w", stderr);
        ::execl(POLARCADE_EXE, POLARCADE_EXE, "--headless", "--ticks", "5000000", "--lives", "99", "--record",
                "long.replay", static_cast<char*>(nullptr));
        ::_exit(127);
    }
    // Wait until a few checkpoints have been flushed (one a second of play), then interrupt. The
    // pilot has 99 lives, so its game is still on (a game over would end the recording first).
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    std::size_t checks = 0;
    while (std::chrono::steady_clock::now() < deadline && checks < 5) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        std::string text = readFile(part);
        checks = 0;
        for (std::size_t at = text.find("\ncheck "); at != std::string::npos;
             at = text.find("\ncheck ", at + 1))
            ++checks;
    }
    if (checks < 5)
        ::kill(child, SIGKILL);  // never leave it running
    else
        ::kill(child, SIGINT);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_GE(checks, 5u) << "the recording did not grow";
    ASSERT_TRUE(WIFEXITED(status)) << "polarcade caught SIGINT and exited by itself";
    EXPECT_EQ(WEXITSTATUS(status), 130);
    std::string err = readFile(folder_ / "err.txt");
    EXPECT_EQ(lineCount(err), 1u) << err;
    EXPECT_EQ(err.rfind("polarcade: interrupted after tick ", 0), 0u) << err;

    EXPECT_FALSE(fs::exists(part)) << "finished and renamed into place";
    Result<Replay> read = readReplay(replay.string());
    ASSERT_TRUE(read.ok()) << read.error().message();
    ASSERT_TRUE(read->end.has_value());
    EXPECT_EQ(read->end->reason, "interrupted");
    EXPECT_GE(read->actions.size(), 5 * kCheckpointInterval);
    CommandOutcome verify = run(POLARCADE_REPLAY_EXE, {replay.string()}, folder_);
    EXPECT_EQ(verify.exitCode, 0) << verify.out << verify.err;
    verify = game({"--headless", "--replay", replay.string(), "--verify"});
    EXPECT_EQ(verify.exitCode, 0) << verify.out << verify.err;
}

}  // namespace
}  // namespace polar::game
