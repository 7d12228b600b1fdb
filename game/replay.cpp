#include "replay.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <limits>
#include <span>
#include <sstream>

#include "polar/atomic_file.h"
#include "polar/state_hash.h"
#include "polar/world_hash.h"

#if defined(__unix__) || defined(__APPLE__)
#include <fcntl.h>
#include <unistd.h>
#define POLAR_HAVE_FSYNC 1
#endif

namespace polar::game {
namespace {

namespace fs = std::filesystem;

constexpr const char* kMagic = "polarcade-replay";
constexpr const char* kSimulatedFull = "no space left on device (simulated)";
// Two characters of this alphabet (base64url) hold one tick's 12-bit trace.
constexpr char kTraceAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";
// Action letters in the order they are written.
constexpr struct {
    char letter;
    Actions bit;
} kActionLetters[] = {{'L', kTurnLeft}, {'R', kTurnRight}, {'T', kThrust}, {'F', kFire}};
constexpr const char* kActionsExpected =
    "a run of actions: letters L (turn left), R (turn right), T (thrust), F (fire) or '.' for none, "
    "then optionally *COUNT (e.g. LF*12)";

// Tuning values as the "tuning" line names them. tickRate has a line of its own ("tick-rate").
struct TuningField {
    const char* name;
    double Tuning::*real;
    int Tuning::*whole;
};
constexpr TuningField kTuningFields[] = {
    {"turn-rate", &Tuning::turnRate, nullptr},
    {"thrust", &Tuning::thrust, nullptr},
    {"max-ship-speed", &Tuning::maxShipSpeed, nullptr},
    {"ship-damping", &Tuning::shipDamping, nullptr},
    {"bullet-speed", &Tuning::bulletSpeed, nullptr},
    {"bullet-life", &Tuning::bulletLife, nullptr},
    {"fire-cooldown", &Tuning::fireCooldown, nullptr},
    {"max-bullets", nullptr, &Tuning::maxBullets},
    {"respawn-delay", &Tuning::respawnDelay, nullptr},
    {"invulnerable-after-respawn", &Tuning::invulnerableAfterRespawn, nullptr},
    {"shield-time", &Tuning::shieldTime, nullptr},
    {"pickup-life", &Tuning::pickupLife, nullptr},
    {"pickup-chance", &Tuning::pickupChance, nullptr},
    {"wave-delay", &Tuning::waveDelay, nullptr},
    {"start-lives", nullptr, &Tuning::startLives},
    {"extra-life-every", nullptr, &Tuning::extraLifeEvery},
};
constexpr double kMaxTuningValue = 1e6;
// 14 doubles and 3 ints (plus one int of padding after maxBullets). A new Tuning field changes the
// size: list it above so replays record it.
static_assert(sizeof(Tuning) == 14 * sizeof(double) + 4 * sizeof(int),
              "add the new Tuning field to kTuningFields");

std::string hex64(std::uint64_t v) {
    char buffer[17];
    std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(v));
    return buffer;
}

std::string hex16(std::uint16_t v) {
    char buffer[5];
    std::snprintf(buffer, sizeof buffer, "%04x", static_cast<unsigned>(v));
    return buffer;
}

// The shortest text that reads back as exactly the same double.
std::string exactDouble(double v) {
    char buffer[32];
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
    return std::string(buffer, end);
}

std::uint64_t hashBytes(std::string_view bytes) {
    StateHash h;
    h.addBytes(bytes.data(), bytes.size());
    return h.value();
}

const char* kindName(Kind kind) {
    switch (kind) {
        case Kind::Arena:
            return "arena";
        case Kind::Ship:
            return "ship";
        case Kind::Rock:
            return "rock";
        case Kind::Bullet:
            return "bullet";
        case Kind::Pickup:
            return "pickup";
        case Kind::Comet:
            return "comet";
        case Kind::Scenery:
            return "scenery";
    }
    return "object";
}

std::uint16_t digestOf(const Game& game, const GameObject& object) {
    StateHash h;
    h.add(objectHash(object));
    h.add(static_cast<int>(game.kindOf(object.id)));
    h.add(game.rockSize(object.id));
    return static_cast<std::uint16_t>(h.value() >> 48);
}

fs::path folderOf(const std::string& file) {
    return fs::absolute(fs::path(file)).lexically_normal().parent_path();
}

// `path` relative to `folder`, or nothing when it lies outside.
std::optional<std::string> inside(const fs::path& path, const fs::path& folder) {
    fs::path relative = path.lexically_relative(fs::absolute(folder).lexically_normal());
    if (relative.empty() || *relative.begin() == "..") return std::nullopt;
    return relative.generic_string();
}

// How a replay names a file the game read: logical paths as they are; an absolute path inside a mod
// or the asset folder as the logical path it stands for; any other relative to `anchor`'s folder.
std::string nameFor(const std::string& path, const AssetFs* assets, const std::string& anchor) {
    fs::path p(path);
    if (!p.is_absolute()) return path;
    p = p.lexically_normal();
    if (assets) {
        for (auto mod = assets->mods().rbegin(); mod != assets->mods().rend(); ++mod)
            if (auto logical = inside(p, *mod)) return *logical;
        if (auto logical = inside(p, assets->root())) return *logical;
    }
    fs::path relative = p.lexically_relative(folderOf(anchor));
    return relative.empty() ? p.generic_string() : relative.generic_string();
}

// ---- writing ----------------------------------------------------------------------------------

std::string actionLetters(Actions actions) {
    std::string out;
    for (const auto& [letter, bit] : kActionLetters)
        if (actions & bit) out += letter;
    return out.empty() ? "." : out;
}

void appendInputs(std::string& out, std::span<const Actions> actions) {
    if (actions.empty()) return;
    out += "in";
    for (std::size_t i = 0; i < actions.size();) {
        std::size_t j = i;
        while (j < actions.size() && actions[j] == actions[i]) ++j;
        out += ' ';
        out += actionLetters(actions[i]);
        if (j - i > 1) out += '*' + std::to_string(j - i);
        i = j;
    }
    out += '\n';
}

void appendTrace(std::string& out, std::span<const std::uint16_t> trace) {
    if (trace.empty()) return;
    out += "trace ";
    for (std::uint16_t v : trace) {
        out += kTraceAlphabet[(v >> 6) & 63];
        out += kTraceAlphabet[v & 63];
    }
    out += '\n';
}

void appendCheckpoint(std::string& out, const Checkpoint& c) {
    out += "check " + std::to_string(c.tick) + ' ' + hex64(c.hash) + " rng=" + hex64(c.rng) +
           " score=" + std::to_string(c.score) + " lives=" + std::to_string(c.lives) +
           " wave=" + std::to_string(c.wave) + '\n';
    out += "objects";
    for (const ObjectDigest& o : c.objects) out += ' ' + std::to_string(o.id) + ':' + hex16(o.digest);
    out += '\n';
}

std::string headerText(const ReplayHeader& h) {
    std::string out = std::string(kMagic) + ' ' + std::to_string(kReplayFormat) + '\n';
    for (const std::string& comment : h.comments) out += comment + '\n';
    out += "game " + h.gameVersion + '\n';
    out += (h.sceneIsFile ? "scene-file " : "scene ") + h.scene + '\n';
    out += "seed " + std::to_string(h.seed) + '\n';
    out += "tick-rate " + exactDouble(h.tuning.tickRate) + '\n';
    out += "tuning";
    for (const TuningField& f : kTuningFields)
        out += std::string(" ") + f.name + '=' +
               (f.real ? exactDouble(h.tuning.*f.real) : std::to_string(h.tuning.*f.whole));
    out += '\n';
    for (const std::string& mod : h.mods) out += "mod " + mod + '\n';
    for (const AssetStamp& a : h.assets) out += "asset " + hex64(a.hash) + ' ' + a.name + '\n';
    for (const ReplayScreenshot& s : h.screenshots)
        out += "screenshot " + std::to_string(s.tick) + ':' + s.png + '\n';
    return out + "begin\n";
}

// ---- reading ----------------------------------------------------------------------------------

struct Token {
    std::string_view text;
    int column = 0;  // 1-based
};

// Spaces, tabs and carriage returns separate tokens: a stray '\r' (a file edited on Windows) must
// not end up inside a name or a reason, which the writer would then drop on a rewrite.
bool isBlank(char c) {
    return c == ' ' || c == '\t' || c == '\r';
}

std::vector<Token> tokenize(std::string_view line) {
    std::vector<Token> tokens;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && isBlank(line[i])) ++i;
        std::size_t start = i;
        while (i < line.size() && !isBlank(line[i])) ++i;
        if (i > start) tokens.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
    }
    return tokens;
}

