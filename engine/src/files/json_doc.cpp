#include "polar/json_doc.h"

#include <algorithm>
#include <cassert>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <unordered_map>

namespace polar {
namespace {

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

// Skips whitespace and comments from i; returns the new offset.
std::size_t skipBlank(const std::string& t, std::size_t i) {
    while (i < t.size()) {
        if (isSpace(t[i])) {
            ++i;
        } else if (t[i] == '/' && i + 1 < t.size() && t[i + 1] == '/') {
            while (i < t.size() && t[i] != '\n') ++i;
        } else if (t[i] == '/' && i + 1 < t.size() && t[i + 1] == '*') {
            std::size_t end = t.find("*/", i + 2);
            i = end == std::string::npos ? t.size() : end + 2;
        } else {
            break;
        }
    }
    return i;
}

void appendUtf8(std::string& out, unsigned long cp) {
    if (cp < 0x80) {
        out += static_cast<char>(cp);
    } else if (cp < 0x800) {
        out += static_cast<char>(0xC0 | (cp >> 6));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
        out += static_cast<char>(0xE0 | (cp >> 12));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (cp >> 18));
        out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    }
}

std::string escapePointerToken(const std::string& key) {
    std::string out;
    for (char c : key) {
        if (c == '~')
            out += "~0";
        else if (c == '/')
            out += "~1";
        else
            out += c;
    }
    return out;
}

// Replaces control characters so a message stays on one line.
std::string oneLine(std::string s) {
    for (char& c : s)
        if (static_cast<unsigned char>(c) < 0x20) c = ' ';
    return s;
}

// Control characters a file put into a message (a key written "a\nb") as escapes, so the message
// stays on one line and still says what is there.
std::string escapeControls(const std::string& s) {
    static const char hex[] = "0123456789abcdef";
    std::string out;
    for (char c : s) {
        auto u = static_cast<unsigned char>(c);
        if (u >= 0x20 && u != 0x7f)
            out += c;
        else if (c == '\n')
            out += "\\n";
        else if (c == '\r')
            out += "\\r";
        else if (c == '\t')
            out += "\\t";
        else
            out += std::string("\\x") + hex[u >> 4] + hex[u & 15];
    }
    return out;
}

bool isHighSurrogate(unsigned long cp) {
    return cp >= 0xD800 && cp < 0xDC00;
}
bool isLowSurrogate(unsigned long cp) {
    return cp >= 0xDC00 && cp < 0xE000;
}

// Reads the \u escape whose backslash is at `i` and moves `i` past it: one code point, or two
// escapes when they are a surrogate pair (cp = 0x10000 + (high - 0xD800) * 0x400 + (low - 0xDC00)).
// An unpaired surrogate (a high one not followed by an escaped low one, or a low one alone) gives
// nullopt and says so in `problem`, with `i` just past the offending escapes.
std::optional<unsigned long> readUnicodeEscape(const std::string& t, std::size_t& i, std::string& problem) {
    auto hex4 = [&](unsigned long& cp) {
        if (i + 6 > t.size() || t[i] != '\\' || t[i + 1] != 'u') return false;
        std::string digits = t.substr(i + 2, 4);
        if (digits.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos) return false;
        cp = std::strtoul(digits.c_str(), nullptr, 16);
        i += 6;
        return true;
    };
    std::size_t start = i;
    unsigned long cp = 0;
    if (!hex4(cp)) {
        problem = "a \\u escape without four hex digits";
        i = std::min(start + 2, t.size());
        return std::nullopt;
    }
    std::string first = t.substr(start, 6);
    if (isLowSurrogate(cp)) {
        problem = "an escaped low surrogate " + first + " without a high surrogate before it";
        return std::nullopt;
    }
    if (!isHighSurrogate(cp)) return cp;
    std::size_t second = i;
    unsigned long low = 0;
    if (!hex4(low) || !isLowSurrogate(low)) {
        std::string next = i > second ? t.substr(second, 6) : std::string("no \\u escape");
        problem = "an escaped high surrogate " + first + " followed by " + next + ", not by a low surrogate";
        return std::nullopt;
    }
    return 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
}

const char* const kSurrogatePair =
    "a high surrogate \\uD800-\\uDBFF followed by a low one \\uDC00-\\uDFFF (one character above U+FFFF)";

// The offset and problem of the first unpaired surrogate escape in a string of `t`, for
// nlohmann's parse error, which says only that one is there. Tolerant of anything, like
// findOverflowingNumber below.
std::optional<std::pair<std::size_t, std::string>> findUnpairedSurrogate(const std::string& t) {
    std::size_t i = 0;
    while (i < t.size()) {
        std::size_t next = skipBlank(t, i);
        if (next != i) {
            i = next;
            continue;
        }
        if (t[i++] != '"') continue;
        while (i < t.size() && t[i] != '"') {
            if (t[i] != '\\') {
                ++i;
            } else if (i + 1 < t.size() && t[i + 1] == 'u') {
                std::size_t at = i;
                std::string problem;
                if (!readUnicodeEscape(t, i, problem)) return std::pair{at, problem};
            } else {
                i += 2;
            }
        }
        ++i;
    }
    return std::nullopt;
}

// The offset of the first number in `t` that overflows a double, for nlohmann's out_of_range
// error, which carries no position. Tolerant of anything: it only skips strings and comments.
std::optional<std::size_t> findOverflowingNumber(const std::string& t) {
    std::size_t i = 0;
    while (i < t.size()) {
        std::size_t next = skipBlank(t, i);
        if (next != i) {
            i = next;
            continue;
        }
        char c = t[i];
        if (c == '"') {
            for (++i; i < t.size() && t[i] != '"'; ++i)
                if (t[i] == '\\') ++i;
            ++i;
        } else if (c == '-' || (c >= '0' && c <= '9')) {
            std::size_t start = i;
            while (i < t.size() && (std::isdigit(static_cast<unsigned char>(t[i])) || t[i] == '-' ||
                                    t[i] == '+' || t[i] == '.' || t[i] == 'e' || t[i] == 'E'))
                ++i;
            std::string token = t.substr(start, i - start);
            errno = 0;
            double v = std::strtod(token.c_str(), nullptr);
            if (!std::isfinite(v) || (errno == ERANGE && std::fabs(v) > 1.0)) return start;
        } else {
            ++i;
        }
    }
    return std::nullopt;
}

}  // namespace

