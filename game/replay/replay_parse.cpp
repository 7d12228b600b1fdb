#include "replay/replay_parse.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "replay/double_text.h"
#include "replay/replay_text.h"

namespace polar::game {
namespace {

namespace fs = std::filesystem;
using detail::kActionLetters;
using detail::kMagic;
using detail::kTraceAlphabet;
using detail::kTuningFields;
using detail::TuningField;

constexpr const char* kActionsExpected =
    "a run of actions: letters L (turn left), R (turn right), T (thrust), F (fire) or '.' for none, "
    "then optionally *COUNT (e.g. LF*12)";
constexpr double kMaxTuningValue = 1e6;

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
    return parseFiniteDouble(text, out);
}

// "0.1.0", "12.3", "1.0.0-rc.1": numbers joined by dots, then optionally '-' or '+' and a suffix.
bool isVersion(std::string_view text) {
    std::size_t i = 0;
    for (bool number = true;; number = !number) {
        std::size_t start = i;
        if (number) {
            while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i;
            if (i == start) return false;
        } else if (i < text.size() && text[i] == '.') {
            ++i;
        } else {
            break;
        }
    }
    if (i == text.size()) return true;
    if ((text[i] != '-' && text[i] != '+') || i + 1 == text.size()) return false;
    return std::all_of(text.begin() + static_cast<std::ptrdiff_t>(i) + 1, text.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+';
    });
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
        failAt(line_, column, what, expected);
    }
    [[noreturn]] void failAt(int line, int column, const std::string& what,
                             const std::string& expected) const {
        throw ParseFailure{Error{path_, line, column, what, expected}};
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

    std::uint64_t count(const Token& token, const char* what, const char* expected) const {
        std::uint64_t v = 0;
        if (!parseInteger(token.text, v) || v > kMaxReplayTicks)
            fail(token.column, std::string("bad ") + what + " \"" + std::string(token.text) + "\"", expected);
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
                if (traceAhead_ && tokens[0].text != "check") traceAheadOfInputs();
                bodyLine(tokens);
                lastBody_ = tokens[0].text;
            }
        }
        replay_.lines = line_;
        if (traceAhead_) traceAheadOfInputs();
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
            h.gameLine = line_;
            expectTokens(tokens, 2, "\"game VERSION\"");
            if (!isVersion(tokens[1].text))
                fail(tokens[1].column, "bad game version \"" + std::string(tokens[1].text) + "\"",
                     "numbers joined by dots, e.g. 0.1.0, then optionally -SUFFIX");
            h.gameVersion = std::string(tokens[1].text);
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
            h.seedLine = line_;
            expectTokens(tokens, 2, "\"seed N\"");
            if (!parseInteger(tokens[1].text, h.seed))
                fail(tokens[1].column, "bad seed \"" + std::string(tokens[1].text) + "\"",
                     "a whole number from 0 to 2^64-1");
        } else if (key == "tick-rate") {
            once(tickRateLine_);
            h.tickRateLine = line_;
            expectTokens(tokens, 2, "\"tick-rate HZ\"");
            if (!parseDouble(tokens[1].text, h.tuning.tickRate) || h.tuning.tickRate < 1 ||
                h.tuning.tickRate > 1000)
                fail(tokens[1].column, "bad tick rate \"" + std::string(tokens[1].text) + "\"",
                     "ticks per second from 1 to 1000");
        } else if (key == "tuning") {
            once(tuningLine_);
            h.tuningLine = line_;
            for (std::size_t i = 1; i < tokens.size(); ++i) tuningValue(tokens[i]);
        } else if (key == "rules") {
            once(rulesLine_);
            const std::string expected = "\"rules N\" with N from 2 to " + std::to_string(kRulesVersion);
            expectTokens(tokens, 2, expected);
            // 1 is what a file without the line means, so no writer writes it.
            if (!parseSignedInt(tokens[1].text, h.rules) || h.rules < 2)
                fail(tokens[1].column, "bad rules version \"" + std::string(tokens[1].text) + "\"", expected);
            if (h.rules > kRulesVersion)
                fail(tokens[1].column,
                     "rules " + std::to_string(h.rules) + " are newer than polarcade " + gameVersion() +
                         " knows" + writtenBy(),
                     "rules up to " + std::to_string(kRulesVersion) +
                         "; play it with the polarcade that recorded it, or a newer one");
        } else if (key == "speed") {
            once(speedLine_);
            const std::string expected = "\"speed PERCENT\" from " + std::to_string(kMinGameSpeed) + " to " +
                                         std::to_string(kMaxGameSpeed - 1);
            expectTokens(tokens, 2, expected);
            if (!parseSignedInt(tokens[1].text, h.speed) || h.speed < kMinGameSpeed ||
                h.speed >= kMaxGameSpeed)
                fail(tokens[1].column, "bad game speed \"" + std::string(tokens[1].text) + "\"", expected);
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
                 "one of game, scene, scene-file, seed, tick-rate, tuning, rules, speed, mod, asset, "
                 "screenshot, "
                 "begin");
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
            fail(column, "bad tuning value \"" + std::string(value) + "\" for " + std::string(name),
                 field->real
                     ? "a number from 0 to 1000000"
                     : (field->whole == &Tuning::extraLifeEvery ? "a whole number from 1 to 1000000"
                                                                : "a whole number from 0 to 1000000"));
    }

    void bodyLine(const std::vector<Token>& tokens) {
        std::string_view key = tokens[0].text;
        std::uint64_t ticks = replay_.actions.size();
        if (key != "objects" && expectObjects_)
            fail(tokens[0].column,
                 "\"" + std::string(key) + "\" where the objects line of the checkpoint on line " +
                     std::to_string(replay_.checkpoints.back().line) + " belongs",
                 "\"objects ID:XXXX …\" after every check line");
        if (key == "in") {
            if (tokens.size() < 2)
                fail(static_cast<int>(current_.size()) + 1, "no actions on the line", kActionsExpected);
            lastIn_ = {ticks + 1, line_, tokens[1].column, 0};
            for (std::size_t i = 1; i < tokens.size(); ++i) inputRun(tokens[i]);
        } else if (key == "trace") {
            traceLine(tokens);
        } else if (key == "check") {
            checkLine(tokens);
            expectObjects_ = true;
        } else if (key == "objects") {
            if (!expectObjects_)
                fail(tokens[0].column, "an objects line that does not follow a check line",
                     "\"check …\" just before it");
            expectObjects_ = false;
            Checkpoint& checkpoint = replay_.checkpoints.back();
            checkpoint.objectsLine = line_;
            checkpoint.hasObjects = true;
            std::vector<ObjectDigest>& objects = checkpoint.objects;
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
                checkpoint.objectColumns.push_back(t.column);
            }
        } else if (key == "end") {
            endLine(tokens);
        } else {
            fail(tokens[0].column, "unknown line \"" + std::string(key) + "\"",
                 "one of in, trace, check, objects, end");
        }
    }

    void traceLine(const std::vector<Token>& tokens) {
        expectTokens(tokens, 2, "\"trace\" and two characters per tick");
        const Token& t = tokens[1];
        if (t.text.size() % 2)
            fail(t.column + static_cast<int>(t.text.size()), "an odd number of trace characters",
                 "two per tick");
        replay_.tracePlaces.push_back({replay_.trace.size() + 1, line_, t.column, 2});
        for (std::size_t i = 0; i < t.text.size(); i += 2) {
            const char* a = std::strchr(kTraceAlphabet, t.text[i]);
            const char* b = std::strchr(kTraceAlphabet, t.text[i + 1]);
            if (!a || !b || !t.text[i] || !t.text[i + 1])
                fail(t.column + static_cast<int>(i) + (a ? 1 : 0), "bad trace character",
                     "letters, digits, '-' and '_'");
            replay_.trace.push_back(
                static_cast<std::uint16_t>(((a - kTraceAlphabet) << 6) | (b - kTraceAlphabet)));
        }
        // More trace than inputs: the checkpoint after it, if it comes next, says which line is wrong.
        traceAhead_ = replay_.trace.size() > replay_.actions.size();
        traceColumn_ = t.column;
    }

    // The trace line before this line covers more ticks than the inputs, and no checkpoint follows
    // it to side with the inputs or the trace: the trace line is blamed, as it came second.
    [[noreturn]] void traceAheadOfInputs() const {
        const TickPlace& trace = replay_.tracePlaces.back();
        failAt(trace.line, traceColumn_,
               "the trace covers " + std::to_string(replay_.trace.size()) + " ticks but only " +
                   std::to_string(replay_.actions.size()) + " have inputs so far",
               "a trace line after the \"in\" lines of its ticks");
    }

    void endLine(const std::vector<Token>& tokens) {
        std::string reasons;
        for (const char* reason : kEndReasons) reasons += (reasons.empty() ? "" : ", ") + std::string(reason);
        const std::string form = "\"end TICK REASON\" with REASON one of " + reasons;
        expectTokens(tokens, 3, form);
        const std::uint64_t ticks = replay_.actions.size();
        std::uint64_t tick = count(tokens[1], "end tick", "the number of ticks recorded");
        if (tick != ticks)
            fail(tokens[1].column,
                 "the end is at tick " + std::to_string(tick) + " but the inputs cover " +
                     std::to_string(ticks) + " ticks",
                 "the tick count of the inputs");
        if (!isEndReason(tokens[2].text))
            fail(tokens[2].column, "unknown end reason \"" + std::string(tokens[2].text) + "\"",
                 "one of " + reasons);
        replay_.end = ReplayEnd{tick, std::string(tokens[2].text), line_};
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
            n = count(countToken, "run length", "a run length from 1 up, e.g. LF*12");
            if (n == 0) fail(countToken.column, "a run of 0 ticks", "a run length from 1 up, e.g. LF*12");
        }
        if (replay_.actions.size() + n > kMaxReplayTicks)
            fail(token.column, "the replay is longer than " + std::to_string(kMaxReplayTicks) + " ticks",
                 "a shorter replay");
        replay_.inputPlaces.push_back({replay_.actions.size() + 1, line_, token.column, 0});
        replay_.actions.insert(replay_.actions.end(), n, actions);
    }

    void checkLine(const std::vector<Token>& tokens) {
        const char* form = "\"check TICK HASH rng=HASH score=N lives=N wave=N\"";
        if (tokens.size() < 3) fail(static_cast<int>(current_.size()) + 1, "the line ends too soon", form);
        Checkpoint c;
        c.line = line_;
        c.hasObjects = false;  // until its objects line
        c.columns.tick = tokens[1].column;
        c.tick = count(tokens[1], "checkpoint tick", "the tick the checkpoint follows");
        std::uint64_t ticks = replay_.actions.size();
        // Three lines say how many ticks there are so far: the inputs, the trace line just before
        // and this one. Where two agree, the third is blamed.
        const bool traceBefore = lastBody_ == "trace" && lastIn_.line > 0;
        if (c.tick != ticks && traceBefore && c.tick == replay_.trace.size())
            failAt(lastIn_.line, lastIn_.column,
                   "the inputs on this line run to tick " + std::to_string(ticks) +
                       ", but the trace on line " + std::to_string(replay_.tracePlaces.back().line) +
                       " and the checkpoint on line " + std::to_string(line_) + " end at tick " +
                       std::to_string(c.tick),
                   "runs that add up to the ticks of the trace line after them");
        if (traceAhead_) traceAheadOfInputs();
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
        c.columns.hash = tokens[2].column;
        c.hash = hash64(tokens[2], "checkpoint state hash");
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
                    fail(value.column, "bad checkpoint " + std::string(name), "a whole number");
            };
            if (name == "rng") {
                if (rng) fail(t.column, "\"rng\" twice", form);
                rng = true;
                c.columns.rng = value.column;
                c.rng = hash64(value, "checkpoint rng state");
            } else if (name == "score") {
                c.columns.score = value.column;
                integer(c.score, score);
            } else if (name == "lives") {
                c.columns.lives = value.column;
                integer(c.lives, lives);
            } else if (name == "wave") {
                c.columns.wave = value.column;
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
    int rulesLine_ = 0, speedLine_ = 0;
    bool expectObjects_ = false;
    std::string_view lastBody_;  // the first word of the last line after "begin" (not a comment)
    TickPlace lastIn_;           // the last "in" line: its first tick, line and first run's column
    bool traceAhead_ = false;    // the last trace line covers more ticks than the inputs
    int traceColumn_ = 0;        // the column of the last trace line's characters
    Replay replay_;
};

}  // namespace

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

std::vector<std::string> replayNotes(const Replay& replay) {
    std::vector<std::string> notes;
    if (replay.header.gameVersion != gameVersion())
        notes.push_back(
            "recorded by polarcade " + replay.header.gameVersion +
            (replay.header.gameLine ? " (line " + std::to_string(replay.header.gameLine) + ")" : "") +
            ", played by " + gameVersion() + ": a change in the game between them can make it differ");
    if (replay.cutOffLine)
        notes.push_back("line " + std::to_string(replay.cutOffLine) +
                        " is incomplete and was ignored (the recording was cut off)");
    return notes;
}

std::optional<Error> missingEnd(const Replay& replay) {
    if (replay.end) return std::nullopt;
    return Error{replay.path, replay.cutOffLine ? replay.cutOffLine : replay.lines + 1, 1,
                 "incomplete: the replay has no end line, so the recording was interrupted (or the file cut "
                 "short) after tick " +
                     std::to_string(replay.actions.size()),
                 "\"end TICK REASON\" after the last tick; --allow-incomplete verifies the ticks there are"};
}

}  // namespace polar::game
