// kill -9 in the middle of a write (atomic writes): a child process rewrites a file again
// and again and is killed at varied moments; after every kill the file is exactly the old contents
// or exactly the new, never torn or missing, and at most the one dead writer's temporary file is
// left, which the next write removes.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "atomic_contents.h"
#include "files/high_scores.h"
#include "polar/atomic_file.h"
#include "run_command.h"
#include "scratch_folder.h"

namespace polar::game {
namespace {

namespace fs = std::filesystem;
using polar::testing::readFile;

// Starts `args[0]` with `args` in `folder`, its output thrown away.
pid_t spawn(const std::vector<std::string>& args, const fs::path& folder) {
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    std::fflush(nullptr);  // or the child would write this process's buffered output again
    pid_t child = ::fork();
    if (child == 0) {
        if (::chdir(folder.c_str()) != 0) ::_exit(126);
        std::freopen("/dev/null", "w", stdout);
        std::freopen("/dev/null", "w", stderr);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    return child;
}

// Kills `child` with SIGKILL after `delay` and reaps it; true when the kill ended it (false: it had
// already finished by itself).
bool killAfter(pid_t child, std::chrono::microseconds delay) {
    std::this_thread::sleep_for(delay);
    ::kill(child, SIGKILL);
    int status = 0;
    ::waitpid(child, &status, 0);
    return WIFSIGNALED(status);
}

// The names of the temporary files in `folder` (an atomic write's "NAME.PID-N.tmp").
std::vector<std::string> temporaries(const fs::path& folder) {
    std::vector<std::string> out;
    for (const auto& entry : fs::directory_iterator(folder))
        if (entry.path().extension() == ".tmp") out.push_back(entry.path().filename().string());
    return out;
}

// The delay before the i-th kill: spread over [0, span), in a scrambled order.
std::chrono::microseconds delayFor(int i, std::chrono::microseconds span) {
    std::uint64_t step = (static_cast<std::uint64_t>(i) * 2654435761u) % 1000;
    return std::chrono::microseconds(static_cast<std::int64_t>(span.count() * step / 1000));
}

// When to kill, at the pace the machine keeps now. The span is measured once, before the kills,
// but a loaded machine (the rest of the suite beside) can slow every later start and write several
// times over, and then every kill lands before the writer got anywhere: the checks still pass,
// but prove nothing, and the counts that say they did fail. So the span grows by half after each
// window of kills in which no writer got as far as writing (no temporary file, no changed file),
// and the kills go on past the planned number (up to three times it) until the counts are met:
// the kills keep landing before, during and after writes whatever the load, and every check on
// every kill stays as it was.
class KillSchedule {
  public:
    KillSchedule(std::chrono::microseconds span, int planned) : span_(span), planned_(planned) {}

    // Whether to kill again: the planned kills, then more until `enough` (at most 3 × planned).
    bool more(bool enough) const { return i_ < planned_ || (!enough && i_ < 3 * planned_); }
    int index() const { return i_; }
    std::chrono::microseconds delay() const { return delayFor(i_, span_); }
    // After a kill: whether that writer got as far as writing.
    void record(bool wrote) {
        windowWrote_ = windowWrote_ || wrote;
        if (++i_ % kWindow == 0) {
            if (!windowWrote_) span_ = span_ * 3 / 2, ++grown_;
            windowWrote_ = false;
        }
    }
    int grown() const { return grown_; }

  private:
    static constexpr int kWindow = 8;
    std::chrono::microseconds span_;
    int planned_ = 0, i_ = 0, grown_ = 0;
    bool windowWrote_ = false;
};

class AtomicKill : public ::testing::Test {
  protected:
    void SetUp() override { folder_ = polar::testing::freshTestFolder("polar-kill"); }
    void TearDown() override { fs::remove_all(folder_); }
    fs::path folder_;
};

TEST_F(AtomicKill, AMultiMegabyteFileIsAlwaysTheOldOrTheNewOne) {
    constexpr std::size_t kSize = 2 << 20;
    const std::string version[2] = {polar::testing::atomicContents(0, kSize),
                                    polar::testing::atomicContents(1, kSize)};
    const fs::path target = folder_ / "big.dat";
    ASSERT_FALSE(writeFileAtomically(target.string(), version[0]));

    // How long one write takes here, so the kills land before, during and after writes.
    auto start = std::chrono::steady_clock::now();
    pid_t timing =
        spawn({POLAR_ATOMIC_WRITER_EXE, "bytes", target.string(), std::to_string(kSize), "2"}, folder_);
    int status = 0;
    ::waitpid(timing, &status, 0);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    auto twoWrites =
        std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - start);
    ASSERT_EQ(readFile(target), version[0]) << "two writes: version 1, then version 0 again";

    int changes = 0, killedMidWrite = 0, kills = 0;
    std::string last = version[0];
    KillSchedule schedule(twoWrites * 3 / 2, 80);
    while (schedule.more(changes > 5 && killedMidWrite > 5)) {
        const int i = schedule.index();
        pid_t child =
            spawn({POLAR_ATOMIC_WRITER_EXE, "bytes", target.string(), std::to_string(kSize)}, folder_);
        ASSERT_GT(child, 0);
        kills += killAfter(child, schedule.delay());
        std::string now = readFile(target);
        ASSERT_TRUE(now == version[0] || now == version[1])
            << "kill " << i << ": a torn or missing file (" << now.size() << " bytes)";
        const bool changed = now != last;
        changes += changed;
        last = std::move(now);
        std::vector<std::string> temps = temporaries(folder_);
        ASSERT_LE(temps.size(), 1u) << "kill " << i
                                    << ": only the last dead writer's temporary file may be left";
        killedMidWrite += temps.size() == 1;
        schedule.record(changed || temps.size() == 1);
    }
    const int runs = schedule.index();
    std::printf(
        "[ figures  ] %d kills of %d runs; %d left a temporary file (killed mid-write); the file changed %d "
        "times; the span grew %d times\n",
        kills, runs, killedMidWrite, changes, schedule.grown());
    EXPECT_GT(kills, runs / 2) << "most runs were killed, not finished";
    EXPECT_GT(changes, 5) << "writes completed between kills";
    EXPECT_GT(killedMidWrite, 5) << "kills landed in the middle of writes";

    // The next write (by a living process) removes what the dead ones left.
    pid_t last_write =
        spawn({POLAR_ATOMIC_WRITER_EXE, "bytes", target.string(), std::to_string(kSize), "1"}, folder_);
    ::waitpid(last_write, &status, 0);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    EXPECT_TRUE(temporaries(folder_).empty());
    EXPECT_NE(readFile(target), last);
}

TEST_F(AtomicKill, HighScoresSurviveKillsAndNoScoreIsLost) {
    const fs::path target = folder_ / "highscores.json";
    // How long a start and four saves take here: the kills are spread over that.
    const fs::path timingTable = folder_ / "timing.json";
    auto start = std::chrono::steady_clock::now();
    pid_t timing = spawn({POLAR_ATOMIC_WRITER_EXE, "scores", timingTable.string(), "4"}, folder_);
    int status = 0;
    ::waitpid(timing, &status, 0);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    auto span =
        std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - start);
    fs::remove(timingTable);

