#pragma once
#include <cassert>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <variant>

namespace polar {

// Bad data from a file or the command line: where it is and what is wrong with it.
struct Error {
    std::string file;  // as the user knows it; empty when there is no file
    int line = 0;      // 1-based; 0 when unknown
    int column = 0;    // 1-based; 0 when unknown
    std::string what;
    std::string expected;

    // "file:line:column: what; expected …", the one-line form every tool prints.
    std::string message() const;
};

// A value or the Error that prevented it.
template <class T>
class Result {
  public:
    Result(T value) : state_(std::move(value)) {}
    Result(Error error) : state_(std::move(error)) {}

    bool ok() const { return std::holds_alternative<T>(state_); }
    explicit operator bool() const { return ok(); }
    T& value() {
        assert(ok());
        return std::get<T>(state_);
    }
    const T& value() const {
        assert(ok());
        return std::get<T>(state_);
    }
    T& operator*() { return value(); }
    const T& operator*() const { return value(); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    const Error& error() const {
        assert(!ok());
        return std::get<Error>(state_);
    }

  private:
    std::variant<T, Error> state_;
};

// A text file as read: the path shown in messages and its contents.
struct SourceFile {
    std::string path;
    std::string text;
};

// Reads a file by its logical path ("scenes/arena.json"): the disk, or an overlay of mod folders.
// Returns nothing when there is no such file.
using FileReader = std::function<std::optional<SourceFile>(const std::string& path)>;

// Reads paths straight from the disk.
FileReader diskReader();

// Lexically joins a path named inside `file` to the folder of `file` ("a/b.json" + "../c" = "a/../c"
// normalised to "c"). An absolute `relative` is returned as it is.
std::string resolveRelative(const std::string& file, const std::string& relative);

}  // namespace polar