template <class T>
bool parseInteger(std::string_view text, T& out, int base = 10) {
    if (text.empty() || text[0] == '+' || text[0] == '-') return false;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out, base);
    return ec == std::errc() && end == text.data() + text.size();
}

bool parseSignedInt(std::string_view text, int& out) {
    if (text.empty() || text[0] == '+') return false;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return ec == std::errc() && end == text.data() + text.size();
}

bool parseDouble(std::string_view text, double& out) {
    if (text.empty() || text[0] == '+') return false;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return ec == std::errc() && end == text.data() + text.size() && std::isfinite(out);
}

// Thrown inside the parser only, caught at its boundary and returned as an Error.
struct ParseFailure {
    Error error;
};

class Parser {
  public:
    Parser(std::string path, std::string_view text) : path_(std::move(path)), text_(text) {}

    Result<Replay> run() {
        try {
            parse();
        } catch (const ParseFailure& failure) {
            return failure.error;
        }
        return std::move(replay_);
    }

  private:
    [[noreturn]] void fail(int column, const std::string& what, const std::string& expected) const {
        throw ParseFailure{Error{path_, line_, column, what, expected}};
    }

    // The rest of the line from a token on (names may hold spaces).
    std::string restFrom(const Token& token) const {
        std::string_view rest = current_.substr(static_cast<std::size_t>(token.column - 1));
        while (!rest.empty() && isBlank(rest.back())) rest.remove_suffix(1);
        return std::string(rest);
    }

    std::uint64_t hash64(const Token& token, const char* what) const {
        std::uint64_t v = 0;
        if (token.text.size() != 16 || !parseInteger(token.text, v, 16))
            fail(token.column, "bad " + std::string(what) + " \"" + std::string(token.text) + "\"",
                 "16 hexadecimal digits");
        return v;
    }

    std::uint64_t count(const Token& token, const char* expected) const {
        std::uint64_t v = 0;
        if (!parseInteger(token.text, v) || v > kMaxReplayTicks)
            fail(token.column, "bad number \"" + std::string(token.text) + "\"", expected);
        return v;
    }

    void expectTokens(const std::vector<Token>& tokens, std::size_t n, const std::string& form) const {
        if (tokens.size() < n) fail(static_cast<int>(current_.size()) + 1, "the line ends too soon", form);
        if (tokens.size() > n)
            fail(tokens[n].column, "unexpected \"" + std::string(tokens[n].text) + "\"", form);
    }

    // The version line of a replay written by another game version, for a friendlier message.
    std::string writtenBy() const {
        std::size_t at = text_.find("\ngame ");
        if (at == std::string_view::npos) return "";
        std::size_t end = text_.find('\n', at + 1);
        return " (it was written by polarcade " +
               std::string(
                   text_.substr(at + 6, (end == std::string_view::npos ? text_.size() : end) - at - 6)) +
               ")";
    }