// The parsed document: nlohmann-json's tree, and beside it one record per value in file order
// (values[0] is the root) with its place in the text, its JSON pointer and, for an array or an
// object, its elements or members in file order: children[first, first + count).
struct JsonDoc::Tree {
    struct Value {
        JsonKind kind = JsonKind::Null;
        std::size_t keyOffset = std::string::npos;  // npos: not an object member
        std::size_t valueOffset = 0;
        const nlohmann::json* json = nullptr;  // into `root`
        const std::string* pointer = nullptr;  // the key of its entry in `byPointer`
        std::string key;
        std::uint32_t first = 0;
        std::uint32_t count = 0;
    };

    SourceFile file;
    nlohmann::json root;
    std::vector<Value> values;
    std::vector<std::uint32_t> children;
    std::unordered_map<std::string, std::uint32_t> byPointer;  // node-based: keys never move
    std::vector<std::size_t> lineStarts;

    std::uint32_t child(std::uint32_t index, std::size_t k) const {
        return children[values[index].first + k];
    }

    std::pair<int, int> lineColumn(std::size_t offset) const {
        offset = std::min(offset, file.text.size());
        auto it = std::upper_bound(lineStarts.begin(), lineStarts.end(), offset);
        std::size_t line = static_cast<std::size_t>(it - lineStarts.begin());
        std::size_t start = lineStarts[line - 1];
        int column = 1;
        for (std::size_t k = start; k < offset; ++k)
            if ((static_cast<unsigned char>(file.text[k]) & 0xC0) != 0x80) ++column;  // count characters
        return {static_cast<int>(line), column};
    }

