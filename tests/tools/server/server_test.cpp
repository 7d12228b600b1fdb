// polarcade-server over real HTTP on loopback: the golden replays submitted and read back from the
// boards, and every attack of issue 44 refused with its JSON error and nothing stored.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>

#include "golden_replays.h"
#include "replay/replay.h"
#include "replay/replay_format.h"
#include "scratch_folder.h"
#include "test_server.h"

namespace polar::server {
namespace {

using nlohmann::json;
using polar::testing::signedBody;
using polar::testing::TestServer;

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string golden(const std::string& name) {
    return readFile(std::string(POLAR_REPLAY_DIR) + "/" + name);
}

// `text` with the first `from` (which must be there) replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
    std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

// Sends raw bytes to the server and returns its answer: the headers and a body of their
// Content-Length (or what came before the server closed, or 5 s passed).
std::string rawExchange(int port, const std::string& bytes) {
    int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<std::uint16_t>(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    timeval timeout{5, 0};
    ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
    std::string answer;
    if (::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0) {
        ::send(fd, bytes.data(), bytes.size(), MSG_NOSIGNAL);
        char buffer[4096];
        for (ssize_t n; (n = ::recv(fd, buffer, sizeof buffer, 0)) > 0;) {
            answer.append(buffer, static_cast<std::size_t>(n));
            const std::size_t end = answer.find("\r\n\r\n");
            const std::size_t length = answer.find("Content-Length: ");
            if (end != std::string::npos && length != std::string::npos && length < end &&
                answer.size() >= end + 4 + std::stoul(answer.substr(length + 16)))
                break;
        }
    }
    ::close(fd);
    return answer;
}

class ServerTest : public ::testing::Test {
  protected:
    void SetUp() override { folder = polar::testing::freshTestFolder("polar-server"); }
    void TearDown() override {
        server.reset();
        std::filesystem::remove_all(folder);
    }
    void start(Limits limits = {}, double cpuSeconds = 5.0) {
        server = std::make_unique<TestServer>(folder, limits, cpuSeconds);
    }

    struct Reply {
        int status = 0;
        json body;
        std::string retryAfter;
    };
    Reply post(const std::string& path, const std::string& body) {
        httplib::Result r = server->client().Post(path.c_str(), body, "application/json");
        if (!r) return {};
        return {r->status, json::parse(r->body, nullptr, false), r->get_header_value("Retry-After")};
    }
    Reply submit(const json& body) { return post("/v1/runs", body.dump()); }
    Reply get(const std::string& path) {
        httplib::Result r = server->client().Get(path.c_str());
        if (!r) return {};
        return {r->status, json::parse(r->body, nullptr, false), r->get_header_value("Retry-After")};
    }
    std::string token() {
        Reply r = post("/v1/tokens", "");
        EXPECT_EQ(r.status, 201);
        return r.body.value("token", "");
    }
    // The refusal `word` with its status, and no run stored.
    void expectRefused(const Reply& r, int status, const std::string& word) {
        EXPECT_EQ(r.status, status) << r.body.dump();
        EXPECT_EQ(r.body.value("error", ""), word) << r.body.dump();
        EXPECT_FALSE(r.body.value("message", "").empty());
        EXPECT_EQ(get("/v1/runs/1").status, 404) << "a refused run was stored";
    }

    std::filesystem::path folder;
    std::unique_ptr<TestServer> server;
    KeyPair ada = generateKeyPair(), bob = generateKeyPair();
};

TEST_F(ServerTest, GoldenRunsAreVerifiedRankedAndReadBackFromTheBoards) {
    start();
    int verified = 0;
    std::set<std::string> boards;
    for (const std::string& file : polar::testing::goldenReplays()) {
        const std::string replay = readFile(file);
        Result<polar::game::Replay> parsed = polar::game::parseReplay(file, replay);
        ASSERT_TRUE(parsed) << parsed.error().message();
        const std::string t = token();
        server->now +=
            static_cast<std::int64_t>(parsed->actions.size()) * 1000 / 60 + 1000;  // played in real time
        Reply r = submit(signedBody("Ada", replay, ada, t));
        if (parsed->header.sceneIsFile) {  // crowded.replay's scene is its own file: not the server's
            EXPECT_EQ(r.status, 422);
            EXPECT_EQ(r.body.value("error", ""), "scene");
            continue;
        }
        if (!polar::game::firstTuningDifference(parsed->header.tuning, polar::game::Tuning{}).empty()) {
            // minefield.replay and saucers.replay start with nine lives: not the game every player plays
            EXPECT_EQ(r.status, 422) << file;
            EXPECT_EQ(r.body.value("error", ""), "tuning") << file;
            continue;
        }
        ASSERT_EQ(r.status, 201) << file << ": " << r.body.dump();
        ++verified;
        boards.insert(r.body["scene"].get<std::string>() + " " + r.body["mode"].get<std::string>());
        // The server's score is the game's at the last tick, which the last checkpoint also records.
        EXPECT_EQ(r.body["score"], parsed->checkpoints.back().score) << file;
        EXPECT_EQ(r.body["wave"], parsed->checkpoints.back().wave) << file;
        EXPECT_EQ(r.body["ticks"], parsed->actions.size()) << file;
        EXPECT_TRUE(r.body["ranked"].get<bool>());
        const std::int64_t id = r.body["id"];
        const std::string scene = r.body["scene"], mode = r.body["mode"];
        Reply board = get("/v1/boards/top?scene=" + scene + "&mode=" + mode + "&season=today");
        ASSERT_EQ(board.status, 200);
        bool listed = false;
        for (const json& run : board.body["runs"])
            listed |= run["id"] == id && run["score"] == r.body["score"];
        EXPECT_TRUE(listed) << board.body.dump();
        httplib::Result bytes = server->client().Get(("/v1/runs/" + std::to_string(id) + "/replay").c_str());
        ASSERT_TRUE(bytes);
        EXPECT_EQ(bytes->body, replay);
    }
    EXPECT_GE(verified, 4);
    Reply best = get("/v1/players/best?name=ada");  // the best run on each board (scene and mode)
    ASSERT_EQ(best.status, 200);
    EXPECT_EQ(best.body["runs"].size(), boards.size());
    Reply around = get("/v1/boards/around?name=Ada&scene=scenes/cave.json&mode=rules-1");
    ASSERT_EQ(around.status, 200) << around.body.dump();
    EXPECT_EQ(around.body["rank"], 1);
}

TEST_F(ServerTest, RunsWithoutATokenAreKeptUnranked) {
    start();
    Reply r = submit(signedBody("Ada", golden("short.replay"), ada));
    ASSERT_EQ(r.status, 201) << r.body.dump();
    EXPECT_FALSE(r.body["ranked"].get<bool>());
    EXPECT_EQ(get("/v1/boards/top?mode=rules-1").body["total"], 0);
    EXPECT_EQ(get("/v1/boards/top?mode=rules-1&ranked=false").body["total"], 1);
}

TEST_F(ServerTest, AChangedInputIsADesync) {
    start();
    expectRefused(
        submit(signedBody("Ada", replaced(golden("short.replay"), "\nin R*2 RT", "\nin L*2 RT"), ada)), 422,
        "desync");
}

TEST_F(ServerTest, AnEditedCheckpointOrTraceIsRefused) {
    start();
    const std::string replay = golden("short.replay");
    expectRefused(submit(signedBody("Ada", replaced(replay, "score=70 lives=3", "score=75 lives=3"), ada)),
                  422, "damaged");
    expectRefused(submit(signedBody("Ada", replaced(replay, "trace 3cLA", "trace 3dLA"), ada)), 422,
                  "damaged");
}

TEST_F(ServerTest, AnEditedScoreLineIsRefused) {
    start();
    // The last checkpoint holds the final score: claiming more than was played is refused.
    expectRefused(submit(signedBody("Ada",
                                    replaced(golden("short.replay"),
                                             "check 600 996519cb1ae926ab rng=3d57156828b2ffe6 score=340",
                                             "check 600 996519cb1ae926ab rng=3d57156828b2ffe6 score=99340"),
                                    ada)),
                  422, "damaged");
}

TEST_F(ServerTest, AnotherVersionModSceneOrTuningIsRefused) {
    start();
    const std::string replay = golden("short.replay");
    expectRefused(submit(signedBody("Ada", replaced(replay, "\ngame 0.1.0\n", "\ngame 0.0.9\n"), ada)), 422,
                  "version");
    expectRefused(submit(signedBody("Ada", replaced(replay, "\nseed 1\n", "\nseed 1\nrules 9\n"), ada)), 422,
                  "version");
    expectRefused(submit(signedBody("Ada", replaced(replay, "\nseed 1\n", "\nseed 1\nmod my-mod\n"), ada)),
                  422, "mods");
    expectRefused(submit(signedBody(
                      "Ada", replaced(replay, "scene scenes/cave.json", "scene scenes/nowhere.json"), ada)),
                  422, "scene");
    expectRefused(submit(signedBody("Ada",
                                    replaced(replay, "asset 02d086663a083c1b scenes/cave.json",
                                             "asset 02d086663a083c1c scenes/cave.json"),
                                    ada)),
                  422, "scene");
    expectRefused(submit(signedBody("Ada", golden("crowded.replay"), ada)), 422, "scene");
    expectRefused(submit(signedBody("Ada", replaced(replay, "thrust=260", "thrust=400"), ada)), 422,
                  "tuning");
}

TEST_F(ServerTest, TruncatedOrOversizeBodiesAreRefused) {
    start();
    const std::string body = signedBody("Ada", golden("short.replay"), ada).dump();
    expectRefused(post("/v1/runs", body.substr(0, body.size() / 2)), 400, "bad-request");
    // A replay cut short inside a valid body has no end line.
    const std::string replay = golden("short.replay");
    expectRefused(submit(signedBody("Ada", replay.substr(0, replay.find("\nend ") + 1), ada)), 422,
                  "incomplete");
    // A body of 100 MB is refused from its Content-Length, before it is read.
    std::string answer = rawExchange(server->port,
                                     "POST /v1/runs HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
                                     "Content-Length: 104857600\r\n\r\n{\"name\":");
    EXPECT_NE(answer.find("HTTP/1.1 413"), std::string::npos) << answer;
    EXPECT_NE(answer.find("\"error\":\"too-large\""), std::string::npos) << answer;
    EXPECT_EQ(get("/v1/runs/1").status, 404);
}

TEST_F(ServerTest, ABadSignatureOrAnotherKeysNameIsRefused) {
    start();
    const std::string replay = golden("short.replay");
    json forged = signedBody("Ada", replay, ada);
    std::string signature = forged["signature"];
    signature[0] = signature[0] == '0' ? '1' : '0';
    forged["signature"] = signature;
    expectRefused(submit(forged), 403, "bad-signature");
    json renamed = signedBody("Ada", replay, ada);
    renamed["name"] = "Eve";  // signed as Ada
    expectRefused(submit(renamed), 403, "bad-signature");
    json otherReplay = signedBody("Ada", replay, ada);
    otherReplay["replay"] = golden("field.replay");  // the signature covers the replay's hash
    expectRefused(submit(otherReplay), 403, "bad-signature");

    ASSERT_EQ(submit(signedBody("Ada", replay, ada)).status, 201);
    Reply taken = submit(signedBody("ADA", golden("field.replay"), bob));  // names compare without case
    EXPECT_EQ(taken.status, 403);
    EXPECT_EQ(taken.body.value("error", ""), "name-taken");
    EXPECT_EQ(get("/v1/runs/2").status, 404);
}

TEST_F(ServerTest, TheSameRunTwiceIsRefused) {
    start();
    const std::string replay = golden("short.replay");
    ASSERT_EQ(submit(signedBody("Ada", replay, ada)).status, 201);
    EXPECT_EQ(submit(signedBody("Ada", replay, ada)).body.value("error", ""), "duplicate");
    // Other bytes, the same run: a comment added, and by another player.
    Reply again = submit(signedBody("Bob", replaced(replay, "\ngame ", "\n# mine\ngame "), bob));
    EXPECT_EQ(again.status, 409);
    EXPECT_EQ(again.body.value("error", ""), "duplicate");
    EXPECT_EQ(get("/v1/runs/2").status, 404);
}

TEST_F(ServerTest, ARunFasterThanItsTokenIsRefusedAndATokenIsUsedOnce) {
    start();
    const std::string replay = golden("short.replay");  // 600 ticks: 10 s of play
    const std::string t = token();
    server->now += 2000;
    expectRefused(submit(signedBody("Ada", replay, ada, t)), 422, "too-fast");
    server->now += 9000;  // 11 s after the token
    Reply ok = submit(signedBody("Ada", replay, ada, t));
    ASSERT_EQ(ok.status, 201) << ok.body.dump();
    EXPECT_TRUE(ok.body["ranked"].get<bool>());
    server->now += 60'000;
    Reply reused = submit(signedBody("Ada", golden("field.replay"), ada, t));
    EXPECT_EQ(reused.status, 403);
    EXPECT_EQ(reused.body.value("error", ""), "bad-token");
    Reply unknown = submit(signedBody("Ada", golden("field.replay"), ada, std::string(32, 'a')));
    EXPECT_EQ(unknown.body.value("error", ""), "bad-token");
    EXPECT_EQ(get("/v1/runs/2").status, 404);
}

TEST_F(ServerTest, NamesWithControlCharactersAreRefusedSqlAndHtmlAreKeptAsText) {
    start();
    const std::string replay = golden("short.replay");
    for (const std::string& name : {std::string("Ada\x01"), std::string("A\nB"),
                                    std::string("\xE2\x80\xAE"
                                                "Ada"),
                                    std::string(), std::string(" Ada"), std::string(25, 'x')})
        expectRefused(submit(signedBody(name, replay, ada)), 400, "bad-request");
    // A name that is not UTF-8 (JSON text must be).
    expectRefused(post("/v1/runs", replaced(signedBody("Ada", replay, ada).dump(), "\"Ada\"", "\"A\xC3\"")),
                  400, "bad-request");
    const std::string sql = "x'); DROP TABLE runs;--";
    const std::string html = "<img src=x onerror=a()>";
    ASSERT_EQ(submit(signedBody(sql, replay, ada)).status, 201);
    ASSERT_EQ(submit(signedBody(html, golden("field.replay"), ada)).status, 201);
    Reply board = get("/v1/boards/top?mode=rules-1&ranked=false");
    ASSERT_EQ(board.status, 200);
    ASSERT_EQ(board.body["runs"].size(), 1u);
    EXPECT_EQ(board.body["runs"][0]["name"], sql);
    httplib::Result raw = server->client().Get("/v1/players/best?name=%3Cimg%20src%3Dx%20onerror%3Da()%3E");
    ASSERT_TRUE(raw);
    EXPECT_EQ(raw->status, 200);
    EXPECT_EQ(raw->get_header_value("Content-Type"), "application/json");
    EXPECT_EQ(raw->get_header_value("X-Content-Type-Options"), "nosniff");
    EXPECT_EQ(json::parse(raw->body)["runs"][0]["name"], html);
}

TEST_F(ServerTest, MalformedHttpAndJsonGetAClearJsonError) {
    start();
    for (const std::string& request :
         {std::string("GARBAGE\r\n\r\n"),
          std::string("POST /v1/runs HTTP/1.1\r\nHost: x\r\nContent-Length: abc\r\n\r\n"),
          std::string("GET /v1/server HTTP/9.9\r\n\r\n")}) {
        std::string answer = rawExchange(server->port, request);
        EXPECT_NE(answer.find("HTTP/1.1 400"), std::string::npos) << request << " -> " << answer;
        EXPECT_NE(answer.find("\"error\":\"bad-request\""), std::string::npos) << answer;
    }
    Reply notJson = post("/v1/runs", "{\"name\": \"Ada\",\n \"replay\": ]");
    EXPECT_EQ(notJson.status, 400);
    EXPECT_NE(notJson.body.value("message", "").find("request body:2:"), std::string::npos)
        << notJson.body.dump();
    EXPECT_EQ(post("/v1/runs", "[1, 2]").status, 400);
    EXPECT_EQ(post("/v1/runs", "{\"name\": 7}").body.value("message", ""),
              "request body:1:10: found a number; expected the player's name as a string");
    // A key given twice could be read one way here and another way by a proxy or a log.
    EXPECT_EQ(post("/v1/runs", "{\"name\": \"Ada\", \"name\": \"Eve\"}").status, 400);
    EXPECT_EQ(post("/v1/runs", "{\"name\": \"Ada\", \"score\": 99999}").status, 400);
    EXPECT_EQ(get("/v1/boards/top?count=1000").status, 400);
    EXPECT_EQ(get("/v1/boards/top?season=month").status, 400);
    EXPECT_EQ(get("/v1/nothing").body.value("error", ""), "not-found");
}

TEST_F(ServerTest, AClientThatStopsSendingIsDroppedAndOthersAreServed) {
    start();
    // Half a request, then nothing: the server answers meanwhile, and drops it after its 5 s read
    // timeout (a trickle of a byte every few seconds is not stopped: tools/server/README.md).
    std::thread slow([&] {
        const auto begin = std::chrono::steady_clock::now();
        std::string answer = rawExchange(server->port, "POST /v1/runs HTTP/1.1\r\nHost: x\r\nContent-Le");
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
        EXPECT_LT(seconds, 8.0);
        EXPECT_NE(answer.find("HTTP/1.1 400"), std::string::npos) << answer;
    });
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    EXPECT_EQ(get("/v1/server").status, 200);
    slow.join();
}

TEST_F(ServerTest, TooManyRunsAMinuteAreAnswered429) {
    Limits limits;
    limits.runsPerKeyPerMinute = 2;
    start(limits);
    const std::string replay = golden("short.replay");
    EXPECT_EQ(submit(signedBody("Ada", replay, ada)).status, 201);
    EXPECT_EQ(submit(signedBody("Ada", replay, ada)).status, 409);
    Reply limited = submit(signedBody("Ada", golden("field.replay"), ada));
    EXPECT_EQ(limited.status, 429);
    EXPECT_EQ(limited.body.value("error", ""), "rate-limited");
    EXPECT_FALSE(limited.retryAfter.empty());
    server->now += 61'000;  // a minute later the key may send again
    EXPECT_EQ(submit(signedBody("Ada", golden("field.replay"), ada)).status, 201);
}

TEST_F(ServerTest, AFullQueueIsAnswered503WithRetryAfter) {
    Limits limits;
    limits.verifyQueue = 0;  // no room at all: every run finds the queue full
    start(limits);
    Reply busy = submit(signedBody("Ada", golden("short.replay"), ada));
    EXPECT_EQ(busy.status, 503);
    EXPECT_EQ(busy.body.value("error", ""), "busy");
    EXPECT_EQ(busy.retryAfter, std::to_string(limits.retryAfterSeconds));
}

TEST_F(ServerTest, ARunOverTheCpuCapIsRefused) {
    start(Limits{}, 1e-6);
    expectRefused(submit(signedBody("Ada", golden("storm.replay"), ada)), 422, "cpu-limit");
}

}  // namespace
}  // namespace polar::server