    void parse() {
        replay_.path = path_;
        std::string_view text = text_;
        // A file cut off in the middle of a write ends in an incomplete line: it is not trusted.
        int lines = static_cast<int>(std::count(text.begin(), text.end(), '\n'));
        if (!text.empty() && text.back() != '\n') {
            text = text.substr(0, text.rfind('\n') == std::string_view::npos ? 0 : text.rfind('\n') + 1);
            replay_.cutOffLine = lines + 1;
        }
        bool begun = false;
        std::size_t pos = 0;
        while (pos < text.size()) {
            std::size_t end = text.find('\n', pos);
            current_ = text.substr(pos, end - pos);
            while (!current_.empty() && current_.back() == '\r') current_.remove_suffix(1);
            pos = end + 1;
            ++line_;
            if (line_ == 1) {
                firstLine();
                continue;
            }
            std::vector<Token> tokens = tokenize(current_);
            if (tokens.empty()) continue;
            if (tokens[0].text.front() == '#') {
                if (!begun) replay_.header.comments.emplace_back(current_);
                continue;
            }
            if (replay_.end)
                fail(tokens[0].column, "\"" + std::string(tokens[0].text) + "\" after the end line",
                     "nothing after \"end\" but comments");
            if (!begun) {
                begun = headerLine(tokens);
            } else {
                bodyLine(tokens);
            }
        }
        if (line_ == 0) {
            line_ = 1;
            fail(1,
                 replay_.cutOffLine ? "the file ends in the middle of its first line" : "the file is empty",
                 std::string("a first line \"") + kMagic + " " + std::to_string(kReplayFormat) + "\"");
        }
        if (!begun) {
            ++line_;
            fail(1, "the replay ends before its \"begin\" line (cut off while its header was written?)",
                 "a header (game, scene, seed, …) and then \"begin\"");
        }
        if (sceneLine_ == 0) {
            line_ = beginLine_;
            fail(1, "the header names no scene",
                 "a \"scene NAME\" or \"scene-file PATH\" line before \"begin\"");
        }
    }

    void firstLine() {
        std::vector<Token> tokens = tokenize(current_);
        const std::string expected =
            std::string("a first line \"") + kMagic + " " + std::to_string(kReplayFormat) + "\"";
        if (tokens.empty() || tokens[0].text != kMagic)
            fail(1, "not a Polarcade replay (the first line is not \"" + std::string(kMagic) + " N\")",
                 expected);
        if (tokens.size() < 2)
            fail(static_cast<int>(current_.size()) + 1, "the format number is missing", expected);
        int format = 0;
        if (!parseSignedInt(tokens[1].text, format))
            fail(tokens[1].column, "bad format number \"" + std::string(tokens[1].text) + "\"", expected);
        if (format != kReplayFormat)
            fail(tokens[1].column,
                 "replay format " + std::to_string(format) + " cannot be read by polarcade " + gameVersion() +
                     writtenBy(),
                 "format " + std::to_string(kReplayFormat) + "; play it with the polarcade that recorded it");
        expectTokens(tokens, 2, expected);
    }

    // Returns true on "begin".
    bool headerLine(const std::vector<Token>& tokens) {
        ReplayHeader& h = replay_.header;
        std::string_view key = tokens[0].text;
        auto once = [&](int& seen) {
            if (seen)
                fail(tokens[0].column,
                     "a second \"" + std::string(key) + "\" line (the first is on line " +
                         std::to_string(seen) + ")",
                     "one such line");
            seen = line_;
        };
        auto needValue = [&](const char* form) {
            if (tokens.size() < 2)
                fail(static_cast<int>(current_.size()) + 1, "the line ends too soon", form);
        };
        if (key == "begin") {
            expectTokens(tokens, 1, "\"begin\" alone");
            beginLine_ = line_;
            return true;
        }
        if (key == "game") {
            once(gameLine_);
            needValue("\"game VERSION\"");
            h.gameVersion = restFrom(tokens[1]);
        } else if (key == "scene" || key == "scene-file") {
            if (sceneLine_)
                fail(tokens[0].column,
                     "a second scene (the first is on line " + std::to_string(sceneLine_) + ")",
                     "one \"scene\" or \"scene-file\" line");
            sceneLine_ = line_;
            h.sceneLine = line_;
            needValue(key == "scene" ? "\"scene LOGICAL-PATH\" (e.g. scenes/cave.json)"
                                     : "\"scene-file PATH\" relative to the replay");
            h.sceneIsFile = key == "scene-file";
            h.scene = restFrom(tokens[1]);
        } else if (key == "seed") {
            once(seedLine_);
            expectTokens(tokens, 2, "\"seed N\"");
            if (!parseInteger(tokens[1].text, h.seed))
                fail(tokens[1].column, "bad seed \"" + std::string(tokens[1].text) + "\"",
                     "a whole number from 0 to 2^64-1");
        } else if (key == "tick-rate") {
            once(tickRateLine_);
            expectTokens(tokens, 2, "\"tick-rate HZ\"");
            if (!parseDouble(tokens[1].text, h.tuning.tickRate) || h.tuning.tickRate < 1 ||
                h.tuning.tickRate > 1000)
                fail(tokens[1].column, "bad tick rate \"" + std::string(tokens[1].text) + "\"",
                     "ticks per second from 1 to 1000");
        } else if (key == "tuning") {
            once(tuningLine_);
            for (std::size_t i = 1; i < tokens.size(); ++i) tuningValue(tokens[i]);
        } else if (key == "mod") {
            needValue("\"mod FOLDER\"");
            h.mods.push_back(restFrom(tokens[1]));
        } else if (key == "asset") {
            if (tokens.size() < 3)
                fail(static_cast<int>(current_.size()) + 1, "the line ends too soon", "\"asset HASH NAME\"");
            h.assets.push_back({restFrom(tokens[2]), hash64(tokens[1], "file hash"), line_});
        } else if (key == "screenshot") {
            needValue("\"screenshot TICK:FILE.png\"");
            std::string value = restFrom(tokens[1]);
            std::size_t colon = value.find(':');
            std::uint64_t tick = 0;
            if (colon == std::string::npos || colon + 1 >= value.size() ||
                !parseInteger(std::string_view(value).substr(0, colon), tick) || tick == 0)
                fail(tokens[1].column, "bad screenshot \"" + value + "\"",
                     "TICK:FILE.png with TICK ≥ 1, e.g. 600:shot.png");
            h.screenshots.push_back({tick, value.substr(colon + 1), line_});
        } else {
            fail(tokens[0].column, "unknown header line \"" + std::string(key) + "\"",
                 "one of game, scene, scene-file, seed, tick-rate, tuning, mod, asset, screenshot, begin");
        }
        return false;
    }

