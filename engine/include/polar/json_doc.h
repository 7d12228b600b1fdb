#pragma once
#include <cstddef>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "polar/error.h"
#include "polar/math.h"

namespace polar {

// A JSON file (comments allowed) parsed with nlohmann-json, which remembers where every value and
// every key stands, so a loader can say `file:line:column` about any of them.
//
// Why a second pass over the text? nlohmann-json reports positions for syntax errors only. The file
// is parsed by nlohmann first; then a small scanner walks the now known-valid text once and records
// the offset of each value by its JSON pointer. The scanner also rejects duplicate keys (a modder's
// copy-paste slip that JSON itself lets pass) and nesting deeper than kMaxDepth.
class JsonDoc {
  public:
    static constexpr int kMaxDepth = 64;

    static Result<JsonDoc> parse(SourceFile file);

    JsonDoc(JsonDoc&&) noexcept;
    JsonDoc& operator=(JsonDoc&&) noexcept;
    ~JsonDoc();

    const nlohmann::json& root() const;
    const std::string& path() const { return file_.path; }
    const std::string& text() const { return file_.text; }

    // An error placed at the value named by a JSON pointer ("/objects/2/position"), or at its key.
    Error errorAt(const std::string& pointer, std::string what, std::string expected,
                  bool atKey = false) const;
    // 1-based line and column (in characters) of a byte offset.
    std::pair<int, int> lineColumn(std::size_t offset) const;

  private:
    struct Place {
        std::size_t key = std::string::npos;
        std::size_t value = 0;
    };
    JsonDoc() = default;

    SourceFile file_;
    std::unique_ptr<nlohmann::json> root_;
    std::unordered_map<std::string, Place> places_;
    std::vector<std::size_t> lineStarts_;

    friend struct JsonScanner;
};

// Thrown by JsonNode when the data is not what the loader expects; loaders catch it at their
// boundary and return the Error. It never leaves a loader.
struct LoadFailure {
    Error error;
};

// A read-only cursor on one value of a JsonDoc, with checked accessors for loaders. Every accessor
// that finds the wrong kind of value throws LoadFailure carrying file:line:column.
class JsonNode {
  public:
    JsonNode(const JsonDoc& doc, const nlohmann::json& value, std::string pointer);
    static JsonNode root(const JsonDoc& doc);

    const std::string& pointer() const { return pointer_; }
    const JsonDoc& doc() const { return *doc_; }
    const nlohmann::json& json() const { return *value_; }

    bool isObject() const;
    bool isArray() const;
    bool isString() const;
    bool isNumber() const;

    // Object access. `allowKeys` rejects any key not listed (at that key's position).
    void allowKeys(std::initializer_list<const char*> keys) const;
    bool has(const char* key) const;
    std::optional<JsonNode> find(const char* key) const;
    JsonNode require(const char* key, const char* expected) const;

    // Array access.
    std::size_t size() const;
    JsonNode at(std::size_t index) const;
    std::vector<JsonNode> items(const char* expected) const;  // requires an array

    // Scalars; `expected` describes the value for the message.
    double number(const char* expected) const;  // finite
    int integer(const char* expected) const;
    bool boolean(const char* expected) const;
    std::string string(const char* expected) const;
    Vec2 vec2(const char* expected) const;  // [x, y]

    [[noreturn]] void fail(std::string what, std::string expected) const;
    [[noreturn]] void failAtKey(std::string what, std::string expected) const;
    // A short description of the value's kind for messages: "a string", "an array", …
    std::string kind() const;

  private:
    const JsonDoc* doc_;
    const nlohmann::json* value_;
    std::string pointer_;
};

// Runs a loader body and turns a LoadFailure into an Error result.
template <class T, class Body>
Result<T> catchLoadFailure(Body&& body) {
    try {
        return body();
    } catch (const LoadFailure& failure) {
        return failure.error;
    }
}

}  // namespace polar