    Error errorAtOffset(std::size_t offset, std::string what, std::string expected) const {
        auto [line, column] = lineColumn(offset);
        return Error{file.path, line, column, std::move(what), std::move(expected)};
    }

    // A loader's message about a value (or its key), which may quote what the file holds.
    Error errorAt(std::optional<std::uint32_t> index, const std::string& what, const std::string& expected,
                  bool atKey) const {
        std::size_t offset = 0;
        if (index) {
            const Value& v = values[*index];
            offset = atKey && v.keyOffset != std::string::npos ? v.keyOffset : v.valueOffset;
        }
        return errorAtOffset(offset, escapeControls(what), escapeControls(expected));
    }

    const nlohmann::json& json(std::uint32_t index) const { return *values[index].json; }

    std::optional<std::uint32_t> find(const std::string& pointer) const {
        auto it = byPointer.find(pointer);
        if (it == byPointer.end()) return std::nullopt;
        return it->second;
    }

    struct Scanner;  // fills `values`, `children` and `byPointer` once the text has parsed
};

namespace {

JsonKind kindOf(const nlohmann::json& json) {
    switch (json.type()) {
        case nlohmann::json::value_t::object:
            return JsonKind::Object;
        case nlohmann::json::value_t::array:
            return JsonKind::Array;
        case nlohmann::json::value_t::string:
            return JsonKind::String;
        case nlohmann::json::value_t::boolean:
            return JsonKind::Boolean;
        case nlohmann::json::value_t::number_integer:
        case nlohmann::json::value_t::number_unsigned:
        case nlohmann::json::value_t::number_float:
            return JsonKind::Number;
        default:
            return JsonKind::Null;
    }
}

}  // namespace

// Walks text that nlohmann-json has accepted, beside the tree it made, and records each value: where
// it (and its key) starts, its pointer, and the members of each object in file order.
struct JsonDoc::Tree::Scanner {
    const std::string& t;
    JsonDoc::Tree& tree;
    std::size_t i = 0;
    std::optional<Error> error;
    // The children of the open array or object at each depth, gathered until it closes and then
    // written to tree.children in one piece (so each one's children are contiguous).
    std::vector<std::vector<std::uint32_t>> open =
        std::vector<std::vector<std::uint32_t>>(JsonDoc::kMaxDepth + 2);

    bool close(std::uint32_t index, int depth) {
        std::vector<std::uint32_t>& mine = open[static_cast<std::size_t>(depth)];
        tree.values[index].first = static_cast<std::uint32_t>(tree.children.size());
        tree.values[index].count = static_cast<std::uint32_t>(mine.size());
        tree.children.insert(tree.children.end(), mine.begin(), mine.end());
        return true;
    }

    bool fail(std::size_t at, std::string what, std::string expected) {
        if (!error) error = tree.errorAtOffset(at, std::move(what), std::move(expected));
        return false;
    }

    std::string readString() {
        std::string out;
        ++i;  // opening quote
        while (i < t.size() && t[i] != '"') {
            if (t[i] != '\\') {
                out += t[i++];
                continue;
            }
            if (++i >= t.size()) break;
            char e = t[i++];
            switch (e) {
                case 'b':
                    out += '\b';
                    break;
                case 'f':
                    out += '\f';
                    break;
                case 'n':
                    out += '\n';
                    break;
                case 'r':
                    out += '\r';
                    break;
                case 't':
                    out += '\t';
                    break;
                case 'u': {
                    std::size_t at = i - 2;
                    i = at;
                    std::string problem;
                    std::optional<unsigned long> cp = readUnicodeEscape(t, i, problem);
                    if (!cp) {
                        fail(at, problem, kSurrogatePair);
                        i = t.size();
                        return out;
                    }
                    appendUtf8(out, *cp);
                    break;
                }
                default:
                    out += e;
                    break;  // \" \\ \/
            }
        }
        ++i;  // closing quote
        return out;
    }