    void tuningValue(const Token& token) {
        std::size_t eq = token.text.find('=');
        std::string_view name = token.text.substr(0, eq);
        const TuningField* field = nullptr;
        for (const TuningField& f : kTuningFields)
            if (name == f.name) field = &f;
        if (!field) {
            std::string names;
            for (const TuningField& f : kTuningFields)
                names += (names.empty() ? "" : ", ") + std::string(f.name);
            fail(token.column, "unknown tuning value \"" + std::string(name) + "\"",
                 "NAME=VALUE with NAME one of " + names);
        }
        std::string_view value =
            eq == std::string_view::npos ? std::string_view() : token.text.substr(eq + 1);
        int column = token.column + static_cast<int>(name.size()) + 1;
        // Every tuning value is a rate, speed, time, chance or count: none is negative, and bounds
        // keep a hand-edited file from making the game loop forever (a new life every 0 points).
        bool ok = false;
        if (field->real) {
            double& v = replay_.header.tuning.*field->real;
            ok = parseDouble(value, v) && v >= 0 && v <= kMaxTuningValue;
        } else {
            int& v = replay_.header.tuning.*field->whole;
            int least = field->whole == &Tuning::extraLifeEvery ? 1 : 0;
            ok = parseSignedInt(value, v) && v >= least && v <= kMaxTuningValue;
        }
        if (!ok)
            fail(column, "bad value \"" + std::string(value) + "\" for " + std::string(name),
                 field->real
                     ? "a number from 0 to 1000000"
                     : (field->whole == &Tuning::extraLifeEvery ? "a whole number from 1 to 1000000"
                                                                : "a whole number from 0 to 1000000"));
    }

    void bodyLine(const std::vector<Token>& tokens) {
        std::string_view key = tokens[0].text;
        std::uint64_t ticks = replay_.actions.size();
        if (key != "objects") expectObjects_ = false;
        if (key == "in") {
            if (tokens.size() < 2)
                fail(static_cast<int>(current_.size()) + 1, "no actions on the line", kActionsExpected);
            for (std::size_t i = 1; i < tokens.size(); ++i) inputRun(tokens[i]);
        } else if (key == "trace") {
            expectTokens(tokens, 2, "\"trace\" and two characters per tick");
            const Token& t = tokens[1];
            if (t.text.size() % 2)
                fail(t.column + static_cast<int>(t.text.size()), "an odd number of trace characters",
                     "two per tick");
            for (std::size_t i = 0; i < t.text.size(); i += 2) {
                const char* a = std::strchr(kTraceAlphabet, t.text[i]);
                const char* b = std::strchr(kTraceAlphabet, t.text[i + 1]);
                if (!a || !b || !t.text[i] || !t.text[i + 1])
                    fail(t.column + static_cast<int>(i) + (a ? 1 : 0), "bad trace character",
                         "letters, digits, '-' and '_'");
                replay_.trace.push_back(
                    static_cast<std::uint16_t>(((a - kTraceAlphabet) << 6) | (b - kTraceAlphabet)));
            }
            if (replay_.trace.size() > ticks)
                fail(t.column,
                     "the trace covers " + std::to_string(replay_.trace.size()) + " ticks but only " +
                         std::to_string(ticks) + " have inputs so far",
                     "a trace line after the \"in\" lines of its ticks");
        } else if (key == "check") {
            checkLine(tokens);
            expectObjects_ = true;
        } else if (key == "objects") {
            if (!expectObjects_)
                fail(tokens[0].column, "an objects line that does not follow a check line",
                     "\"check …\" just before it");
            expectObjects_ = false;
            std::vector<ObjectDigest>& objects = replay_.checkpoints.back().objects;
            for (std::size_t i = 1; i < tokens.size(); ++i) {
                const Token& t = tokens[i];
                std::size_t colon = t.text.find(':');
                ObjectDigest o;
                if (colon == std::string_view::npos || !parseInteger(t.text.substr(0, colon), o.id) ||
                    t.text.size() - colon - 1 != 4 || !parseInteger(t.text.substr(colon + 1), o.digest, 16))
                    fail(t.column, "bad object digest \"" + std::string(t.text) + "\"",
                         "ID:XXXX (an object id and 4 hex digits)");
                if (!objects.empty() && o.id <= objects.back().id)
                    fail(t.column, "object " + std::to_string(o.id) + " is out of order",
                         "objects in creation order (rising ids)");
                objects.push_back(o);
            }
        } else if (key == "end") {
            const char* form = "\"end TICK REASON\"";
            expectTokens(tokens, 3, form);
            std::uint64_t tick = count(tokens[1], "the number of ticks recorded");
            if (tick != ticks)
                fail(tokens[1].column,
                     "the end is at tick " + std::to_string(tick) + " but the inputs cover " +
                         std::to_string(ticks) + " ticks",
                     "the tick count of the inputs");
            replay_.end = ReplayEnd{tick, std::string(tokens[2].text), line_};
        } else {
            fail(tokens[0].column, "unknown line \"" + std::string(key) + "\"",
                 "one of in, trace, check, objects, end");
        }
    }

    void inputRun(const Token& token) {
        std::size_t star = token.text.find('*');
        std::string_view letters = token.text.substr(0, star);
        Actions actions = 0;
        if (letters == ".") {
            actions = 0;
        } else if (letters.empty()) {
            fail(token.column, "a run without actions", kActionsExpected);
        } else {
            for (std::size_t i = 0; i < letters.size(); ++i) {
                Actions bit = 0;
                for (const auto& [letter, b] : kActionLetters)
                    if (letters[i] == letter) bit = b;
                if (!bit || (actions & bit))
                    fail(token.column + static_cast<int>(i),
                         (bit ? "action '" : "unknown action '") + std::string(1, letters[i]) +
                             (bit ? "' twice" : "'"),
                         kActionsExpected);
                actions |= bit;
            }
        }
        std::uint64_t n = 1;
        if (star != std::string_view::npos) {
            Token countToken{token.text.substr(star + 1), token.column + static_cast<int>(star) + 1};
            n = count(countToken, "a run length from 1 up, e.g. LF*12");
            if (n == 0) fail(countToken.column, "a run of 0 ticks", "a run length from 1 up, e.g. LF*12");
        }
        if (replay_.actions.size() + n > kMaxReplayTicks)
            fail(token.column, "the replay is longer than " + std::to_string(kMaxReplayTicks) + " ticks",
                 "a shorter replay");
        replay_.actions.insert(replay_.actions.end(), n, actions);
    }

