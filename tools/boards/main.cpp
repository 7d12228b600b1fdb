// polarcade-boards: the world boards from the command line, for CI systems and club tournaments.
#include <cstdio>
#include <fstream>
#include <sstream>

#include "app/input/data_folder.h"
#include "cli.h"
#include "http_client.h"
#include "key_store.h"
#include "polar/atomic_file.h"
#include "polar/json_doc.h"
#include "polar/json_writer.h"
#include "signature.h"

namespace {

using polar::JsonDoc;
using polar::JsonNode;

// A server's JSON answer, or nothing when it is not JSON.
std::optional<JsonDoc> parsed(const std::string& body) {
    polar::Result<JsonDoc> doc = polar::JsonDoc::parse(polar::SourceFile{"answer", body});
    if (!doc) return std::nullopt;
    return std::move(*doc);
}

// A member of an object as text ("" when missing or not a string).
std::string textOf(const JsonNode& object, const char* key) {
    std::optional<JsonNode> node = object.isObject() ? object.find(key) : std::nullopt;
    return node && node->isString() ? node->string(key) : "";
}

// A member of an object as a number (0 when missing or not one).
long long numberOf(const JsonNode& object, const char* key) {
    std::optional<JsonNode> node = object.isObject() ? object.find(key) : std::nullopt;
    return node && node->isNumber() ? static_cast<long long>(node->number(key)) : 0;
}

bool flagOf(const JsonNode& object, const char* key) {
    std::optional<JsonNode> node = object.isObject() ? object.find(key) : std::nullopt;
    return node && node->isBoolean() && node->boolean(key);
}
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
    std::optional<JsonDoc> body = parsed(reply.body);
    if (reply.status == 0)
        text = "no answer: " + reply.error;
    else if (body && !textOf(body->root(), "error").empty())
        text = textOf(body->root(), "error") + ": " + textOf(body->root(), "message");
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
    std::optional<JsonDoc> doc = parsed(reply.body);
    if (reply.status != 200 || !doc || !doc->root().isObject()) {
        std::printf("refused  %s\n", refusalOf(reply).c_str());
        return 1;
    }
    const JsonNode body = doc->root();
    std::printf("%s %s, %s, %s: %lld runs\n", textOf(body, "scene").c_str(), textOf(body, "mode").c_str(),
                textOf(body, "season").c_str(), flagOf(body, "ranked") ? "ranked" : "unranked",
                numberOf(body, "total"));
    std::optional<JsonNode> runs = body.find("runs");
    for (std::size_t i = 0; runs && i < runs->size(); ++i) {
        const JsonNode run = runs->at(i);
        std::printf("#%-5lld %-24s %8lld  wave %-3lld %7lld ticks  run %lld  %s\n", numberOf(run, "rank"),
                    textOf(run, "name").c_str(), numberOf(run, "score"), numberOf(run, "wave"),
                    numberOf(run, "ticks"), numberOf(run, "id"), textOf(run, "submitted").c_str());
    }
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
        polar::JsonWriter body;
        body.beginObject()
            .member("name", f.name)
            .member("public_key", polar::server::toHex(publicKey))
            .member("signature", polar::server::toHex(polar::server::sign(*key, message)))
            .member("replay", replay)
            .endObject();
        HttpReply reply =
            polar::boards::httpRequest(base + "/v1/runs", body.text(), "application/json", 120, true);
        std::optional<JsonDoc> answer = parsed(reply.body);
        if (reply.status == 201 && answer) {
            const JsonNode a = answer->root();
            std::printf("verified %s  run %lld  score %lld  wave %lld  %lld ticks  %s %s %s  #%lld\n",
                        file.c_str(), numberOf(a, "id"), numberOf(a, "score"), numberOf(a, "wave"),
                        numberOf(a, "ticks"), textOf(a, "scene").c_str(), textOf(a, "mode").c_str(),
                        flagOf(a, "ranked") ? "ranked" : "unranked", numberOf(a, "rank"));
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