    int best = 0, kills = 0;
    KillSchedule schedule(span, 60);
    while (schedule.more(best > 10)) {
        const int i = schedule.index();
        pid_t child = spawn({POLAR_ATOMIC_WRITER_EXE, "scores", target.string()}, folder_);
        ASSERT_GT(child, 0);
        kills += killAfter(child, schedule.delay());
        if (!fs::exists(target)) {
            ASSERT_EQ(best, 0) << "kill " << i << ": the table went missing";
            schedule.record(!temporaries(folder_).empty());
            continue;
        }
        std::optional<Error> problem;
        HighScores table = HighScores::load(target.string(), &problem);
        ASSERT_FALSE(problem) << "kill " << i << ": " << problem->message();
        ASSERT_EQ(table.toJson(), readFile(target)) << "kill " << i << ": exactly a table the game wrote";
        ASSERT_FALSE(table.entries().empty());
        ASSERT_GE(table.entries().front().score, best) << "kill " << i << ": a saved score was lost";
        const bool saved = table.entries().front().score > best;
        best = table.entries().front().score;
        std::vector<std::string> temps = temporaries(folder_);
        ASSERT_LE(temps.size(), 1u);
        schedule.record(saved || !temps.empty());
    }
    EXPECT_GT(kills, schedule.index() / 2);
    EXPECT_GT(best, 10) << "saves completed between kills";
}

// The real program: polarcade's screenshot, written while the game is killed at varied moments.
TEST_F(AtomicKill, AScreenshotIsAlwaysTheOldOrTheNewFrame) {
    auto shoot = [&](int tick, const std::string& file) {
        return std::vector<std::string>{POLARCADE_EXE,  "--headless",
                                        "--ticks",      std::to_string(tick),
                                        "--screenshot", std::to_string(tick) + ":" + file};
    };
    auto start = std::chrono::steady_clock::now();
    for (int tick : {40, 41}) {
        pid_t child = spawn(shoot(tick, "frame-" + std::to_string(tick) + ".png"), folder_);
        int status = 0;
        ::waitpid(child, &status, 0);
        ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    }
    auto oneRun =
        std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - start) / 2;
    const std::string frame[2] = {readFile(folder_ / "frame-40.png"), readFile(folder_ / "frame-41.png")};
    ASSERT_NE(frame[0], frame[1]);
    fs::copy_file(folder_ / "frame-40.png", folder_ / "shot.png");

    int changes = 0;
    std::string last = frame[0];
    KillSchedule schedule(oneRun * 3 / 2, 24);
    while (schedule.more(changes > 0)) {
        const int i = schedule.index();
        // Each run writes the other frame, so every run that gets to write changes the file.
        pid_t child = spawn(shoot(last == frame[0] ? 41 : 40, "shot.png"), folder_);
        killAfter(child, schedule.delay());
        std::string now = readFile(folder_ / "shot.png");
        ASSERT_TRUE(now == frame[0] || now == frame[1]) << "kill " << i << ": a torn or missing picture";
        const bool changed = now != last;
        changes += changed;
        last = std::move(now);
        std::vector<std::string> temps = temporaries(folder_);
        ASSERT_LE(temps.size(), 1u);
        schedule.record(changed || !temps.empty());
    }
    EXPECT_GT(changes, 0) << "some runs got to write their frame";
}

}  // namespace
}  // namespace polar::game
