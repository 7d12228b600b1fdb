// polarcade-replay as a CI system runs it: JUnit XML reports (read back with a real XML parser)
// and the suite split into shards.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "junit_report.h"
#include "run_command.h"
#include "scratch_folder.h"
#include "shard.h"

namespace polar::game {
namespace {

namespace fs = std::filesystem;
using polar::testing::CommandOutcome;
using polar::testing::readFile;
using polar::testing::run;
using polar::testing::runShell;
using polar::testing::shellQuote;

void writeText(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

class ReplayCi : public ::testing::Test {
  protected:
    void SetUp() override { dir_ = polar::testing::freshTestFolder("polar-replay-ci"); }
    void TearDown() override { fs::remove_all(dir_); }

    // The report read by python3's xml.etree: what it holds, or a test failure when it is not XML.
    nlohmann::json parsed(const fs::path& report) {
        CommandOutcome r = runShell(shellQuote(POLAR_PYTHON) + " " + shellQuote(POLAR_JUNIT_CHECK) + " " +
                                    shellQuote(report.string()));
        EXPECT_EQ(r.exitCode, 0) << "not well-formed: " << r.err << "\n" << readFile(report);
        return r.exitCode == 0 ? nlohmann::json::parse(r.out) : nlohmann::json::object();
    }
    // The lines polarcade-replay --list prints for these arguments.
    std::vector<std::string> listed(const std::vector<std::string>& args) {
        std::vector<std::string> all = {"--list"};
        all.insert(all.end(), args.begin(), args.end());
        CommandOutcome r = run(POLARCADE_REPLAY_EXE, all);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        std::vector<std::string> lines;
        std::istringstream in(r.out);
        for (std::string line; std::getline(in, line);) lines.push_back(line);
        return lines;
    }

    fs::path dir_;
};

const nlohmann::json* caseNamed(const nlohmann::json& report, const std::string& name) {
    for (const nlohmann::json& c : report["cases"])
        if (c["name"] == name) return &c;
    return nullptr;
}

TEST_F(ReplayCi, TheJUnitReportHoldsEveryReplayWithItsOutcome) {
    const fs::path goldens(POLAR_REPLAY_DIR);
    // A folder and file names with every character XML must escape.
    const std::string oddFolder = "odd & <\"names\">'";
    const std::string oddName = "a&b<c>\"d'.replay";
    const fs::path odd = dir_ / oddFolder, ok = dir_ / "ok";
    fs::create_directories(odd);
    fs::create_directories(ok);
    fs::copy(goldens / "short.replay", ok / "fine.replay");
    fs::copy(goldens / "short-600.png", ok / "short-600.png");
    // The wrong picture for the screenshot after tick 600: a failure with an actual and a diff PNG.
    fs::copy(goldens / "short.replay", odd / oddName);
    fs::copy(goldens / "crowded-900.png", odd / "short-600.png");
    // One digit of the checkpoint after tick 120 changed: a damaged line (the trace sides with the game).
    std::string stale = readFile(goldens / "short.replay");
    const std::size_t check = stale.find("\ncheck 120 ");
    ASSERT_NE(check, std::string::npos);
    stale[check + 11] = stale[check + 11] == '0' ? '1' : '0';
    writeText(odd / "stale.replay", stale);
    writeText(odd / "garbage.replay", "this is not a replay\n");
    // The first input turned the other way: the game differs, a desync.
    std::string turned = readFile(goldens / "short.replay");
    const std::size_t firstRun = turned.find("\nin R*2 ");
    ASSERT_NE(firstRun, std::string::npos);
    turned[firstRun + 4] = 'L';
    writeText(odd / "turned.replay", turned);
    // Cut after its 40th line, as an interrupted recording leaves it: incomplete.
    std::string cut = readFile(goldens / "short.replay");
    std::size_t at = 0;
    for (int line = 0; line < 40; ++line) at = cut.find('\n', at) + 1;
    writeText(odd / "cut.replay", cut.substr(0, at));

    const fs::path report = dir_ / "report.xml";
    CommandOutcome r = run(POLARCADE_REPLAY_EXE, {"-j", "2", "--failures", (dir_ / "failures").string(),
                                                  "--junit", report.string(), dir_.string()});
    EXPECT_EQ(r.exitCode, 2) << "an unreadable replay is exit 2\n" << r.out << r.err;
    nlohmann::json xml = parsed(report);
    ASSERT_EQ(xml["suites"].size(), 1u);
    const nlohmann::json& suite = xml["suites"][0];
    EXPECT_EQ(suite["name"], "polarcade-replay");
    EXPECT_EQ(suite["tests"], "6");
    EXPECT_EQ(suite["failures"], "4");
    EXPECT_EQ(suite["errors"], "1");
    EXPECT_EQ(suite["properties"]["version"], POLARCADE_VERSION);
    ASSERT_EQ(xml["cases"].size(), 6u);

    const std::string oddClass = polar::game::junitClassname((odd / oddName).string());
    EXPECT_NE(oddClass.find(oddFolder), std::string::npos) << oddClass;
    EXPECT_EQ(oddClass.find('/'), std::string::npos) << oddClass;

    const nlohmann::json* fine = caseNamed(xml, "fine.replay");
    ASSERT_NE(fine, nullptr);
    EXPECT_EQ(fine->at("classname"), polar::game::junitClassname((ok / "fine.replay").string()));
    EXPECT_TRUE(fine->at("failure").is_null());
    EXPECT_TRUE(fine->at("error").is_null());
    EXPECT_GT(std::stod(fine->at("time").get<std::string>()), 0.0) << "600 ticks take some time";

    const nlohmann::json* picture = caseNamed(xml, oddName);
    ASSERT_NE(picture, nullptr) << "the escaped name reads back as it was";
    EXPECT_EQ(picture->at("classname"), oddClass);
    EXPECT_EQ(picture->at("file"), (odd / oddName).string());
    ASSERT_FALSE(picture->at("failure").is_null());
    EXPECT_EQ(picture->at("failure")["type"], "screenshot");
    const std::string pictureText = picture->at("failure")["text"];
    EXPECT_NE(pictureText.find("screenshot after tick 600"), std::string::npos) << pictureText;
    const std::string actual = (dir_ / "failures" / "a&b<c>\"d'-600.actual.png").string();
    const std::string diff = (dir_ / "failures" / "a&b<c>\"d'-600.diff.png").string();
    EXPECT_NE(pictureText.find("actual: " + actual), std::string::npos) << pictureText;
    EXPECT_NE(pictureText.find("diff:   " + diff), std::string::npos) << pictureText;
    EXPECT_TRUE(fs::exists(actual));
    EXPECT_NE(picture->at("out").get<std::string>().find("[[ATTACHMENT|" + diff + "]]"), std::string::npos);

    const nlohmann::json* desync = caseNamed(xml, "stale.replay");
    ASSERT_NE(desync, nullptr);
    ASSERT_FALSE(desync->at("failure").is_null());
    EXPECT_EQ(desync->at("failure")["type"], "damaged");
    const std::string desyncText = desync->at("failure")["text"];
    EXPECT_NE(desyncText.find("checkpoint after tick 120"), std::string::npos) << desyncText;
    EXPECT_EQ(desync->at("failure")["message"], desyncText.substr(0, desyncText.find('\n')));

    const nlohmann::json* turnedCase = caseNamed(xml, "turned.replay");
    ASSERT_NE(turnedCase, nullptr);
    ASSERT_FALSE(turnedCase->at("failure").is_null());
    EXPECT_EQ(turnedCase->at("failure")["type"], "desync");
    EXPECT_EQ(turnedCase->at("failure")["message"].get<std::string>().rfind(
                  (odd / "turned.replay").string() + ":27:4: desync: the game first differs after tick 1", 0),
              0u)
        << turnedCase->at("failure")["message"];

    const nlohmann::json* cutCase = caseNamed(xml, "cut.replay");
    ASSERT_NE(cutCase, nullptr);
    ASSERT_FALSE(cutCase->at("failure").is_null());
    EXPECT_EQ(cutCase->at("failure")["type"], "incomplete");
    EXPECT_EQ(cutCase->at("failure")["message"].get<std::string>().rfind(
                  (odd / "cut.replay").string() + ":41:1: incomplete: the replay has no end line", 0),
              0u)
        << cutCase->at("failure")["message"];

    const nlohmann::json* garbage = caseNamed(xml, "garbage.replay");
    ASSERT_NE(garbage, nullptr);
    ASSERT_FALSE(garbage->at("error").is_null());
    EXPECT_EQ(garbage->at("error")["type"], "unplayable");
    EXPECT_NE(garbage->at("error")["text"].get<std::string>().find("garbage.replay:1:"), std::string::npos);
    EXPECT_TRUE(garbage->at("failure").is_null());
}

TEST_F(ReplayCi, TextThatXmlCannotHoldIsReplacedAndTheReportStaysWellFormed) {
    EXPECT_EQ(xmlEscaped("a&b<c>\"d'e"), "a&amp;b&lt;c&gt;&quot;d&apos;e");
    EXPECT_EQ(xmlEscaped("tab\tline\nreturn\r"), "tab&#9;line&#10;return&#13;");
    EXPECT_EQ(xmlEscaped(std::string("nul\0bell\a", 9)),
              "nul\xEF\xBF\xBD"
              "bell\xEF\xBF\xBD");
    EXPECT_EQ(xmlEscaped("caf\xC3\xA9 \xE2\x86\x92"), "caf\xC3\xA9 \xE2\x86\x92") << "UTF-8 is kept";
    EXPECT_EQ(xmlEscaped("bad \xC3 \xFF \xC0\xAF \xED\xA0\x80"),
              "bad \xEF\xBF\xBD \xEF\xBF\xBD \xEF\xBF\xBD\xEF\xBF\xBD \xEF\xBF\xBD\xEF\xBF\xBD\xEF\xBF\xBD")
        << "a cut sequence, a byte no UTF-8 has, an overlong '/', a surrogate";

    CheckResult broken;
    broken.path = std::string("dir\x01/na\xFFme\n.replay");
    broken.report = std::string("line 1 \x1B[31m\nline 2 ]]> <tag>");
    broken.notes = {"a note & more"};
    CheckResult passed;
    passed.status = CheckResult::kPassed;
    passed.path = "./tests/replays/short.replay";
    passed.seconds = 1.5;
    const fs::path report = dir_ / "report.xml";
    writeText(report, junitReport("suite \"x\"", {broken, passed}, {{"shard", "1/2"}}));
    nlohmann::json xml = parsed(report);
    ASSERT_EQ(xml["cases"].size(), 2u);
    EXPECT_EQ(xml["suites"][0]["name"], "suite \"x\"");
    EXPECT_EQ(xml["suites"][0]["time"], "1.500");
    EXPECT_EQ(xml["suites"][0]["properties"]["shard"], "1/2");
    EXPECT_EQ(xml["cases"][0]["error"]["text"], "line 1 \xEF\xBF\xBD[31m\nline 2 ]]> <tag>");
    EXPECT_EQ(xml["cases"][0]["error"]["message"], "line 1 \xEF\xBF\xBD[31m");
    EXPECT_EQ(xml["cases"][0]["name"], "na\xEF\xBF\xBDme\n.replay") << "a newline in an attribute is kept";
    EXPECT_EQ(xml["cases"][0]["out"], "note: a note & more\n");
    EXPECT_EQ(xml["cases"][1]["classname"], "tests.replays");
    EXPECT_EQ(xml["cases"][1]["time"], "1.500");
}

TEST_F(ReplayCi, ClassnamesComeFromTheFolder) {
    EXPECT_EQ(junitClassname("tests/replays/short.replay"), "tests.replays");
    EXPECT_EQ(junitClassname("./tests/replays/short.replay"), "tests.replays");
    EXPECT_EQ(junitClassname("/work/suite/a.replay"), "work.suite");
    EXPECT_EQ(junitClassname("a.replay"), ".");
    EXPECT_EQ(junitClassname("x/../a.replay"), ".");
}

TEST_F(ReplayCi, TheShardsAreDisjointAndTogetherCoverTheSuiteOnce) {
    // Seven files in two folders, named on the command line out of order: --list needs no real replays.
    std::vector<std::string> all;
    for (const char* name : {"b/3.replay", "a/1.replay", "b/1.replay", "a/2.replay", "b/2.replay",
                             "a/3.replay", "a/10.replay"}) {
        fs::create_directories((dir_ / name).parent_path());
        writeText(dir_ / name, "");
        all.push_back((dir_ / name).generic_string());
    }
    std::vector<std::string> sorted = all;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(listed({"--shard", "1/1", (dir_ / "b").string(), (dir_ / "a").string()}), sorted);
    for (std::size_t n = 1; n <= 5; ++n) {
        std::multiset<std::string> seen;
        for (std::size_t k = 1; k <= n; ++k) {
            std::vector<std::string> args = {"--shard", std::to_string(k) + "/" + std::to_string(n),
                                             (dir_ / "b").string(), (dir_ / "a").string()};
            std::vector<std::string> shard = listed(args);
            // Every N-th of the sorted suite from the K-th, the same from the function the tool uses.
            std::vector<std::string> expected;
            for (std::size_t i = k - 1; i < sorted.size(); i += n) expected.push_back(sorted[i]);
            EXPECT_EQ(shard, expected) << k << "/" << n;
            EXPECT_EQ(shardOf(all, Shard{k, n}), expected) << k << "/" << n;
            seen.insert(shard.begin(), shard.end());
        }
        EXPECT_EQ(std::vector<std::string>(seen.begin(), seen.end()), sorted)
            << "N = " << n << ": every replay exactly once";
    }
}

TEST_F(ReplayCi, AnEmptyShardPassesWithAnEmptyReport) {
    fs::copy(fs::path(POLAR_REPLAY_DIR) / "game-over.replay", dir_ / "only.replay");
    const fs::path report = dir_ / "report.xml";
    CommandOutcome r =
        run(POLARCADE_REPLAY_EXE, {"--shard", "2/3", "--junit", report.string(), dir_.string()});
    EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("shard 2/3: 0 of 1 replays"), std::string::npos) << r.out;
    nlohmann::json xml = parsed(report);
    EXPECT_EQ(xml["suites"][0]["tests"], "0");
    EXPECT_EQ(xml["suites"][0]["name"], "polarcade-replay shard 2/3");
    EXPECT_EQ(xml["suites"][0]["properties"]["shard"], "2/3");
}

TEST_F(ReplayCi, ABadShardIsOneMessageAndExitTwo) {
    for (const char* bad :
         {"0/3", "4/3", "a/b", "1/0", "3", "1/2/3", "-1/3", " 1/3", "99999999999999999999/3"}) {
        CommandOutcome r = run(POLARCADE_REPLAY_EXE, {"--shard", bad, POLAR_REPLAY_DIR});
        EXPECT_EQ(r.exitCode, 2) << bad;
        EXPECT_EQ(r.out, "") << bad;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << bad << ": " << r.err;
        EXPECT_EQ(r.err.rfind(std::string("polarcade-replay: --shard ") + bad + ": ", 0), 0u) << r.err;
        EXPECT_NE(r.err.find("expected K/N with 1 <= K <= N"), std::string::npos) << r.err;
    }
    std::string problem;
    EXPECT_FALSE(parseShard("0/3", problem));
    EXPECT_EQ(problem, "K is 0, outside 1..3");
    std::optional<Shard> fine = parseShard("2/3", problem);
    ASSERT_TRUE(fine);
    EXPECT_EQ(fine->index, 2u);
    EXPECT_EQ(fine->count, 3u);
}

TEST_F(ReplayCi, AReportThatCannotBeWrittenIsOneMessageExitTwoAndNoFile) {
    writeText(dir_ / "a-file", "x");
    fs::create_directories(dir_ / "a-folder");
    const std::vector<std::pair<std::string, std::string>> bad = {
        {(dir_ / "missing" / "report.xml").string(), "does not exist"},
        {(dir_ / "a-file" / "report.xml").string(), "is not a folder"},
        {(dir_ / "a-folder").string(), "it is a folder"},
        {(dir_ / "a-folder").string() + "/", "it names a folder"},
    };
    for (const auto& [path, why] : bad) {
        CommandOutcome r = run(POLARCADE_REPLAY_EXE, {"--junit", path, POLAR_REPLAY_DIR});
        EXPECT_EQ(r.exitCode, 2) << path;
        EXPECT_EQ(r.out, "") << "refused before any replay is played: " << path;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find("--junit " + path + ": "), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(why), std::string::npos) << r.err;
    }
    std::vector<std::string> left;
    for (const auto& entry : fs::recursive_directory_iterator(dir_)) left.push_back(entry.path().string());
    EXPECT_EQ(left.size(), 2u) << "nothing written besides a-file and a-folder";
}

}  // namespace
}  // namespace polar::game