    void checkLine(const std::vector<Token>& tokens) {
        const char* form = "\"check TICK HASH rng=HASH score=N lives=N wave=N\"";
        if (tokens.size() < 3) fail(static_cast<int>(current_.size()) + 1, "the line ends too soon", form);
        Checkpoint c;
        c.line = line_;
        c.tick = count(tokens[1], "the tick the checkpoint follows");
        std::uint64_t ticks = replay_.actions.size();
        if (c.tick != ticks)
            fail(tokens[1].column,
                 "a checkpoint after tick " + std::to_string(c.tick) + " where the inputs so far cover " +
                     std::to_string(ticks) + " ticks",
                 "the tick count of the inputs before it");
        if (c.tick == 0)
            fail(tokens[1].column, "a checkpoint before the first tick", "checkpoints after ticks 1 and up");
        if (!replay_.checkpoints.empty() && replay_.checkpoints.back().tick == c.tick)
            fail(tokens[1].column, "a second checkpoint after tick " + std::to_string(c.tick),
                 "one per tick");
        c.hash = hash64(tokens[2], "state hash");
        bool rng = false, score = false, lives = false, wave = false;
        for (std::size_t i = 3; i < tokens.size(); ++i) {
            const Token& t = tokens[i];
            std::size_t eq = t.text.find('=');
            std::string_view name = t.text.substr(0, eq);
            Token value{eq == std::string_view::npos ? std::string_view() : t.text.substr(eq + 1),
                        t.column + static_cast<int>(name.size()) + 1};
            auto integer = [&](int& out, bool& seen) {
                if (seen) fail(t.column, "\"" + std::string(name) + "\" twice", form);
                seen = true;
                if (!parseSignedInt(value.text, out))
                    fail(value.column, "bad " + std::string(name), "a whole number");
            };
            if (name == "rng") {
                if (rng) fail(t.column, "\"rng\" twice", form);
                rng = true;
                c.rng = hash64(value, "rng state");
            } else if (name == "score") {
                integer(c.score, score);
            } else if (name == "lives") {
                integer(c.lives, lives);
            } else if (name == "wave") {
                integer(c.wave, wave);
            } else {
                fail(t.column, "unknown checkpoint value \"" + std::string(name) + "\"", form);
            }
        }
        if (!rng || !score || !lives || !wave)
            fail(static_cast<int>(current_.size()) + 1,
                 std::string("the checkpoint lacks ") + (!rng     ? "rng"
                                                         : !score ? "score"
                                                         : !lives ? "lives"
                                                                  : "wave"),
                 form);
        replay_.checkpoints.push_back(std::move(c));
    }

    std::string path_;
    std::string_view text_;
    std::string_view current_;
    int line_ = 0;
    int gameLine_ = 0, sceneLine_ = 0, seedLine_ = 0, tickRateLine_ = 0, tuningLine_ = 0, beginLine_ = 0;
    bool expectObjects_ = false;
    Replay replay_;
};

// ---- desync reports ---------------------------------------------------------------------------

std::string label(const Game& game, ObjectId id) {
    const GameObject* object = game.world().find(id);
    std::string out = "#" + std::to_string(id);
    if (!object) return out;
    Kind kind = game.kindOf(id);
    out += " " + object->name + " (" + kindName(kind);
    if (kind == Kind::Rock) out += ", size " + std::to_string(game.rockSize(id));
    return out + ")";
}

std::string joinList(const std::vector<std::string>& items) {
    constexpr std::size_t kShown = 12;
    std::string out;
    for (std::size_t i = 0; i < items.size() && i < kShown; ++i) out += (i ? ", " : "") + items[i];
    if (items.size() > kShown) out += " and " + std::to_string(items.size() - kShown) + " more";
    return out;
}

std::vector<std::string> differences(const Checkpoint& expected, const Checkpoint& actual, const Game& game,
                                     bool explainHidden) {
    std::vector<std::string> out;
    auto counter = [&](const char* name, long long e, long long a) {
        if (e != a)
            out.push_back(std::string(name) + ": expected " + std::to_string(e) + ", actual " +
                          std::to_string(a));
    };
    counter("score", expected.score, actual.score);
    counter("lives", expected.lives, actual.lives);
    counter("wave", expected.wave, actual.wave);
    if (expected.rng != actual.rng)
        out.push_back("rng state: expected " + hex64(expected.rng) + ", actual " + hex64(actual.rng));
    std::vector<std::string> differ, onlyRecorded, onlyHere;
    std::size_t i = 0, j = 0;
    const auto& e = expected.objects;
    const auto& a = actual.objects;
    while (i < e.size() || j < a.size()) {
        if (j == a.size() || (i < e.size() && e[i].id < a[j].id)) {
            onlyRecorded.push_back("#" + std::to_string(e[i++].id));
        } else if (i == e.size() || a[j].id < e[i].id) {
            onlyHere.push_back(label(game, a[j++].id));
        } else {
            if (e[i].digest != a[j].digest) differ.push_back(label(game, a[j].id));
            ++i, ++j;
        }
    }
    if (!differ.empty()) out.push_back("objects that differ: " + joinList(differ));
    if (!onlyRecorded.empty()) out.push_back("objects only in the recording: " + joinList(onlyRecorded));
    if (!onlyHere.empty()) out.push_back("objects only in this run: " + joinList(onlyHere));
    if (out.empty() && expected.hash != actual.hash && explainHidden)
        out.push_back(
            "no object or counter differs: the difference is in the game's timers or bookkeeping "
            "(fire cooldown, respawn, wave and comet timers, bullet and pickup lives)");
    return out;
}

// ---- files ------------------------------------------------------------------------------------

std::optional<Error> writeFailure(const std::string& path, const std::string& what) {
    return Error{path, 0, 0, what, "a writable folder with free space"};
}

}  // namespace

const char* gameVersion() {
    return POLAR_GAME_VERSION;
}

Result<Replay> parseReplay(const std::string& path, std::string_view text) {
    return Parser(path, text).run();
}

Result<Replay> readReplay(const std::string& path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
        return Error{path, 0, 0, "no such replay file", "the path of a .replay file"};
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in && !in.eof()) return Error{path, 0, 0, "cannot read the file", "a readable replay file"};
    return parseReplay(path, text.str());
}

