#include "polar/json_writer.h"

#include <cassert>
#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace polar {

// The open objects and arrays, innermost last, each with the key it will have in its parent; the
// finished document once the outermost closes. nlohmann-json keeps the member order and writes.
struct JsonWriter::Stack {
    struct Open {
        nlohmann::ordered_json value;
        std::string keyInParent;
    };
    int indent = -1;
    std::vector<Open> open;
    std::optional<std::string> key;  // named, its value not yet written
    std::optional<nlohmann::ordered_json> done;

    // Places a finished value where the writer stands.
    void place(nlohmann::ordered_json v) {
        if (open.empty()) {
            assert(!done && "JsonWriter: a second top-level value");
            done = std::move(v);
            return;
        }
        nlohmann::ordered_json& parent = open.back().value;
        if (parent.is_array()) {
            assert(!key && "JsonWriter: a key inside an array");
            parent.push_back(std::move(v));
            return;
        }
        assert(key && "JsonWriter: a value in an object without a key");
        assert(!parent.contains(*key) && "JsonWriter: the same key twice in one object");
        parent[*key] = std::move(v);
        key.reset();
    }

    void begin(nlohmann::ordered_json empty) {
        assert(open.empty() || open.back().value.is_array() || key);
        std::string name = key.value_or("");
        key.reset();
        open.push_back(Open{std::move(empty), std::move(name)});
    }

    void end([[maybe_unused]] bool object) {
        assert(!open.empty() && open.back().value.is_object() == object && !key);
        Open last = std::move(open.back());
        open.pop_back();
        if (!open.empty() && open.back().value.is_object()) key = std::move(last.keyInParent);
        place(std::move(last.value));
    }
};

JsonWriter::JsonWriter(int indent) : stack_(std::make_unique<Stack>()) {
    stack_->indent = indent;
}
JsonWriter::JsonWriter(JsonWriter&&) noexcept = default;
JsonWriter& JsonWriter::operator=(JsonWriter&&) noexcept = default;
JsonWriter::~JsonWriter() = default;

JsonWriter& JsonWriter::beginObject() {
    stack_->begin(nlohmann::ordered_json::object());
    return *this;
}

JsonWriter& JsonWriter::endObject() {
    stack_->end(true);
    return *this;
}

JsonWriter& JsonWriter::beginArray() {
    stack_->begin(nlohmann::ordered_json::array());
    return *this;
}

JsonWriter& JsonWriter::endArray() {
    stack_->end(false);
    return *this;
}

JsonWriter& JsonWriter::key(std::string_view name) {
    assert(!stack_->open.empty() && stack_->open.back().value.is_object() && !stack_->key);
    stack_->key = std::string(name);
    return *this;
}

JsonWriter& JsonWriter::null() {
    stack_->place(nullptr);
    return *this;
}

JsonWriter& JsonWriter::value(bool v) {
    stack_->place(v);
    return *this;
}

JsonWriter& JsonWriter::value(double v) {
    stack_->place(v);
    return *this;
}

JsonWriter& JsonWriter::value(std::string_view v) {
    stack_->place(std::string(v));
    return *this;
}

JsonWriter& JsonWriter::signedValue(std::int64_t v) {
    stack_->place(v);
    return *this;
}

JsonWriter& JsonWriter::unsignedValue(std::uint64_t v) {
    stack_->place(v);
    return *this;
}

std::string JsonWriter::text() const {
    assert(stack_->done && stack_->open.empty() && "JsonWriter: text() before the document is closed");
    if (!stack_->done) return {};
    return stack_->done->dump(stack_->indent, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

std::string jsonNumberText(double v) {
    return nlohmann::json(v).dump();
}

}  // namespace polar
