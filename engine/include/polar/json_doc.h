#pragma once
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "polar/error.h"
#include "polar/math.h"

namespace polar {

class JsonNode;

// What a JSON value is. Whole numbers are numbers too: JsonNode::isInteger says which ones
// JsonNode::integer reads.
enum class JsonKind { Null, Boolean, Number, String, Array, Object };

// A JSON file (comments allowed), parsed once, that remembers where every value and every key
// stands, so a loader can say `file:line:column` about any of them. Objects keep their members in
// file order.
//
// Why a second pass over the text? The parser reports positions for syntax errors only. So once
// the file has parsed, a small scanner walks the now known-valid text and records the offset of
// each value and key, the members of each object in file order, and each value's JSON pointer
// ("/objects/2/position"). The scanner also rejects duplicate keys (a modder's copy-paste slip that
// JSON itself lets pass) and nesting deeper than kMaxDepth. The parsed tree lives behind the
// document; JsonNode is the way to read it.
class JsonDoc {
  public:
    static constexpr int kMaxDepth = 64;

    static Result<JsonDoc> parse(SourceFile file);

    JsonDoc(JsonDoc&&) noexcept;
    JsonDoc& operator=(JsonDoc&&) noexcept;
    ~JsonDoc();

    // The top-level value. Nodes stay valid while the document lives, also after it is moved.
    JsonNode root() const;
    const std::string& path() const;
    const std::string& text() const;

    // An error placed at the value named by a JSON pointer ("/objects/2/position"), or at its key;
    // at the start of the file when no value has that pointer.
    Error errorAt(const std::string& pointer, std::string what, std::string expected,
                  bool atKey = false) const;
    // 1-based line and column (in characters) of a byte offset.
    std::pair<int, int> lineColumn(std::size_t offset) const;

  private:
    struct Tree;  // the parsed values and their places (engine/src/files/json_doc.cpp)
    JsonDoc();
    std::unique_ptr<Tree> tree_;

    friend class JsonNode;
};

// Thrown by JsonNode when the data is not what the loader expects; loaders catch it at their
// boundary and return the Error. It never leaves a loader.
struct LoadFailure {
    Error error;
};

// A read-only cursor on one value of a JsonDoc, with checked accessors for loaders. Every accessor
// that finds the wrong kind of value throws LoadFailure carrying file:line:column, what was found and
// what `expected` says. A node is two words; copy it freely.
class JsonNode {
  public:
    static JsonNode root(const JsonDoc& doc);

    // The kind, and the same as a message says it: "an object", "a string", "a number", "null", …
    JsonKind kind() const;
    std::string kindName() const;
    bool isNull() const { return kind() == JsonKind::Null; }
    bool isBoolean() const { return kind() == JsonKind::Boolean; }
    bool isNumber() const { return kind() == JsonKind::Number; }
    bool isInteger() const;  // a whole number within ±kMaxInteger
    bool isString() const { return kind() == JsonKind::String; }
    bool isArray() const { return kind() == JsonKind::Array; }
    bool isObject() const { return kind() == JsonKind::Object; }

    // Scalars; `expected` describes the value for the message.
    bool boolean(const char* expected) const;
    double number(const char* expected) const;  // finite
    int integer(const char* expected) const;    // whole, within ±kMaxInteger
    std::string string(const char* expected) const;
    Vec2 vec2(const char* expected) const;  // [x, y]
    static constexpr double kMaxInteger = 1e9;

    // Arrays and objects: the elements of an array, or the members of an object in file order.
    std::size_t size() const;                                   // 0 for anything else
    JsonNode at(std::size_t i) const;                           // i < size()
    std::vector<JsonNode> items(const char* expected) const;    // requires an array
    std::vector<JsonNode> members(const char* expected) const;  // requires an object
    // This value's key in its object ("" for the root and for array elements).
    const std::string& key() const;

    // Object members by key. `allowKeys` rejects the first key in file order that is not listed
    // (at that key's position).
    void allowKeys(std::initializer_list<const char*> keys) const;
    bool has(const char* key) const;
    std::optional<JsonNode> find(const char* key) const;
    JsonNode require(const char* key, const char* expected) const;

    // Where the value is: its JSON pointer ("/objects/2") and its 1-based line and column; an Error
    // placed there (or at its key) without throwing; and the same thrown as LoadFailure.
    const std::string& pointer() const;
    int line() const;
    int column() const;
    Error error(std::string what, std::string expected, bool atKey = false) const;
    [[noreturn]] void fail(std::string what, std::string expected) const;
    [[noreturn]] void failAtKey(std::string what, std::string expected) const;

  private:
    JsonNode(const JsonDoc::Tree& tree, std::uint32_t index) : tree_(&tree), index_(index) {}
    const JsonDoc::Tree* tree_;
    std::uint32_t index_;

    friend class JsonDoc;
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
