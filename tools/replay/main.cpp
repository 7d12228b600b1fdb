// polarcade-replay: verifies many replays in parallel, for game developers and CI.
#include <unistd.h>
#if defined(__EMSCRIPTEN__)
#include <emscripten.h>
#endif

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "cli.h"
#include "files/assets.h"
#include "junit_report.h"
#include "output_file.h"
#include "polar/atomic_file.h"
#include "polarcade_version.h"
#include "replay_check.h"
#include "shard.h"

namespace {

namespace fs = std::filesystem;
using polar::game::CheckResult;

// The replay files named on the command line: files as given, folders searched for *.replay.
bool collect(const std::vector<std::string>& args, std::vector<std::string>& files) {
    for (const std::string& arg : args) {
        std::error_code ec;
        if (fs::is_directory(arg, ec)) {
            std::vector<std::string> found;
            for (auto it = fs::recursive_directory_iterator(arg, ec);
                 !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
                if (it->is_regular_file(ec) && it->path().extension() == ".replay")
                    found.push_back(it->path().generic_string());
            std::sort(found.begin(), found.end());
            if (found.empty())
                std::fprintf(stderr, "polarcade-replay: %s: no .replay files in this folder\n", arg.c_str());
            files.insert(files.end(), found.begin(), found.end());
        } else if (fs::exists(arg, ec)) {
            files.push_back(arg);
        } else {
            std::fprintf(
                stderr,
                "polarcade-replay: %s: no such file or folder; expected replay files or folders of them\n",
                arg.c_str());
            return false;
        }
    }
    return true;
}

void drawProgress(std::size_t done, std::size_t total, std::uint64_t ticks, std::uint64_t allTicks) {
    constexpr int kWidth = 30;
    double fraction =
        allTicks ? std::min(1.0, static_cast<double>(ticks) / allTicks) : (total ? double(done) / total : 1);
    int filled = static_cast<int>(fraction * kWidth);
    std::fprintf(stderr, "\r[%.*s%*s] %3d%%  %zu/%zu replays", filled, "##############################",
                 kWidth - filled, "", static_cast<int>(fraction * 100), done, total);
    std::fflush(stderr);
}

// Whether stderr is a terminal (the progress bar is drawn only there). Under node, emscripten's
// isatty says yes for every standard stream, so node itself is asked.
bool stderrIsTerminal() {
#if defined(__EMSCRIPTEN__)
    return EM_ASM_INT({ return typeof process == 'object' && process.stderr.isTTY ? 1 : 0; }) != 0;
#else
    return ::isatty(::fileno(stderr)) != 0;
#endif
}

const char* statusWord(CheckResult::Status status) {
    switch (status) {
        case CheckResult::kPassed:
            return "PASS   ";
        case CheckResult::kUpdated:
            return "UPDATED";
        case CheckResult::kDesynced:
            return "DESYNC ";
        case CheckResult::kDamaged:
            return "DAMAGED";
        case CheckResult::kScreenshotDiffers:
            return "PICTURE";
        case CheckResult::kIncomplete:
            return "INCOMPLETE";
        case CheckResult::kUnplayable:
            return "ERROR  ";
    }
    return "?";
}

// The command line's values.
struct Flags {
    std::vector<std::string> paths;
    unsigned jobs = std::max(1u, std::thread::hardware_concurrency());
    unsigned stepThreads = 1;
    polar::game::CheckOptions options;
    bool quiet = false;
    bool list = false;
    std::string junit, shardText;
    bool junitGiven = false, shardGiven = false;  // the flag was there, even with an empty value
};

void addFlags(polar::cli::Command& app, Flags& f) {
    app.option("paths", f.paths, "Replay files or folders of them").required().typeName("DIR|FILE");
    app.option("-j,--jobs", f.jobs,
               "Replays verified at once, one per thread (default: every core); results do not depend on it",
               {1, 256});
    app.option("--step-threads", f.stepThreads,
               "Threads inside each replay's world step (default 1); results do not depend on it. The "
               "game's worlds are below the size at which a step shares its work, so cores left over by "
               "-j stay idle: spent inside a replay they made it no faster (measured)",
               {1, 64})
        .typeName("N");
    app.option("--mod", f.options.mods, "A mod folder laid over assets/, as the game's --mod (repeatable)")
        .existingFolder();
    app.option("--failures", f.options.failureDir,
               "Where the actual and diff PNGs of differing screenshots go")
        .typeName("DIR")
        .showDefault();
    const polar::cli::Option updateShots =
        app.flag("--update-screenshots", f.options.updateScreenshots,
                 "Verify, then write each screenshot line's PNG from this build (for a new "
                 "screenshot line or an intended change in drawing); look at them before committing");
    app.flag("--update", f.options.update,
             "Re-record the checkpoints, trace, file stamps and screenshots from this build, keeping the "
             "inputs "
             "(for an intended change to the game); review the diff before committing")
        .excludes(updateShots);
    app.flag("--allow-incomplete", f.options.allowIncomplete,
             "Pass a replay without its end line (an interrupted recording) when every tick it holds "
             "matches; by default such a replay fails as INCOMPLETE");
    app.flag("-q,--quiet", f.quiet, "Print only replays that fail, and the summary");
    app.option("--junit", f.junit,
               "Also write a JUnit XML report to FILE (atomically): a testcase per replay, desyncs, "
               "damaged lines, incomplete replays and differing screenshots as failures, unreadable "
               "replays as errors")
        .typeName("FILE");
    app.option("--shard", f.shardText,
               "Verify only shard K of N (1 <= K <= N): the replays sorted by path, every N-th one "
               "from the K-th; N runners with K = 1..N verify each replay exactly once")
        .typeName("K/N");
    app.flag("--list", f.list,
             "Print the replays that would be verified (after --shard), one a line, and exit");
}

// --shard read and --junit's folder checked, before any replay is played; false after a message.
bool checkFlags(const Flags& f, std::optional<polar::game::Shard>& shard) {
    if (!f.shardText.empty() || f.shardGiven) {
        std::string problem;
        shard = polar::game::parseShard(f.shardText, problem);
        if (!shard) {
            std::fprintf(stderr,
                         "polarcade-replay: --shard %s: %s; expected K/N with 1 <= K <= N, e.g. 2/4\n",
                         f.shardText.c_str(), problem.c_str());
            return false;
        }
    }
    if (!f.junit.empty() || f.junitGiven) {
        if (std::string problem = polar::cli::outputFileProblem(f.junit); !problem.empty()) {
            std::fprintf(stderr, "polarcade-replay: --junit %s: %s; expected a file in a writable folder\n",
                         f.junit.c_str(), problem.c_str());
            return false;
        }
    }
    return true;
}

// Verifies every file on `jobs` threads, with a progress bar on a terminal. Workers take the next
// file by index; each result lands in its own slot, so the report is in the order given whatever
// the number of threads.
std::vector<CheckResult> verifyAll(const std::vector<std::string>& files, polar::game::CheckOptions options,
                                   unsigned jobs) {
    std::uint64_t allTicks = 0;
    for (const std::string& file : files) allTicks += polar::game::replayTicks(file);
    std::atomic<std::uint64_t> ticksDone{0};
    options.ticksDone = &ticksDone;

    std::vector<CheckResult> results(files.size());
    std::atomic<std::size_t> next{0}, finished{0};
    auto work = [&] {
        for (std::size_t i; (i = next.fetch_add(1)) < files.size();) {
            const auto start = std::chrono::steady_clock::now();
            results[i] = polar::game::checkReplayFile(files[i], options);
            results[i].seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            finished.fetch_add(1);
        }
    };
    // One job runs here, on this thread (a build without threads, WebAssembly's, has only it).
    std::vector<std::thread> pool;
    const std::size_t threads = std::min<std::size_t>(jobs, files.size());
    if (threads <= 1) work();
    for (std::size_t t = 0; threads > 1 && t < threads; ++t) pool.emplace_back(work);
    const bool bar = stderrIsTerminal();
    while (bar && finished.load() < files.size()) {
        drawProgress(finished.load(), files.size(), ticksDone.load(), allTicks);
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    for (std::thread& thread : pool) thread.join();
    if (bar) {
        drawProgress(files.size(), files.size(), allTicks, allTicks);
        std::fprintf(stderr, "\n");
    }
    return results;
}

// How many replays ended each way, and which desynced where.
struct Tally {
    std::size_t passed = 0, updated = 0, desynced = 0, damaged = 0, pictures = 0, incomplete = 0, broken = 0;
    std::vector<std::string> desyncs, damages;
};

// A line per replay (only the failures with --quiet), with its notes and, for a failure, its report.
Tally printResults(const std::vector<CheckResult>& results, bool quiet) {
    Tally t;
    for (const CheckResult& r : results) {
        bool ok = r.status == CheckResult::kPassed || r.status == CheckResult::kUpdated;
        if (!ok || !quiet) {
            std::printf("%s %s", statusWord(r.status), r.path.c_str());
            if (ok)
                std::printf("  (%llu ticks, %zu checkpoints, %zu screenshots)",
                            static_cast<unsigned long long>(r.ticks), r.checkpoints, r.screenshots);
            if (r.status == CheckResult::kDesynced)
                std::printf("  after tick %llu", static_cast<unsigned long long>(r.desyncTick));
            if (r.status == CheckResult::kDamaged)
                std::printf("  at tick %llu", static_cast<unsigned long long>(r.desyncTick));
            std::printf("\n");
            for (const std::string& note : r.notes) std::printf("  note: %s\n", note.c_str());
        }
        if (!ok) {
            std::string report = r.report;
            if (!report.empty() && report.back() == '\n') report.pop_back();
            std::printf("  %s\n", report.c_str());
        }
        switch (r.status) {
            case CheckResult::kPassed:
                ++t.passed;
                break;
            case CheckResult::kUpdated:
                ++t.updated;
                break;
            case CheckResult::kDesynced:
                ++t.desynced;
                t.desyncs.push_back(fs::path(r.path).filename().string() + " after tick " +
                                    std::to_string(r.desyncTick));
                break;
            case CheckResult::kDamaged:
                ++t.damaged;
                t.damages.push_back(fs::path(r.path).filename().string() + " at tick " +
                                    std::to_string(r.desyncTick));
                break;
            case CheckResult::kScreenshotDiffers:
                ++t.pictures;
                break;
            case CheckResult::kIncomplete:
                ++t.incomplete;
                break;
            case CheckResult::kUnplayable:
                ++t.broken;
                break;
        }
    }
    return t;
}

void printSummary(const Tally& t, std::size_t count) {
    std::printf("%zu replay%s: %zu passed", count, count == 1 ? "" : "s", t.passed);
    if (t.updated) std::printf(", %zu updated", t.updated);
    std::printf(", %zu desynced", t.desynced);
    for (std::size_t i = 0; i < t.desyncs.size(); ++i)
        std::printf("%s%s", i ? ", " : " (", t.desyncs[i].c_str());
    if (!t.desyncs.empty()) std::printf(")");
    std::printf(", %zu damaged", t.damaged);
    for (std::size_t i = 0; i < t.damages.size(); ++i)
        std::printf("%s%s", i ? ", " : " (", t.damages[i].c_str());
    if (!t.damages.empty()) std::printf(")");
    std::printf(", %zu with differing screenshots, %zu incomplete, %zu unreadable\n", t.pictures,
                t.incomplete, t.broken);
}

// The JUnit report, atomically; false after a message when it cannot be written.
bool writeJunit(const std::string& path, const std::vector<CheckResult>& results,
                const std::optional<polar::game::Shard>& shard) {
    std::vector<std::pair<std::string, std::string>> properties = {{"version", polar::kPolarcadeVersion}};
    std::string suite = "polarcade-replay";
    if (shard) {
        const std::string k = std::to_string(shard->index) + "/" + std::to_string(shard->count);
        properties.emplace_back("shard", k);
        suite += " shard " + k;
    }
    if (auto error = polar::writeFileAtomically(path, polar::game::junitReport(suite, results, properties))) {
        std::fprintf(stderr, "polarcade-replay: --junit %s: %s\n", path.c_str(), error->message().c_str());
        return false;
    }
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    polar::cli::Command app{
        "Verifies Polarcade replays: each is played headless from its recorded inputs and checked tick by "
        "tick "
        "against its recorded state hashes and checkpoint screenshots. Folders are searched for *.replay. "
        "Exit code 0: all passed; 1: a replay desynced, has a damaged trace or checkpoint line, a differing "
        "screenshot or no end line (INCOMPLETE); 2: bad arguments or a replay that cannot be read or "
        "started.",
        "polarcade-replay"};
    Flags flags;
    addFlags(app, flags);
    if (int code = app.parse(argc, argv); code >= 0) return code;
    flags.shardGiven = app.count("--shard") > 0;
    flags.junitGiven = app.count("--junit") > 0;

    // Plan: the flags checked, the replays chosen, the assets found.
    std::optional<polar::game::Shard> shard;
    if (!checkFlags(flags, shard)) return polar::cli::kBadInput;
    std::vector<std::string> files;
    if (!collect(flags.paths, files)) return polar::cli::kBadInput;
    if (files.empty()) return polar::cli::kBadInput;
    const std::size_t suiteSize = files.size();
    if (shard) files = polar::game::shardOf(std::move(files), *shard);
    if (flags.list) {
        for (const std::string& file : files) std::printf("%s\n", file.c_str());
        return 0;
    }
    if (shard)
        std::printf("shard %zu/%zu: %zu of %zu replays\n", shard->index, shard->count, files.size(),
                    suiteSize);
    polar::Result<std::string> root = polar::game::AssetFs::findRoot();
    if (!root) {
        std::fprintf(stderr, "polarcade-replay: %s\n", root.error().message().c_str());
        return polar::cli::kBadInput;
    }
    flags.options.assetRoot = *root;
    flags.options.threads.workers = flags.stepThreads;

    // Verify, then report.
    const std::vector<CheckResult> results = verifyAll(files, flags.options, flags.jobs);
    const Tally tally = printResults(results, flags.quiet);
    printSummary(tally, files.size());
    if (!flags.junit.empty() && !writeJunit(flags.junit, results, shard)) return polar::cli::kBadInput;
    if (tally.broken) return polar::cli::kBadInput;
    return tally.desynced || tally.damaged || tally.pictures || tally.incomplete ? 1 : 0;
}