    // Records the value at `i`, which nlohmann parsed into `json`, and everything inside it; its
    // record's index goes to `index`.
    bool value(std::string pointer, std::string key, std::size_t keyOffset, const nlohmann::json& json,
               int depth, std::uint32_t& index) {
        i = skipBlank(t, i);
        if (i >= t.size()) return fail(t.size(), "unexpected end of file", "a value");
        if (depth > JsonDoc::kMaxDepth)
            return fail(i, "nesting deeper than " + std::to_string(JsonDoc::kMaxDepth) + " levels",
                        "a flatter document");
        index = static_cast<std::uint32_t>(tree.values.size());
        const std::string& here = tree.byPointer.emplace(std::move(pointer), index).first->first;
        tree.values.push_back(JsonDoc::Tree::Value{kindOf(json), keyOffset, i, &json, &here, std::move(key)});
        std::vector<std::uint32_t>& mine = open[static_cast<std::size_t>(depth)];
        mine.clear();
        char c = t[i];
        // A key given twice keeps its last value in nlohmann, so the text at its first place can be
        // an array or object where the kept value is not; the second place is reported as a
        // duplicate only once it is reached, so stop here with the same words.
        if ((c == '{' && !json.is_object()) || (c == '[' && !json.is_array())) {
            if (keyOffset == std::string::npos)
                return fail(i, "a value under a key given twice (a later value replaced it)",
                            "each key once in an object");
            return fail(keyOffset,
                        "duplicate key \"" + tree.values[index].key + "\" (a later value replaced this one)",
                        "each key once in an object");
        }
        if (c == '{') {
            ++i;
            i = skipBlank(t, i);
            if (i < t.size() && t[i] == '}') return ++i, true;
            while (i < t.size()) {
                i = skipBlank(t, i);
                std::size_t keyAt = i;
                std::string name = readString();
                if (error) return false;
                std::string child = here + "/" + escapePointerToken(name);
                if (tree.byPointer.count(child))
                    return fail(keyAt, "duplicate key " + t.substr(keyAt, i - keyAt),
                                "each key once in an object");
                auto member = json.find(name);
                if (member == json.end())
                    return fail(keyAt, "a key the parser did not keep", "valid JSON (comments allowed)");
                i = skipBlank(t, i) + 1;  // ':'
                std::uint32_t childIndex = 0;
                if (!value(std::move(child), std::move(name), keyAt, *member, depth + 1, childIndex))
                    return false;
                mine.push_back(childIndex);
                i = skipBlank(t, i);
                if (i < t.size() && t[i++] == '}') return close(index, depth);
            }
            return fail(t.size(), "unexpected end of file", "'}'");
        }
        if (c == '[') {
            ++i;
            i = skipBlank(t, i);
            if (i < t.size() && t[i] == ']') return ++i, true;
            for (std::size_t k = 0; i < t.size(); ++k) {
                if (k >= json.size()) return fail(i, "an element the parser did not keep", "valid JSON");
                std::uint32_t childIndex = 0;
                if (!value(here + "/" + std::to_string(k), "", std::string::npos, json[k], depth + 1,
                           childIndex))
                    return false;
                mine.push_back(childIndex);
                i = skipBlank(t, i);
                if (i < t.size() && t[i++] == ']') return close(index, depth);
            }
            return fail(t.size(), "unexpected end of file", "']'");
        }
        if (c == '"') {
            readString();
            return !error;
        }
        while (i < t.size() && !isSpace(t[i]) && t[i] != ',' && t[i] != ']' && t[i] != '}' && t[i] != '/')
            ++i;
        return true;
    }
};

JsonDoc::JsonDoc() : tree_(std::make_unique<Tree>()) {}
JsonDoc::JsonDoc(JsonDoc&&) noexcept = default;
JsonDoc& JsonDoc::operator=(JsonDoc&&) noexcept = default;
JsonDoc::~JsonDoc() = default;