std::string formatReplay(const Replay& replay) {
    std::string out = headerText(replay.header);
    const std::uint64_t total = replay.actions.size();
    std::span<const Actions> actions(replay.actions);
    std::span<const std::uint16_t> trace(replay.trace);
    std::uint64_t pos = 0;
    std::size_t next = 0;
    // The same pieces the writer makes: a segment every kCheckpointInterval ticks and one at each
    // checkpoint.
    while (pos < total) {
        std::uint64_t checkpoint =
            next < replay.checkpoints.size() ? replay.checkpoints[next].tick : total + 1;
        std::uint64_t to =
            std::min({checkpoint, (pos / kCheckpointInterval + 1) * kCheckpointInterval, total});
        appendInputs(out, actions.subspan(pos, to - pos));
        if (pos < trace.size())
            appendTrace(out, trace.subspan(pos, std::min<std::uint64_t>(to, trace.size()) - pos));
        if (checkpoint == to) appendCheckpoint(out, replay.checkpoints[next++]);
        pos = to;
    }
    if (replay.end) out += "end " + std::to_string(replay.end->tick) + ' ' + replay.end->reason + '\n';
    return out;
}

Checkpoint checkpointOf(const Game& game) {
    Checkpoint c;
    c.tick = game.tickCount();
    c.hash = game.hash();
    c.rng = game.rng().state();
    c.score = game.score();
    c.lives = game.lives();
    c.wave = game.wave();
    c.objects.reserve(game.world().objects().size());
    for (const GameObject& object : game.world().objects())
        c.objects.push_back({object.id, digestOf(game, object)});
    return c;
}

Result<Game> createStampedGame(const Game::Config& config, const AssetFs* assets, const std::string& anchor,
                               std::vector<AssetStamp>& stamps) {
    auto seen = std::make_shared<std::vector<AssetStamp>>();
    Game::Config stamped = config;
    stamped.reader = [inner = config.reader, seen, assets,
                      anchor](const std::string& name) -> std::optional<SourceFile> {
        std::optional<SourceFile> file = inner(name);
        if (file) seen->push_back({nameFor(name, assets, anchor), hashBytes(file->text), 0});
        return file;
    };
    Result<Game> game = Game::create(stamped);
    stamps = *seen;
    return game;
}

ReplayHeader headerFor(const Game& game, const std::string& replayPath, std::vector<std::string> mods,
                       std::vector<AssetStamp> stamps) {
    ReplayHeader h;
    h.sceneIsFile = fs::path(game.scenePath()).is_absolute();
    h.scene = h.sceneIsFile ? nameFor(game.scenePath(), nullptr, replayPath) : game.scenePath();
    h.seed = game.seed();
    h.tuning = game.tuning();
    h.mods = std::move(mods);
    h.assets = std::move(stamps);
    return h;
}

Game::Config configFor(const Replay& replay, const AssetFs& assets) {
    Game::Config config;
    config.scene = replay.header.sceneIsFile
                       ? (folderOf(replay.path) / replay.header.scene).lexically_normal().generic_string()
                       : replay.header.scene;
    config.reader = assets.reader();
    config.seed = replay.header.seed;
    config.tuning = replay.header.tuning;
    return config;
}

std::vector<std::string> replayNotes(const Replay& replay) {
    std::vector<std::string> notes;
    if (replay.header.gameVersion != gameVersion())
        notes.push_back("recorded by polarcade " + replay.header.gameVersion + ", played by " +
                        gameVersion() + ": a change in the game between them can make it differ");
    if (replay.cutOffLine)
        notes.push_back("line " + std::to_string(replay.cutOffLine) +
                        " is incomplete and was ignored (the recording was cut off)");
    if (!replay.end)
        notes.push_back("no end line: the recording was interrupted after tick " +
                        std::to_string(replay.actions.size()) + "; everything up to there is checked");
    return notes;
}

// ---- ReplayWriter -----------------------------------------------------------------------------

ReplayWriter::ReplayWriter(std::string path, std::FILE* file, ReplayWriteFault fault)
    : path_(std::move(path)), partPath_(path_ + ".part"), file_(file), fault_(std::move(fault)) {}

ReplayWriter::~ReplayWriter() {
    if (file_) std::fclose(file_);
}

Result<std::unique_ptr<ReplayWriter>> ReplayWriter::open(const std::string& path, const ReplayHeader& header,
                                                         ReplayWriteFault fault) {
    const std::string part = path + ".part";
    bool injected = fault && fault(ReplayWriteStep::kOpen);
    std::FILE* file = injected ? nullptr : std::fopen(part.c_str(), "wb");
    if (!file)
        return *writeFailure(
            path, "cannot create " + part + ": " + (injected ? kSimulatedFull : std::strerror(errno)));
    std::unique_ptr<ReplayWriter> writer(new ReplayWriter(path, file, std::move(fault)));
    if (auto error = writer->flush(headerText(header))) return *error;
    return writer;
}

std::optional<Error> ReplayWriter::flush(std::string text) {
    if (!file_) return writeFailure(path_, "the recording was already stopped");
    auto stop = [&](const std::string& what) {
        std::fclose(file_);
        file_ = nullptr;
        return writeFailure(path_, what + "; what was recorded before is kept in " + partPath_);
    };
    if (fault_ && fault_(ReplayWriteStep::kFlush)) {
        std::fwrite(text.data(), 1, text.size() / 2, file_);  // a torn write, as a full disk leaves it
        std::fflush(file_);
        return stop(std::string("cannot write the recording: ") + kSimulatedFull);
    }
    if (std::fwrite(text.data(), 1, text.size(), file_) != text.size() || std::fflush(file_) != 0)
        return stop(std::string("cannot write the recording: ") + std::strerror(errno));
    return std::nullopt;
}

std::optional<Error> ReplayWriter::record(Actions actions, const Game& game) {
    if (finished_ || !file_) return std::nullopt;
    actions_.push_back(actions & kAllActions);
    trace_.push_back(traceOf(game.hash()));
    if (game.tickCount() % kCheckpointInterval != 0) return std::nullopt;
    std::string text;
    appendInputs(text, actions_);
    appendTrace(text, trace_);
    appendCheckpoint(text, checkpointOf(game));
    actions_.clear();
    trace_.clear();
    lastCheckpoint_ = game.tickCount();
    return flush(std::move(text));
}

