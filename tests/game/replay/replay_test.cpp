#include "replay/replay.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "rules/bot.h"
#include "scratch_folder.h"

namespace polar::game {
namespace {

namespace fs = std::filesystem;

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

void writeText(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

// Runs a command line; returns its exit code and what it printed (stdout and stderr).
int run(const std::string& command, std::string& output) {
    output.clear();
    std::FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return -1;
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) output.append(buffer, n);
    int status = ::pclose(pipe);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

class ReplayTest : public ::testing::Test {
  protected:
    void SetUp() override { dir_ = polar::testing::freshTestFolder("polar-replay"); }
    void TearDown() override { fs::remove_all(dir_); }

    Game newGame(std::uint64_t seed, const Tuning& tuning = {}) {
        Game::Config config;
        config.reader = assets_.reader();
        config.seed = seed;
        config.tuning = tuning;
        Result<Game> game = Game::create(config);
        EXPECT_TRUE(game.ok()) << (game.ok() ? "" : game.error().message());
        return std::move(*game);
    }

    // Records `ticks` ticks of the demo pilot into `path` the way the game does; returns the inputs.
    std::vector<Actions> record(const std::string& path, std::uint64_t seed, int ticks, bool finish = true) {
        Game game = newGame(seed);
        std::vector<AssetStamp> stamps;
        Game::Config config;
        config.reader = assets_.reader();
        config.seed = seed;
        EXPECT_TRUE(createStampedGame(config, &assets_, path, stamps).ok());
        auto writer = ReplayWriter::open(path, headerFor(game, path, {}, stamps));
        EXPECT_TRUE(writer.ok());
        Bot bot(seed);
        std::vector<Actions> inputs;
        for (int t = 0; t < ticks; ++t) {
            Actions a = bot.decide(game);
            game.tick(a);
            inputs.push_back(a);
            EXPECT_FALSE((*writer)->record(a, game));
        }
        if (finish) {
            EXPECT_FALSE((*writer)->finish(game, "quit"));
        }
        return inputs;
    }

    Replay load(const std::string& path) {
        Result<Replay> replay = readReplay(path);
        EXPECT_TRUE(replay.ok()) << (replay.ok() ? "" : replay.error().message());
        return replay.ok() ? std::move(*replay) : Replay{};
    }

    Verification verify(const Replay& replay) {
        Result<Verification> v = verifyReplay(replay, assets_);
        EXPECT_TRUE(v.ok()) << (v.ok() ? "" : v.error().message());
        return v.ok() ? *v : Verification{};
    }

    // The first input index from `from` on where adding thrust must change the game: the ship is
    // there and the pilot is not thrusting already.
    std::size_t quietTick(const Replay& replay, std::size_t from) {
        Result<Game> game = Game::create(configFor(replay, assets_));
        EXPECT_TRUE(game.ok());
        for (std::size_t t = 0; t < replay.actions.size(); ++t) {
            if (t >= from && game->shipId() != 0 && !(replay.actions[t] & kThrust)) return t;
            game->tick(replay.actions[t]);
        }
        return replay.actions.size();
    }

    AssetFs assets_{POLAR_ASSET_DIR};
    fs::path dir_;
};

TEST_F(ReplayTest, ARecordingVerifiesAndReadsBackAsTheSameText) {
    const std::string path = (dir_ / "game.replay").string();
    std::vector<Actions> inputs = record(path, 11, 200);
    EXPECT_FALSE(fs::exists(path + ".part")) << "renamed into place when finished";
    Replay replay = load(path);
    EXPECT_EQ(replay.actions, inputs);
    EXPECT_EQ(replay.trace.size(), 200u);
    ASSERT_EQ(replay.checkpoints.size(), 4u) << "every 60 ticks and at the end";
    EXPECT_EQ(replay.checkpoints[0].tick, 60u);
    EXPECT_EQ(replay.checkpoints[3].tick, 200u);
    ASSERT_TRUE(replay.end);
    EXPECT_EQ(replay.end->reason, "quit");
    EXPECT_EQ(replay.header.seed, 11u);
    EXPECT_EQ(replay.header.scene, "scenes/cave.json");
    EXPECT_EQ(replay.header.assets.front().name, "scenes/cave.json");
    EXPECT_EQ(formatReplay(replay), readText(path));

    Verification v = verify(replay);
    EXPECT_FALSE(v.desync);
    EXPECT_EQ(v.ticks, 200u);
    EXPECT_EQ(v.checkpoints, 4u);
}

TEST_F(ReplayTest, TheTuningIsRecordedAndUsed) {
    Tuning tuning;
    tuning.startLives = 7;
    tuning.thrust = 123.456789012345;
    Game game = newGame(3, tuning);
    Replay replay;
    replay.path = (dir_ / "t.replay").string();
    replay.header = headerFor(game, replay.path, {}, {});
    for (int t = 0; t < 90; ++t) {
        game.tick(kThrust);
        replay.actions.push_back(kThrust);
        replay.trace.push_back(traceOf(game.hash()));
    }
    replay.checkpoints.push_back(checkpointOf(game));
    Result<Replay> back = parseReplay(replay.path, formatReplay(replay));
    ASSERT_TRUE(back.ok()) << back.error().message();
    EXPECT_EQ(back->header.tuning.startLives, 7);
    EXPECT_EQ(back->header.tuning.thrust, 123.456789012345) << "doubles are written to round-trip exactly";
    EXPECT_FALSE(verify(*back).desync);
}

TEST_F(ReplayTest, OneChangedInputIsReportedAtTheTickWhereTheGameFirstDiffers) {
    const std::string path = (dir_ / "game.replay").string();
    std::vector<Actions> inputs = record(path, 5, 400);
    Replay replay = load(path);
    for (std::size_t from : {30u, 137u, 250u}) {
        SCOPED_TRACE("tampered near tick " + std::to_string(from));
        Replay tampered = replay;
        std::size_t t = quietTick(replay, from);
        ASSERT_LT(t, inputs.size());
        tampered.actions[t] |= kThrust;  // tick t + 1 is played with it
        Verification v = verify(tampered);
        ASSERT_TRUE(v.desync);
        EXPECT_TRUE(v.desync->traced);
        EXPECT_EQ(v.desync->firstTick, t + 1);
        EXPECT_EQ(v.desync->checkpointTick, std::min<std::uint64_t>((t + 1 + 59) / 60 * 60, 400));
        EXPECT_NE(v.desync->expected, v.desync->actual);
        std::string report = describe(*v.desync, path);
        EXPECT_NE(report.find("first differs after tick " + std::to_string(t + 1)), std::string::npos)
            << report;
        EXPECT_NE(report.find("ship"), std::string::npos) << "names the object that differs:\n" << report;
    }
}

TEST_F(ReplayTest, WithoutATraceTheDesyncIsPlacedBetweenCheckpoints) {
    const std::string path = (dir_ / "game.replay").string();
    record(path, 5, 300);
    Replay replay = load(path);
    replay.trace.clear();
    std::size_t t = quietTick(replay, 130);
    ASSERT_LT(t, 180u);
    replay.actions[t] |= kThrust;
    Verification v = verify(replay);
    ASSERT_TRUE(v.desync);
    EXPECT_FALSE(v.desync->traced);
    EXPECT_EQ(v.desync->checkpointTick, 180u);
    EXPECT_EQ(v.desync->firstTick, 121u) << "the checkpoint at 120 still matched";
    EXPECT_NE(describe(*v.desync, path).find("ticks 121-180"), std::string::npos);
}

TEST_F(ReplayTest, ACutOffFileIsReadUpToItsLastCompleteLineAndStillVerifies) {
    const std::string path = (dir_ / "game.replay").string();
    record(path, 8, 250);
    const std::string text = readText(path);
    const std::size_t begin = text.find("begin\n") + 6;
    int cuts = 0;
    for (std::size_t cut = begin; cut < text.size(); cut += 23, ++cuts) {
        SCOPED_TRACE("cut after byte " + std::to_string(cut));
        Result<Replay> replay = parseReplay(path, std::string_view(text).substr(0, cut));
        ASSERT_TRUE(replay.ok()) << replay.error().message();
        EXPECT_FALSE(replay->end);
        std::size_t lastNewline = text.rfind('\n', cut - 1);
        EXPECT_EQ(replay->cutOffLine != 0, lastNewline != cut - 1);
        Verification v = verify(*replay);
        EXPECT_FALSE(v.desync) << describe(*v.desync, path);
        EXPECT_EQ(v.ticks, replay->actions.size());
    }
    EXPECT_GT(cuts, 50);
    Result<Replay> headerOnly = parseReplay(path, std::string_view(text).substr(0, begin - 3));
    ASSERT_FALSE(headerOnly.ok());
    EXPECT_NE(headerOnly.error().message().find("ends before its \"begin\" line"), std::string::npos);
}

TEST_F(ReplayTest, ACrashKeepsTheRecordingUpToTheLastFlush) {
    const std::string path = (dir_ / "game.replay").string();
    writeText(path, "an older replay\n");
    record(path, 4, 150, /*finish=*/false);  // the writer is dropped as a crash would leave it
    EXPECT_EQ(readText(path), "an older replay\n") << "the old file is untouched";
    Replay part = load(path + ".part");
    EXPECT_EQ(part.actions.size(), 120u) << "flushed at every checkpoint";
    EXPECT_FALSE(part.end);
    EXPECT_FALSE(verify(part).desync) << "everything it holds is checked and matches";
    std::optional<Error> incomplete = missingEnd(part);
    ASSERT_TRUE(incomplete) << "verifiers fail it unless told to allow incomplete replays";
    EXPECT_EQ(incomplete->line, part.lines + 1) << "where the end line is missing";
    EXPECT_NE(incomplete->message().find("interrupted (or the file cut short) after tick 120"),
              std::string::npos)
        << incomplete->message();
}

TEST_F(ReplayTest, AFullDiskStopsTheRecordingAndKeepsTheOldFile) {
    const std::string path = (dir_ / "game.replay").string();
    writeText(path, "an older replay\n");
    Game game = newGame(2);
    int flushes = 0;
    auto writer = ReplayWriter::open(path, headerFor(game, path, {}, {}), [&](ReplayWriteStep step) {
        return step == ReplayWriteStep::kFlush && ++flushes == 3;
    });
    ASSERT_TRUE(writer.ok());
    std::optional<Error> error;
    int t = 0;
    for (; t < 300 && !error; ++t) {
        game.tick(kFire);
        error = (*writer)->record(kFire, game);
    }
    ASSERT_TRUE(error);
    EXPECT_EQ(t, 120) << "the second checkpoint's flush failed";
    EXPECT_NE(error->message().find("no space left"), std::string::npos);
    EXPECT_NE(error->message().find(".part"), std::string::npos) << "says where the partial recording is";
    EXPECT_EQ(readText(path), "an older replay\n");
    Replay part = load(path + ".part");
    EXPECT_NE(part.cutOffLine, 0) << "the torn write left an incomplete last line";
    EXPECT_GE(part.actions.size(), 60u);
    EXPECT_LE(part.actions.size(), 120u);
    EXPECT_FALSE(verify(part).desync);
}

TEST_F(ReplayTest, AFailedFinishKeepsTheOldFile) {
    const std::string path = (dir_ / "game.replay").string();
    writeText(path, "an older replay\n");
    Game game = newGame(2);
    auto writer = ReplayWriter::open(path, headerFor(game, path, {}, {}),
                                     [](ReplayWriteStep step) { return step == ReplayWriteStep::kFinish; });
    ASSERT_TRUE(writer.ok());
    for (int t = 0; t < 70; ++t) {
        game.tick(0);
        ASSERT_FALSE((*writer)->record(0, game));
    }
    EXPECT_TRUE((*writer)->finish(game, "quit"));
    EXPECT_EQ(readText(path), "an older replay\n");
    Replay part = load(path + ".part");
    EXPECT_TRUE(part.end) << "complete, only not renamed";
}

TEST_F(ReplayTest, AnotherFormatVersionIsAClearErrorNotADesync) {
    Result<Replay> newer =
        parseReplay("x.replay", "polarcade-replay 2\ngame 9.0.0\nscene scenes/cave.json\nbegin\n");
    ASSERT_FALSE(newer.ok());
    EXPECT_EQ(newer.error().message(),
              std::string("x.replay:1:18: replay format 2 cannot be read by polarcade ") + gameVersion() +
                  " (it was written by polarcade 9.0.0); expected format 1; play it with the polarcade that "
                  "recorded it");
    Result<Replay> other = parseReplay("x.png", "\x89PNG\r\n");
    ASSERT_FALSE(other.ok());
    EXPECT_EQ(other.error().message().rfind("x.png:1:1: not a Polarcade replay", 0), 0u)
        << other.error().message();
}

TEST_F(ReplayTest, BadLinesArePointedAtByLineAndColumn) {
    const std::string head = "polarcade-replay 1\nscene scenes/cave.json\nseed 1\nbegin\n";
    struct Case {
        std::string body, message;
    } cases[] = {
        {"in LF*3 LX\n", "x.replay:5:10: unknown action 'X'"},
        {"in LL\n", "x.replay:5:5: action 'L' twice"},
        {"in F*0\n", "x.replay:5:6: a run of 0 ticks"},
        {"in F*3\ncheck 4 0000000000000000 rng=0000000000000000 score=0 lives=3 wave=1\n",
         "x.replay:6:7: a checkpoint after tick 4 where the inputs so far cover 3 ticks"},
        {"in F*3\ncheck 3 00000000000000zz rng=0000000000000000 score=0 lives=3 wave=1\n",
         "x.replay:6:9: bad checkpoint state hash"},
        {"in F*3\ncheck 3 0000000000000000 rng=0000000000000000 score=0 lives=3\n",
         "x.replay:6:62: the checkpoint lacks wave"},
        {"in F\ntrace AAAA\n", "x.replay:6:7: the trace covers 2 ticks but only 1 have inputs so far"},
        {"objects 1:abcd\n", "x.replay:5:1: an objects line that does not follow a check line"},
        {"in F\nend 1 quit\nin F\n", "x.replay:7:1: \"in\" after the end line"},
        {"in F\nend 1 tickz\n",
         "x.replay:6:7: unknown end reason \"tickz\"; expected one of game-over, quit, "
         "restart, ticks, interrupted"},
        {"in F\nend 1\n", "x.replay:6:6: the line ends too soon; expected \"end TICK REASON\""},
        {"in F\nend 1 quit now\n", "x.replay:6:12: unexpected \"now\""},
        {"in F\nend 2 quit\n", "x.replay:6:5: the end is at tick 2 but the inputs cover 1 ticks"},
        {"in F\nend x quit\n", "x.replay:6:5: bad end tick \"x\""},
        // Three lines count the ticks: the inputs, the trace after them and the checkpoint after
        // that. Where two agree, the third is blamed.
        {"in F*2\ntrace AAAAAA\ncheck 3 CHK\nobjects\n",
         "x.replay:5:4: the inputs on this line run to tick 2, but the trace on line 6 and the checkpoint on "
         "line 7 end at tick 3"},
        {"in F*4\ntrace AAAAAA\ncheck 3 CHK\nobjects\n",
         "x.replay:5:4: the inputs on this line run to tick 4, but the trace on line 6 and the checkpoint on "
         "line 7 end at tick 3"},
        {"in F*3\ntrace AAAAAA\ncheck 4 CHK\nobjects\n",
         "x.replay:7:7: a checkpoint after tick 4 where the inputs so far cover 3 ticks"},
        {"in F*2\ntrace AAAAAA\ncheck 2 CHK\nobjects\n",
         "x.replay:6:7: the trace covers 3 ticks but only 2 have inputs so far"},
        {"in F\ncheck 1 CHK\nin F\n",
         "x.replay:7:1: \"in\" where the objects line of the checkpoint on line 6 belongs"},
        {"jump\n", "x.replay:5:1: unknown line \"jump\""},
    };
    for (Case& c : cases) {
        if (std::size_t at = c.body.find("CHK"); at != std::string::npos)
            c.body.replace(at, 3, "0000000000000000 rng=0000000000000000 score=0 lives=3 wave=1");
        Result<Replay> r = parseReplay("x.replay", head + c.body);
        ASSERT_FALSE(r.ok()) << c.body;
        EXPECT_EQ(r.error().message().rfind(c.message, 0), 0u) << r.error().message();
    }
    Result<Replay> header =
        parseReplay("x.replay", "polarcade-replay 1\nscene scenes/cave.json\ntuning thrust=fast\nbegin\n");
    ASSERT_FALSE(header.ok());
    EXPECT_EQ(header.error().message().rfind("x.replay:3:15: bad tuning value \"fast\" for thrust", 0), 0u)
        << header.error().message();
    Result<Replay> endless = parseReplay(
        "x.replay",
        "polarcade-replay 1\nscene scenes/cave.json\ntuning start-lives=3 extra-life-every=0\nbegin\n");
    ASSERT_FALSE(endless.ok()) << "a new life every 0 points would never stop giving lives";
    EXPECT_EQ(
        endless.error().message().rfind("x.replay:3:39: bad tuning value \"0\" for extra-life-every", 0), 0u)
        << endless.error().message();
    Result<Replay> version =
        parseReplay("x.replay", "polarcade-replay 1\ngame 0.1.X\nscene scenes/cave.json\nbegin\n");
    ASSERT_FALSE(version.ok());
    EXPECT_EQ(version.error().message().rfind("x.replay:2:6: bad game version \"0.1.X\"", 0), 0u)
        << version.error().message();
    Result<Replay> noScene = parseReplay("x.replay", "polarcade-replay 1\nseed 1\nbegin\n");
    ASSERT_FALSE(noScene.ok());
    EXPECT_EQ(noScene.error().message().rfind("x.replay:3:1: the header names no scene", 0), 0u);
}

// Found by the replay fuzzer: "NAME\r\r" kept a '\r' in the name (and in comments and the end
// reason), which formatReplay then wrote as a line ending, so a rewritten replay named another file.
TEST_F(ReplayTest, CarriageReturnsAreBlanksAndARewriteReadsTheSame) {
    const std::string text =
        "polarcade-replay 1\r\n# note\r\r\ngame 0.1.0\r\r\nscene scenes/cave.json \r\r\n"
        "asset 0123456789abcdef sprites/ship.bounds.json\r \r\nbegin\r\nin F*2\r\nend 2 quit\r\r\n";
    Result<Replay> replay = parseReplay("x.replay", text);
    ASSERT_TRUE(replay.ok()) << replay.error().message();
    EXPECT_EQ(replay->header.comments, std::vector<std::string>{"# note"});
    EXPECT_EQ(replay->header.gameVersion, "0.1.0");
    EXPECT_EQ(replay->header.scene, "scenes/cave.json");
    ASSERT_EQ(replay->header.assets.size(), 1u);
    EXPECT_EQ(replay->header.assets[0].name, "sprites/ship.bounds.json");
    ASSERT_TRUE(replay->end.has_value());
    EXPECT_EQ(replay->end->reason, "quit");
    std::string rewritten = formatReplay(*replay);
    EXPECT_EQ(rewritten.find('\r'), std::string::npos);
    Result<Replay> again = parseReplay("x.replay", rewritten);
    ASSERT_TRUE(again.ok()) << again.error().message();
    EXPECT_EQ(formatReplay(*again), rewritten);
}

TEST_F(ReplayTest, AChangedOrMissingSceneIsAClearErrorNotADesync) {
    const std::string path = (dir_ / "game.replay").string();
    record(path, 6, 100);
    Replay replay = load(path);

    // A mod that replaces one rock's bounds: the game would differ for a reason outside the simulation.
    const fs::path mod = dir_ / "mod";
    fs::create_directories(mod / "sprites");
    std::string bounds = readText(fs::path(POLAR_ASSET_DIR) / "sprites/rock-large-2.bounds.json");
    writeText(mod / "sprites/rock-large-2.bounds.json", bounds + "\n// edited\n");
    AssetFs modded(POLAR_ASSET_DIR, {mod.string()});
    Result<ReplayPlayer> player = ReplayPlayer::start(replay, modded);
    ASSERT_FALSE(player.ok());
    int line = 0;
    for (const AssetStamp& a : replay.header.assets)
        if (a.name == "sprites/rock-large-2.bounds.json") line = a.line;
    ASSERT_GT(line, 0);
    EXPECT_EQ(player.error().message().rfind(
                  path + ":" + std::to_string(line) +
                      ":1: sprites/rock-large-2.bounds.json is not the file this replay was recorded with",
                  0),
              0u)
        << player.error().message();

    Replay elsewhere = replay;
    elsewhere.header.scene = "scenes/volcano.json";
    player = ReplayPlayer::start(elsewhere, assets_);
    ASSERT_FALSE(player.ok());
    EXPECT_EQ(player.error().message().rfind(path + ":" + std::to_string(replay.header.sceneLine) +
                                                 ":1: the recorded scene scenes/volcano.json is not here",
                                             0),
              0u)
        << player.error().message();
}

TEST_F(ReplayTest, TheRecorderKeepsTheNewestGamesAndWritesRecordOnlyOnce) {
    const std::string folder = (dir_ / "replays").string();
    const std::string first = (dir_ / "first.replay").string();
    GameRecorder recorder({first, folder, 2, {"my-mod"}, {}});
    for (int n = 0; n < 3; ++n) {
        Game game = newGame(20 + n);
        recorder.start(game, assets_);
        EXPECT_TRUE(recorder.recording());
        for (int t = 0; t < 30; ++t) {
            game.tick(kFire);
            recorder.record(kFire, game);
        }
        recorder.finish(game, "quit");
        EXPECT_FALSE(recorder.recording());
    }
    EXPECT_EQ(load(first).header.seed, 20u) << "--record FILE gets the first game";
    EXPECT_EQ(load(first).header.mods, std::vector<std::string>{"my-mod"});
    std::vector<std::uint64_t> kept;
    for (const auto& entry : fs::directory_iterator(folder)) {
        EXPECT_EQ(entry.path().extension(), ".replay");
        kept.push_back(load(entry.path().string()).header.seed);
    }
    std::sort(kept.begin(), kept.end());
    EXPECT_EQ(kept, (std::vector<std::uint64_t>{21, 22})) << "only the newest are kept";
}

TEST_F(ReplayTest, TheRecorderEndsAtGameOver) {
    GameRecorder recorder({(dir_ / "over.replay").string(), "", 20, {}, {}});
    Tuning tuning;
    tuning.startLives = 1;
    tuning.invulnerableAfterRespawn = 0;
    Game game = newGame(3, tuning);
    recorder.start(game, assets_);
    while (!game.over() && game.tickCount() < 60 * 120) {
        game.tick(0);
        recorder.record(0, game);
    }
    ASSERT_TRUE(game.over());
    EXPECT_FALSE(recorder.recording());
    Replay replay = load((dir_ / "over.replay").string());
    ASSERT_TRUE(replay.end);
    EXPECT_EQ(replay.end->reason, "game-over");
    EXPECT_EQ(replay.end->tick, game.tickCount());
    EXPECT_EQ(replay.checkpoints.back().lives, 0);
    EXPECT_FALSE(verify(replay).desync);
}

TEST_F(ReplayTest, InterruptedRecordingsAreRecoveredAndOldOnesPruned) {
    for (const char* name :
         {"2024-01-01_10-00-00.replay", "2024-01-02_10-00-00.replay", "2024-01-03_10-00-00.replay"})
        writeText(dir_ / name, "x\n");
    writeText(dir_ / "2024-01-04_10-00-00.replay.part", "y\n");
    writeText(dir_ / "2024-01-05_10-00-00.replay.part", "z\n");  // still being written by another game
    fs::last_write_time(dir_ / "2024-01-04_10-00-00.replay.part",
                        fs::file_time_type::clock::now() - std::chrono::minutes(5));
    std::vector<std::string> recovered = recoverInterruptedReplays(dir_.string());
    ASSERT_EQ(recovered.size(), 1u);
    EXPECT_TRUE(fs::exists(dir_ / "2024-01-04_10-00-00.replay"));
    EXPECT_TRUE(fs::exists(dir_ / "2024-01-05_10-00-00.replay.part"));
    EXPECT_EQ(pruneReplays(dir_.string(), 2), 2u);
    EXPECT_FALSE(fs::exists(dir_ / "2024-01-01_10-00-00.replay"));
    EXPECT_FALSE(fs::exists(dir_ / "2024-01-02_10-00-00.replay"));
    EXPECT_TRUE(fs::exists(dir_ / "2024-01-03_10-00-00.replay"));
    EXPECT_TRUE(fs::exists(dir_ / "2024-01-04_10-00-00.replay"));
    std::string fresh = newReplayPath(dir_.string());
    EXPECT_EQ(fs::path(fresh).extension(), ".replay");
    EXPECT_FALSE(fs::exists(fresh));
}

// ---- the programs, as a developer or CI runs them ----

TEST_F(ReplayTest, PolarcadeReplayReportsATamperedGoldenReplayAtTheTickItDiverges) {
    // Change one input of a committed golden replay by editing its text, as a person would.
    const std::string golden = readText(fs::path(POLAR_REPLAY_DIR) / "game-over.replay");
    Result<Replay> parsed = parseReplay("game-over.replay", golden);
    ASSERT_TRUE(parsed.ok());
    parsed->path = (fs::path(POLAR_REPLAY_DIR) / "game-over.replay").string();
    std::size_t t = quietTick(*parsed, 400);
    parsed->actions[t] |= kThrust;
    std::string tampered = formatReplay(*parsed);
    writeText(dir_ / "tampered.replay", tampered);
    fs::copy(fs::path(POLAR_REPLAY_DIR) / "short.replay", dir_ / "fine.replay");
    fs::copy(fs::path(POLAR_REPLAY_DIR) / "short-600.png", dir_ / "short-600.png");
    std::istringstream before(golden), after(tampered);
    int changedLines = 0;
    for (std::string a, b; std::getline(before, a) && std::getline(after, b);) changedLines += a != b;
    EXPECT_EQ(changedLines, 1) << "only one input line changed";

    std::string out;
    int code = run(std::string(POLARCADE_REPLAY_EXE) + " -j 2 " + dir_.string(), out);
    EXPECT_EQ(code, 1) << out;
    EXPECT_NE(out.find("DESYNC  " + (dir_ / "tampered.replay").generic_string() + "  after tick " +
                       std::to_string(t + 1)),
              std::string::npos)
        << out;
    EXPECT_NE(out.find("PASS    " + (dir_ / "fine.replay").generic_string()), std::string::npos) << out;
    EXPECT_NE(out.find("2 replays: 1 passed, 1 desynced (tampered.replay after tick " +
                       std::to_string(t + 1) + ")"),
              std::string::npos)
        << out;

    // The game itself, with --verify: exit 1 and the same report.
    code = run(std::string(POLARCADE_EXE) + " --headless --replay " + (dir_ / "tampered.replay").string() +
                   " --verify",
               out);
    EXPECT_EQ(code, 1) << out;
    EXPECT_NE(out.find("first differs after tick " + std::to_string(t + 1)), std::string::npos) << out;
    code = run(
        std::string(POLARCADE_EXE) + " --headless --replay " + (dir_ / "fine.replay").string() + " --verify",
        out);
    EXPECT_EQ(code, 0) << out;
}

// A golden cut after its 40th line, as an interrupted recording leaves it, fails as INCOMPLETE in
// polarcade-replay and in the game's --verify alike; --allow-incomplete passes what it holds, with a
// note. One changed trace character is a damaged trace in both, never a desync.
TEST_F(ReplayTest, AnInterruptedRecordingFailsAndADamagedTraceIsNotADesync) {
    const std::string golden = readText(fs::path(POLAR_REPLAY_DIR) / "short.replay");
    std::size_t at = 0;
    for (int line = 0; line < 40; ++line) at = golden.find('\n', at) + 1;
    const fs::path cut = dir_ / "cut.replay";
    writeText(cut, golden.substr(0, at));
    fs::copy(fs::path(POLAR_REPLAY_DIR) / "short-600.png", dir_ / "short-600.png");
    const std::string replayExe = POLARCADE_REPLAY_EXE, gameExe = POLARCADE_EXE;
    const std::string place = cut.string() + ":41:1: incomplete: the replay has no end line";
    std::string out;

    EXPECT_EQ(run(replayExe + " " + cut.string(), out), 1) << out;
    EXPECT_NE(out.find("INCOMPLETE " + cut.generic_string()), std::string::npos) << out;
    EXPECT_NE(out.find(place), std::string::npos) << out;
    EXPECT_NE(
        out.find("1 replay: 0 passed, 0 desynced, 0 damaged, 0 with differing screenshots, 1 incomplete, "
                 "0 unreadable"),
        std::string::npos)
        << out;
    EXPECT_EQ(run(replayExe + " --allow-incomplete " + cut.string(), out), 0) << out;
    EXPECT_NE(out.find("PASS    " + cut.generic_string() + "  (240 ticks, 3 checkpoints"), std::string::npos)
        << out;
    EXPECT_NE(out.find("note: " + place), std::string::npos) << out;

    EXPECT_EQ(run(gameExe + " --headless --replay " + cut.string() + " --verify", out), 1) << out;
    EXPECT_NE(out.find(place), std::string::npos) << out;
    EXPECT_EQ(run(gameExe + " --headless --replay " + cut.string() + " --verify --allow-incomplete", out), 0)
        << out;
    EXPECT_NE(out.find("(incomplete: no end line)"), std::string::npos) << out;
    EXPECT_EQ(run(gameExe + " --headless --replay " + cut.string(), out), 0) << "watching is not verifying\n"
                                                                             << out;
    EXPECT_EQ(run(gameExe + " --headless --replay " + cut.string() + " --allow-incomplete", out), 2)
        << "--allow-incomplete needs --verify\n"
        << out;

    // The 29th character of the first trace line's token (line 28), changed within the alphabet.
    std::string damaged = golden;
    at = 0;
    for (int line = 0; line < 27; ++line) at = damaged.find('\n', at) + 1;
    ASSERT_EQ(damaged.compare(at, 6, "trace "), 0);
    damaged[at + 29] = damaged[at + 29] == 'A' ? 'B' : 'A';
    const fs::path trace = dir_ / "trace.replay";
    writeText(trace, damaged);
    const std::string token = trace.string() + ":28:29: damaged trace: the token of tick 12 is ";
    EXPECT_EQ(run(replayExe + " " + trace.string(), out), 1) << out;
    EXPECT_NE(out.find("DAMAGED " + trace.generic_string() + "  at tick 12"), std::string::npos) << out;
    EXPECT_NE(out.find(token), std::string::npos) << out;
    EXPECT_NE(out.find("0 desynced, 1 damaged (trace.replay at tick 12)"), std::string::npos) << out;
    EXPECT_EQ(run(gameExe + " --headless --replay " + trace.string() + " --verify", out), 1) << out;
    EXPECT_NE(out.find(token), std::string::npos) << out;
}

TEST_F(ReplayTest, GoldenReplaysAreInTheWritersOwnForm) {
    int goldens = 0;
    for (const auto& entry : fs::directory_iterator(POLAR_REPLAY_DIR)) {
        if (entry.path().extension() != ".replay") continue;
        ++goldens;
        std::string text = readText(entry.path());
        Replay replay = load(entry.path().string());
        EXPECT_EQ(formatReplay(replay), text) << entry.path();
        EXPECT_TRUE(replay.end) << entry.path();
        EXPECT_FALSE(replay.checkpoints.empty());
        EXPECT_EQ(replay.trace.size(), replay.actions.size());
    }
    EXPECT_GE(goldens, 3);
}

TEST_F(ReplayTest, ResultsDoNotDependOnTheNumberOfThreads) {
    std::string one, three;
    int a = run(std::string(POLARCADE_REPLAY_EXE) + " -j 1 " + POLAR_REPLAY_DIR, one);
    int b = run(std::string(POLARCADE_REPLAY_EXE) + " -j 3 " + POLAR_REPLAY_DIR, three);
    EXPECT_EQ(a, 0) << one;
    EXPECT_EQ(b, 0) << three;
    EXPECT_EQ(one, three);
}

TEST_F(ReplayTest, BadInputGivesExitCodeTwoAndOneClearLine) {
    writeText(dir_ / "broken.replay", "polarcade-replay 1\nscene scenes/cave.json\nbegin\nin Q\n");
    std::string out;
    EXPECT_EQ(run(std::string(POLARCADE_REPLAY_EXE) + " " + (dir_ / "broken.replay").string(), out), 2);
    EXPECT_NE(out.find("broken.replay:4:4: unknown action 'Q'"), std::string::npos) << out;
    EXPECT_EQ(run(std::string(POLARCADE_REPLAY_EXE) + " " + (dir_ / "nowhere").string(), out), 2);
    EXPECT_EQ(
        run(std::string(POLARCADE_EXE) + " --headless --replay " + (dir_ / "broken.replay").string(), out),
        2);
    EXPECT_NE(out.find("broken.replay:4:4: unknown action 'Q'"), std::string::npos) << out;
    EXPECT_EQ(run(std::string(POLARCADE_EXE) + " --headless --replay x.replay --scene cave", out), 2);
    EXPECT_NE(out.find("--scene cannot be used with --replay"), std::string::npos) << out;
    EXPECT_EQ(run(std::string(POLARCADE_EXE) + " --verify", out), 2) << "--verify needs --replay";
}

TEST_F(ReplayTest, UpdateReRecordsTheCheckpointsFromThisBuild) {
    // A replay whose recorded hashes are wrong, as after an intended change to the rules.
    const std::string golden = readText(fs::path(POLAR_REPLAY_DIR) / "short.replay");
    std::string stale = golden;
    std::size_t check = stale.find("\ncheck 120 ");
    ASSERT_NE(check, std::string::npos);
    stale[check + 11] = stale[check + 11] == '0' ? '1' : '0';
    writeText(dir_ / "short.replay", stale);
    fs::copy(fs::path(POLAR_REPLAY_DIR) / "short-600.png", dir_ / "short-600.png");
    std::string out;
    EXPECT_EQ(run(std::string(POLARCADE_REPLAY_EXE) + " " + (dir_ / "short.replay").string(), out), 1) << out;
    EXPECT_NE(out.find("checkpoint after tick 120"), std::string::npos) << out;
    EXPECT_NE(out.find("disagrees with the per-tick trace, which matched every tick"), std::string::npos)
        << out;
    EXPECT_EQ(run(std::string(POLARCADE_REPLAY_EXE) + " --update " + (dir_ / "short.replay").string(), out),
              0)
        << out;
    EXPECT_NE(out.find("UPDATED"), std::string::npos) << out;
    EXPECT_EQ(readText(dir_ / "short.replay"), golden) << "inputs, comments and screenshot lines are kept";
}

TEST_F(ReplayTest, ADifferingScreenshotIsReportedWithPictures) {
    fs::copy(fs::path(POLAR_REPLAY_DIR) / "short.replay", dir_ / "short.replay");
    fs::copy(fs::path(POLAR_REPLAY_DIR) / "crowded-900.png", dir_ / "short-600.png");  // the wrong picture
    std::string out;
    const fs::path failures = dir_ / "failures";
    int code = run(std::string(POLARCADE_REPLAY_EXE) + " --failures " + failures.string() + " " +
                       (dir_ / "short.replay").string(),
                   out);
    EXPECT_EQ(code, 1) << out;
    int line = load((dir_ / "short.replay").string()).header.screenshots.at(0).line;
    EXPECT_NE(out.find("short.replay:" + std::to_string(line) + ":1: screenshot after tick 600: "),
              std::string::npos)
        << out;
    EXPECT_TRUE(fs::exists(failures / "short-600.actual.png"));
    EXPECT_TRUE(fs::exists(failures / "short-600.diff.png"));
    // After an intended change, --update-screenshots rewrites it, and then it passes.
    EXPECT_EQ(
        run(std::string(POLARCADE_REPLAY_EXE) + " --update-screenshots " + (dir_ / "short.replay").string(),
            out),
        0)
        << out;
    EXPECT_EQ(readText(dir_ / "short-600.png"), readText(fs::path(POLAR_REPLAY_DIR) / "short-600.png"));
    EXPECT_EQ(run(std::string(POLARCADE_REPLAY_EXE) + " " + (dir_ / "short.replay").string(), out), 0) << out;
}

}  // namespace
}  // namespace polar::game