Result<JsonDoc> JsonDoc::parse(SourceFile file) {
    JsonDoc doc;
    Tree& tree = *doc.tree_;
    tree.file = std::move(file);
    const std::string& text = tree.file.text;
    tree.lineStarts.push_back(0);
    for (std::size_t k = 0; k < text.size(); ++k)
        if (text[k] == '\n') tree.lineStarts.push_back(k + 1);
    auto errorAt = [&](std::size_t offset, std::string what, std::string expected) {
        return tree.errorAtOffset(offset, std::move(what), std::move(expected));
    };

    // nlohmann-json takes a NUL byte for the end of the input (and of a // comment), so the rest of
    // the file would be ignored without a word and the position scanner would lose its way.
    if (std::size_t nul = text.find('\0'); nul != std::string::npos)
        return errorAt(nul, "a NUL byte (binary data)", "a text file");
    try {
        tree.root = nlohmann::json::parse(text, nullptr, true, true);
    } catch (const nlohmann::json::parse_error& e) {
        std::string message = e.what();
        std::size_t colon = message.find(": ");
        if (colon != std::string::npos) message = message.substr(colon + 2);
        std::string expected = "valid JSON (comments allowed)";
        std::size_t exp = message.find("; expected ");
        if (exp != std::string::npos) {
            expected = message.substr(exp + 11);
            message = message.substr(0, exp);
        }
        std::size_t at = e.byte > 0 ? e.byte - 1 : 0;
        if (message.find("surrogate") != std::string::npos) {
            if (auto bad = findUnpairedSurrogate(text); bad && bad->first <= at)
                return errorAt(bad->first, oneLine(bad->second), kSurrogatePair);
        }
        return errorAt(at, oneLine(message), oneLine(expected));
    } catch (const nlohmann::json::exception& e) {
        // Number overflow (1e999): nlohmann gives no position, so find the number ourselves.
        return errorAt(findOverflowingNumber(text).value_or(0),
                       "a non-finite number (too large for a double)", "a finite number");
    }

    Tree::Scanner scanner{text, tree, 0, std::nullopt};
    if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) scanner.i = 3;  // nlohmann skips a UTF-8 BOM too
    std::uint32_t root = 0;
    if (!scanner.value("", "", std::string::npos, tree.root, 0, root)) return *scanner.error;
    return doc;
}

JsonNode JsonDoc::root() const {
    return JsonNode(*tree_, 0);
}

const std::string& JsonDoc::path() const {
    return tree_->file.path;
}

const std::string& JsonDoc::text() const {
    return tree_->file.text;
}

std::pair<int, int> JsonDoc::lineColumn(std::size_t offset) const {
    return tree_->lineColumn(offset);
}

Error JsonDoc::errorAt(const std::string& pointer, std::string what, std::string expected, bool atKey) const {
    return tree_->errorAt(tree_->find(pointer), what, expected, atKey);
}

JsonNode JsonNode::root(const JsonDoc& doc) {
    return doc.root();
}

JsonKind JsonNode::kind() const {
    return tree_->values[index_].kind;
}

std::string JsonNode::kindName() const {
    switch (kind()) {
        case JsonKind::Object:
            return "an object";
        case JsonKind::Array:
            return "an array";
        case JsonKind::String:
            return "a string";
        case JsonKind::Boolean:
            return "a boolean";
        case JsonKind::Number:
            return "a number";
        case JsonKind::Null:
            break;
    }
    return "null";
}

bool JsonNode::isInteger() const {
    if (!isNumber()) return false;
    double v = tree_->json(index_).get<double>();
    return v == std::floor(v) && std::fabs(v) <= kMaxInteger;
}

bool JsonNode::boolean(const char* expected) const {
    if (!isBoolean()) fail("found " + kindName(), expected);
    return tree_->json(index_).get<bool>();
}

