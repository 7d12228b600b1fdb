// polarcade-boards: the world boards from the command line, for CI systems and club tournaments.
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/input/data_folder.h"
#include "cli.h"
#include "http_client.h"
#include "key_store.h"
#include "polar/atomic_file.h"
#include "signature.h"

namespace {

using nlohmann::json;
using polar::boards::HttpReply;

struct Flags {
    std::string server, data, name, scene = "scenes/cave.json", mode, season = "all", around, output;
    std::vector<std::string> files;
    std::int64_t from = 1, run = 0;
    int count = 20;
    bool unranked = false;
};

std::string trimmed(std::string url) {
    while (!url.empty() && url.back() == '/') url.pop_back();
    return url;
}

// The error a server's JSON body names ("desync: …"), or the status and body as they came; one
// line, with the server's name for the replay ("submitted.replay") replaced by `file`.
std::string refusalOf(const HttpReply& reply, const std::string& file = "") {
    std::string text;
    json body = json::parse(reply.body, nullptr, false);
    if (reply.status == 0)
        text = "no answer: " + reply.error;
    else if (body.is_object() && body.contains("error") && body["error"].is_string())
        text = body["error"].get<std::string>() + ": " + body.value("message", "");
    else
        text = "HTTP " + std::to_string(reply.status) + ": " + reply.body.substr(0, 200);
    text = text.substr(0, text.find('\n'));
    constexpr std::string_view kServerName = "submitted.replay";
    if (std::size_t at = text.find(kServerName); !file.empty() && at != std::string::npos)
        text.replace(at, kServerName.size(), file);
    for (char& c : text)
        if (static_cast<unsigned char>(c) < 0x20) c = ' ';
    return text;
}

void addBoardFlags(polar::cli::Command& cmd, Flags& f) {
    cmd.option("--scene", f.scene, "The board's scene").showDefault();
    cmd.option("--mode", f.mode, "The board's mode (default: the server's, rules-N of its newest rules)");
    cmd.option("--season", f.season, "Runs of all time, this week or today (UTC)")
        .oneOf({"all", "week", "today"});
    cmd.option("--count", f.count, "Runs a page", {1, 100}).showDefault();
    cmd.flag("--unranked", f.unranked, "The board of runs sent without a run token (offline play)");
}

std::string boardQuery(const Flags& f) {
    std::string q = "scene=" + polar::boards::urlEncode(f.scene) + "&season=" + f.season +
                    "&count=" + std::to_string(f.count) + "&ranked=" + (f.unranked ? "false" : "true");
    if (!f.mode.empty()) q += "&mode=" + polar::boards::urlEncode(f.mode);
    return q;
}

int printBoard(const HttpReply& reply) {
    json body = json::parse(reply.body, nullptr, false);
    if (reply.status != 200 || !body.is_object()) {
        std::printf("refused  %s\n", refusalOf(reply).c_str());
        return 1;
    }
    std::printf("%s %s, %s, %s: %lld runs\n", body.value("scene", "").c_str(), body.value("mode", "").c_str(),
                body.value("season", "").c_str(), body.value("ranked", true) ? "ranked" : "unranked",
                static_cast<long long>(body.value("total", 0)));
    for (const json& run : body["runs"])
        std::printf("#%-5lld %-24s %8d  wave %-3d %7llu ticks  run %lld  %s\n",
                    static_cast<long long>(run.value("rank", 0)), run.value("name", "").c_str(),
                    run.value("score", 0), run.value("wave", 0),
                    static_cast<unsigned long long>(run.value("ticks", 0ULL)),
                    static_cast<long long>(run.value("id", 0)), run.value("submitted", "").c_str());
    return 0;
}

int submit(const Flags& f, const std::string& base) {
    polar::game::DataFolder folder = polar::game::openDataFolder(f.data);
    if (!folder.writable()) {
        std::fprintf(stderr, "polarcade-boards: %s\n",
                     folder.problem ? folder.problem->message().c_str() : "no data folder for the key");
        return polar::cli::kBadInput;
    }
    std::string note;
    polar::Result<std::string> key = polar::boards::loadOrMakeKey(folder.path, note);
    if (!key) {
        std::fprintf(stderr, "polarcade-boards: %s\n", key.error().message().c_str());
        return polar::cli::kBadInput;
    }
    if (!note.empty()) std::fprintf(stderr, "polarcade-boards: %s\n", note.c_str());
    const std::string publicKey = polar::server::publicKeyOf(*key);
    int refused = 0;
    for (const std::string& file : f.files) {
        std::ifstream in(file, std::ios::binary);
        std::stringstream text;
        text << in.rdbuf();
        if (!in) {
            std::printf("refused  %s  unreadable: cannot read the file\n", file.c_str());
            ++refused;
            continue;
        }
        const std::string replay = text.str();
        const std::string message =
            polar::server::signedMessage(f.name, polar::server::sha256Hex(replay), "");
        json body{{"name", f.name},
                  {"public_key", polar::server::toHex(publicKey)},
                  {"signature", polar::server::toHex(polar::server::sign(*key, message))},
                  {"replay", replay}};
        HttpReply reply = polar::boards::httpRequest(
            base + "/v1/runs", body.dump(-1, ' ', false, json::error_handler_t::replace), "application/json",
            120, true);
        json answer = json::parse(reply.body, nullptr, false);
        if (reply.status == 201 && answer.is_object()) {
            std::printf("verified %s  run %lld  score %d  wave %d  %llu ticks  %s %s %s  #%lld\n",
                        file.c_str(), static_cast<long long>(answer.value("id", 0)), answer.value("score", 0),
                        answer.value("wave", 0), static_cast<unsigned long long>(answer.value("ticks", 0ULL)),
                        answer.value("scene", "").c_str(), answer.value("mode", "").c_str(),
                        answer.value("ranked", false) ? "ranked" : "unranked",
                        static_cast<long long>(answer.value("rank", 0)));
        } else {
            std::printf("refused  %s  %s\n", file.c_str(), refusalOf(reply, file).c_str());
            ++refused;
        }
    }
    return refused ? 1 : 0;
}

int fetch(const Flags& f, const std::string& base) {
    HttpReply reply = polar::boards::httpRequest(base + "/v1/runs/" + std::to_string(f.run) + "/replay");
    if (reply.status != 200) {
        std::printf("refused  run %lld  %s\n", static_cast<long long>(f.run), refusalOf(reply).c_str());
        return 1;
    }
    const std::string out = f.output.empty() ? "run-" + std::to_string(f.run) + ".replay" : f.output;
    if (std::optional<polar::Error> error = polar::writeFileAtomically(out, reply.body)) {
        std::fprintf(stderr, "polarcade-boards: %s\n", error->message().c_str());
        return polar::cli::kBadInput;
    }
    std::printf("fetched  run %lld  %s  %zu bytes\n", static_cast<long long>(f.run), out.c_str(),
                reply.body.size());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    polar::cli::Command app{
        "Submits runs to a Polarcade world-board server (polarcade-server) and reads its boards. Runs are "
        "signed "
        "with the player's Ed25519 key, made on first use and kept in the data folder (online-key, readable "
        "by "
        "its owner only). Prints one line per run with its verdict. Exit code 0: every run verified; 1: a "
        "run "
        "was refused or the server did not answer; 2: bad arguments.",
        "polarcade-boards"};
    Flags f;
    app.option("--server", f.server, "The server's address, http://HOST:PORT").required().typeName("URL");
    app.option("--data", f.data, "The data folder with the key (default: the game's data folder)")
        .typeName("DIR");
    polar::cli::Command& submitCmd = app.subcommand("submit", "Sends replay files; one verdict line each");
    submitCmd.option("files", f.files, "Replay files").required().typeName("FILE");
    submitCmd.option("--name", f.name, "The player's name (it belongs to the first key that uses it)")
        .required();
    polar::cli::Command& topCmd = app.subcommand("top", "Prints a board's best runs");
    addBoardFlags(topCmd, f);
    topCmd.option("--from", f.from, "The first rank shown", {1, std::int64_t{1} << 40}).showDefault();
    polar::cli::Command& aroundCmd = app.subcommand("around", "Prints the runs around a player's best");
    aroundCmd.option("name", f.around, "The player's name").required();
    addBoardFlags(aroundCmd, f);
    polar::cli::Command& fetchCmd = app.subcommand("fetch", "Downloads a run's replay");
    fetchCmd.option("run", f.run, "The run's number", {1, std::int64_t{1} << 60}).required();
    fetchCmd.option("-o,--output", f.output, "Where to write it (default run-RUN.replay)").typeName("FILE");
    app.requireSubcommand();
    if (int code = app.parse(argc, argv); code >= 0) return code;

    const std::string base = trimmed(f.server);
    if (submitCmd.parsed()) return submit(f, base);
    if (fetchCmd.parsed()) return fetch(f, base);
    if (topCmd.parsed())
        return printBoard(polar::boards::httpRequest(base + "/v1/boards/top?" + boardQuery(f) +
                                                     "&from=" + std::to_string(f.from)));
    return printBoard(polar::boards::httpRequest(base + "/v1/boards/around?" + boardQuery(f) +
                                                 "&name=" + polar::boards::urlEncode(f.around)));
}