std::optional<Error> ReplayWriter::finish(const Game& game, std::string_view reason) {
    if (finished_) return std::nullopt;
    finished_ = true;
    std::string text;
    if (!actions_.empty()) {
        appendInputs(text, actions_);
        appendTrace(text, trace_);
        appendCheckpoint(text, checkpointOf(game));
    }
    text += "end " + std::to_string(game.tickCount()) + ' ' + std::string(reason) + '\n';
    if (auto error = flush(std::move(text))) return error;
    auto stop = [&](const std::string& what) {
        std::fclose(file_);
        file_ = nullptr;
        return writeFailure(path_, what + "; the recording is kept in " + partPath_);
    };
    if (fault_ && fault_(ReplayWriteStep::kFinish))
        return stop(std::string("cannot finish the file: ") + kSimulatedFull);
#ifdef POLAR_HAVE_FSYNC
    if (::fsync(::fileno(file_)) != 0)
        return stop(std::string("cannot flush the file to the disk: ") + std::strerror(errno));
#endif
    if (std::fclose(file_) != 0) {
        file_ = nullptr;
        return writeFailure(path_, std::string("cannot close the file: ") + std::strerror(errno) +
                                       "; the recording is kept in " + partPath_);
    }
    file_ = nullptr;
    std::error_code ec;
    fs::rename(partPath_, path_, ec);
    if (ec) return writeFailure(path_, "cannot rename " + partPath_ + " into place: " + ec.message());
    syncFolder(fs::path(path_).parent_path());
    return std::nullopt;
}

// ---- GameRecorder -----------------------------------------------------------------------------

GameRecorder::GameRecorder(Options options) : options_(std::move(options)) {
    if (options_.folder.empty()) return;
    for (const std::string& path : recoverInterruptedReplays(options_.folder))
        std::printf("polarcade: an interrupted recording was kept as %s\n", path.c_str());
}

GameRecorder::~GameRecorder() {
    stop(nullptr, "");
}

void GameRecorder::start(const Game& game, const AssetFs& assets) {
    stop(nullptr, "");
    std::vector<std::string> paths;
    if (!options_.recordPath.empty() && !recordPathUsed_) {
        paths.push_back(options_.recordPath);
        recordPathUsed_ = true;
    }
    if (!options_.folder.empty()) {
        std::error_code ec;
        fs::create_directories(options_.folder, ec);
        paths.push_back(newReplayPath(options_.folder));
    }
    Game::Config config;
    config.scene = game.scenePath();
    config.reader = assets.reader();
    config.seed = game.seed();
    config.tuning = game.tuning();
    for (const std::string& path : paths) {
        std::vector<AssetStamp> stamps;
        Result<Game> again = createStampedGame(config, &assets, path, stamps);
        if (!again) {
            std::fprintf(stderr, "polarcade: not recording: %s\n", again.error().message().c_str());
            continue;
        }
        auto writer =
            ReplayWriter::open(path, headerFor(game, path, options_.mods, std::move(stamps)), options_.fault);
        if (!writer) {
            std::fprintf(stderr, "polarcade: not recording: %s\n", writer.error().message().c_str());
            continue;
        }
        writers_.push_back(std::move(*writer));
    }
}

void GameRecorder::record(Actions actions, const Game& game) {
    // Hot reload changed the rules in the middle of the game: a replay could not reproduce it. The
    // recording ends at its last flush (before the edit), as if the game had stopped there.
    if (game.modified() && !writers_.empty()) {
        std::fprintf(stderr,
                     "polarcade: recording stopped at tick %llu: a file was reloaded during the game\n",
                     static_cast<unsigned long long>(game.tickCount()));
        stop(nullptr, "modified");
        return;
    }
    for (auto it = writers_.begin(); it != writers_.end();) {
        if (auto error = (*it)->record(actions, game)) {
            std::fprintf(stderr, "polarcade: recording stopped: %s\n", error->message().c_str());
            it = writers_.erase(it);
        } else {
            ++it;
        }
    }
    if (game.over()) stop(&game, "game-over");
}

void GameRecorder::finish(const Game& game, std::string_view reason) {
    stop(&game, reason);
}

void GameRecorder::stop(const Game* game, std::string_view reason) {
    if (writers_.empty()) return;
    for (auto& writer : writers_) {
        if (!game) continue;  // no final state: the .part file stays, readable up to its last flush
        if (auto error = writer->finish(*game, reason))
            std::fprintf(stderr, "polarcade: replay not saved: %s\n", error->message().c_str());
        else
            std::printf("polarcade: replay saved to %s\n", writer->path().c_str());
    }
    writers_.clear();
    if (!options_.folder.empty()) pruneReplays(options_.folder, options_.keep);
}

std::string newReplayPath(const std::string& folder) {
    std::time_t now = std::time(nullptr);
    std::tm local{};
#if defined(_WIN32)
    localtime_s(&local, &now);
#else
    localtime_r(&now, &local);
#endif
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y-%m-%d_%H-%M-%S", &local);
    fs::path base = fs::path(folder) / stamp;
    std::error_code ec;
    for (int n = 1;; ++n) {
        // A second game in the same second gets "_02": names still sort by age.
        char suffix[16] = "";
        if (n > 1) std::snprintf(suffix, sizeof suffix, "_%02d", n);
        std::string path = base.generic_string() + suffix + ".replay";
        if (!fs::exists(path, ec) && !fs::exists(path + ".part", ec)) return path;
    }
}

std::size_t pruneReplays(const std::string& folder, std::size_t keep) {
    std::vector<fs::path> replays;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(folder, ec))
        if (entry.is_regular_file(ec) && entry.path().extension() == ".replay")
            replays.push_back(entry.path());
    if (replays.size() <= keep) return 0;
    std::sort(replays.begin(), replays.end());
    std::size_t removed = 0;
    for (std::size_t i = 0; i + keep < replays.size(); ++i) removed += fs::remove(replays[i], ec) ? 1 : 0;
    return removed;
}