double JsonNode::number(const char* expected) const {
    if (!isNumber()) fail("found " + kindName(), expected);
    double v = tree_->json(index_).get<double>();
    if (!std::isfinite(v)) fail("a non-finite number", expected);
    return v;
}

int JsonNode::integer(const char* expected) const {
    double v = number(expected);
    if (v != std::floor(v) || std::fabs(v) > kMaxInteger)
        fail("found " + tree_->json(index_).dump(), expected);
    return static_cast<int>(v);
}

std::string JsonNode::string(const char* expected) const {
    if (!isString()) fail("found " + kindName(), expected);
    return tree_->json(index_).get<std::string>();
}

Vec2 JsonNode::vec2(const char* expected) const {
    if (!isArray() || size() != 2)
        fail("found " + (isArray() ? "an array of " + std::to_string(size()) + " items" : kindName()),
             expected);
    return Vec2(at(0).number(expected), at(1).number(expected));
}

std::size_t JsonNode::size() const {
    return tree_->values[index_].count;
}

JsonNode JsonNode::at(std::size_t i) const {
    assert(i < size());
    return JsonNode(*tree_, tree_->child(index_, i));
}

namespace {
// An array's elements or an object's members, in file order.
std::vector<JsonNode> childrenOf(const JsonNode& node) {
    std::vector<JsonNode> out;
    out.reserve(node.size());
    for (std::size_t k = 0; k < node.size(); ++k) out.push_back(node.at(k));
    return out;
}
}  // namespace

std::vector<JsonNode> JsonNode::items(const char* expected) const {
    if (!isArray()) fail("found " + kindName(), expected);
    return childrenOf(*this);
}

std::vector<JsonNode> JsonNode::members(const char* expected) const {
    if (!isObject()) fail("found " + kindName(), expected);
    return childrenOf(*this);
}

const std::string& JsonNode::key() const {
    return tree_->values[index_].key;
}

void JsonNode::allowKeys(std::initializer_list<const char*> keys) const {
    if (!isObject()) fail("found " + kindName(), "an object");
    for (std::size_t m = 0; m < size(); ++m) {
        std::uint32_t child = tree_->child(index_, m);
        const std::string& name = tree_->values[child].key;
        if (std::find_if(keys.begin(), keys.end(), [&](const char* k) { return name == k; }) != keys.end())
            continue;
        std::string list;
        for (const char* k : keys) list += (list.empty() ? "" : ", ") + std::string("\"") + k + "\"";
        JsonNode(*tree_, child).failAtKey("unknown key \"" + name + "\"", "one of " + list);
    }
}

bool JsonNode::has(const char* key) const {
    return find(key).has_value();
}

std::optional<JsonNode> JsonNode::find(const char* key) const {
    if (!isObject()) return std::nullopt;
    std::optional<std::uint32_t> child = tree_->find(pointer() + "/" + escapePointerToken(key));
    if (!child) return std::nullopt;
    return JsonNode(*tree_, *child);
}

JsonNode JsonNode::require(const char* key, const char* expected) const {
    if (!isObject()) fail("found " + kindName(), "an object");
    if (auto node = find(key)) return *node;
    fail(std::string("missing key \"") + key + "\"", expected);
}

const std::string& JsonNode::pointer() const {
    return *tree_->values[index_].pointer;
}

int JsonNode::line() const {
    return tree_->lineColumn(tree_->values[index_].valueOffset).first;
}

int JsonNode::column() const {
    return tree_->lineColumn(tree_->values[index_].valueOffset).second;
}

Error JsonNode::error(std::string what, std::string expected, bool atKey) const {
    return tree_->errorAt(index_, what, expected, atKey);
}

void JsonNode::fail(std::string what, std::string expected) const {
    throw LoadFailure{error(std::move(what), std::move(expected))};
}

void JsonNode::failAtKey(std::string what, std::string expected) const {
    throw LoadFailure{error(std::move(what), std::move(expected), true)};
}

}  // namespace polar
