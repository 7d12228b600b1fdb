#pragma once
#include <concepts>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

namespace polar {

// Writes a JSON document in the order it is told, for files and tool output: members stay in the
// order they were added, numbers read back exactly, strings are escaped as JSON requires (bytes that
// are not UTF-8 become U+FFFD). `indent` spaces per level lay it out one value a line (the files the
// game writes use 2); a negative indent gives one compact line.
//
//   JsonWriter w(2);
//   w.beginObject().member("format", 1).key("tags").beginArray().value("a").endArray().endObject();
//   write(w.text());
//
// A value is an array element, the value of the key just named, or the document itself. Misuse (a
// value in an object without a key, a key twice, text() before everything is closed) is a
// programmer mistake and asserts.
class JsonWriter {
  public:
    explicit JsonWriter(int indent = -1);
    JsonWriter(JsonWriter&&) noexcept;
    JsonWriter& operator=(JsonWriter&&) noexcept;
    ~JsonWriter();

    JsonWriter& beginObject();
    JsonWriter& endObject();
    JsonWriter& beginArray();
    JsonWriter& endArray();
    // The key of the next value, inside an object.
    JsonWriter& key(std::string_view name);

    JsonWriter& null();
    JsonWriter& value(bool v);
    JsonWriter& value(double v);  // a non-finite number is written as null
    JsonWriter& value(std::string_view v);
    JsonWriter& value(const char* v) { return value(std::string_view(v)); }
    template <std::integral T>
    JsonWriter& value(T v) {
        if constexpr (std::signed_integral<T>)
            return signedValue(static_cast<std::int64_t>(v));
        else
            return unsignedValue(static_cast<std::uint64_t>(v));
    }
    // key(name).value(v)
    template <class T>
    JsonWriter& member(std::string_view name, const T& v) {
        return key(name).value(v);
    }

    // The document written so far, once every object and array is closed.
    std::string text() const;

  private:
    JsonWriter& signedValue(std::int64_t v);
    JsonWriter& unsignedValue(std::uint64_t v);

    struct Stack;
    std::unique_ptr<Stack> stack_;
};

// A number as JSON text: the shortest that reads back to exactly `v` ("0.1", "2.0", "1e+100").
std::string jsonNumberText(double v);

}  // namespace polar