std::vector<std::string> recoverInterruptedReplays(const std::string& folder) {
    std::vector<std::string> recovered;
    std::error_code ec;
    const auto now = fs::file_time_type::clock::now();
    for (const auto& entry : fs::directory_iterator(folder, ec)) {
        const std::string name = entry.path().filename().string();
        constexpr std::string_view suffix = ".replay.part";
        if (name.size() <= suffix.size() ||
            name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
            continue;
        auto written = entry.last_write_time(ec);
        if (ec || now - written < std::chrono::seconds(10)) continue;  // maybe another running game's
        fs::path target = entry.path();
        target.replace_extension();  // drops ".part"
        if (fs::exists(target, ec)) continue;
        fs::rename(entry.path(), target, ec);
        if (!ec) recovered.push_back(target.generic_string());
    }
    std::sort(recovered.begin(), recovered.end());
    return recovered;
}

// ---- playing back -----------------------------------------------------------------------------

std::string describe(const Desync& d, const std::string& path) {
    std::string out = path;
    if (d.line > 0) out += ":" + std::to_string(d.line) + ":1";
    out += ": desync: ";
    if (d.traced) {
        out += "the game first differs after tick " + std::to_string(d.firstTick);
    } else if (d.traceAgrees) {
        out += "the checkpoint after tick " + std::to_string(d.checkpointTick) +
               " disagrees with the per-tick trace, which matched every tick: the checkpoint line is "
               "damaged or was edited, the game is not at fault";
    } else {
        out += "the game differs at the checkpoint after tick " + std::to_string(d.checkpointTick) +
               " (no per-tick trace: it first differs somewhere in ticks " + std::to_string(d.firstTick) +
               "-" + std::to_string(d.checkpointTick) + ")";
    }
    out += "; expected the recorded game\n";
    if (d.checkpointTick) {
        out += "  checkpoint after tick " + std::to_string(d.checkpointTick) + ": expected state hash " +
               hex64(d.expected) + ", actual " + hex64(d.actual) + "\n";
        if (d.expected == d.actual)
            out += "  (the state differed from tick " + std::to_string(d.firstTick) +
                   " on but is the same again here)\n";
    } else {
        out += "  the replay ends before its next checkpoint, so no objects can be compared\n";
    }
    for (const std::string& line : d.differences) out += "  " + line + "\n";
    return out;
}

Result<ReplayPlayer> ReplayPlayer::start(const Replay& replay, const AssetFs& assets) {
    const ReplayHeader& h = replay.header;
    Game::Config config = configFor(replay, assets);
    std::string mods = h.mods.empty() ? std::string("no mods") : "mods " + joinList(h.mods);
    if (!assets.resolve(config.scene))
        return Error{replay.path, h.sceneLine, 1,
                     "the recorded scene " + h.scene + " is not here (it was recorded with " + mods + ")",
                     h.sceneIsFile ? "the scene file next to the replay, where it was when recorded"
                                   : "that scene in assets/ or a mod folder given with --mod"};
    std::vector<AssetStamp> stamps;
    Result<Game> game = createStampedGame(config, &assets, replay.path, stamps);
    if (!game)
        return Error{replay.path, h.sceneLine, 1, "the recorded game cannot start: " + game.error().message(),
                     "the scene and bounds files it was recorded with (" + mods + ")"};
    if (!h.assets.empty()) {
        for (std::size_t i = 0; i < std::max(stamps.size(), h.assets.size()); ++i) {
            if (i < stamps.size() && i < h.assets.size() && stamps[i].hash == h.assets[i].hash) continue;
            int line = i < h.assets.size() ? h.assets[i].line : h.assets.back().line;
            std::string what =
                i >= h.assets.size()
                    ? "the game now also reads " + stamps[i].name + ", which the recording did not"
                : i >= stamps.size()
                    ? "the recording read " + h.assets[i].name + ", which the game no longer does"
                    : stamps[i].name + " is not the file this replay was recorded with (hash " +
                          hex64(stamps[i].hash) + ", recorded " + hex64(h.assets[i].hash) + ")";
            return Error{
                replay.path, line, 1, what,
                "the same scene and bounds files (it was recorded with " + mods +
                    "); after an intended change, re-record the replay or run polarcade-replay --update"};
        }
    }
    return ReplayPlayer(replay, std::move(*game));
}

std::optional<Desync> ReplayPlayer::step() {
    const Replay& r = *replay_;
    if (done()) return std::nullopt;
    game_.tick(r.actions[game_.tickCount()]);
    const std::uint64_t t = game_.tickCount();
    if (!firstDiffers_ && t <= r.trace.size() && traceOf(game_.hash()) != r.trace[t - 1]) firstDiffers_ = t;
    if (nextCheckpoint_ < r.checkpoints.size() && r.checkpoints[nextCheckpoint_].tick == t) {
        const Checkpoint& expected = r.checkpoints[nextCheckpoint_++];
        Checkpoint actual = checkpointOf(game_);
        if (actual.hash == expected.hash && !firstDiffers_) {
            ++matched_;
            lastMatched_ = t;
            return std::nullopt;
        }
        Desync d;
        d.traced = firstDiffers_.has_value();
        d.traceAgrees = !firstDiffers_ && t <= r.trace.size();
        d.firstTick = firstDiffers_.value_or(d.traceAgrees ? t : lastMatched_ + 1);
        d.checkpointTick = t;
        d.line = expected.line;
        d.expected = expected.hash;
        d.actual = actual.hash;
        d.differences = differences(expected, actual, game_, !d.traceAgrees);
        return d;
    }
    if (done() && firstDiffers_) {
        Desync d;
        d.traced = true;
        d.firstTick = *firstDiffers_;
        return d;
    }
    return std::nullopt;
}

Result<Verification> verifyReplay(const Replay& replay, const AssetFs& assets) {
    Result<ReplayPlayer> player = ReplayPlayer::start(replay, assets);
    if (!player) return player.error();
    Verification v;
    while (!player->done()) {
        std::optional<Desync> desync = player->step();
        if (desync) {
            v.desync = std::move(desync);
            break;
        }
    }
    v.ticks = player->game().tickCount();
    v.checkpoints = player->checkpointsMatched();
    return v;
}

}  // namespace polar::game
