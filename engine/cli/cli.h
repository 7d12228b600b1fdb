#pragma once
// The command line every Polarcade executable shares, the game's and the tools' alike: flags and
// options declared on a Command (a program, or one of its subcommands), a bad flag refused with
// one line naming it and exit code 2, --help exiting 0 and --version printing the project's version.
//
// Why a layer of its own? CLI11 does the parsing, and it is a header-only library whose header
// alone takes seconds to compile; behind this one (cli.cpp is the only file that includes it) a
// program's files compile as fast as the rest of the tree. And every numeric flag goes through one
// rule, numbers.h: CLI11 on its own reads -5 into an unsigned value as 18446744073709551611, an
// overflow as the largest value, and 010 as eight.
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "numbers.h"
#include "output_file.h"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace polar::cli {

inline constexpr int kBadInput = 2;

// The types a numeric option holds (bool is a flag).
template <class T>
concept Numeric = std::is_arithmetic_v<T> && !std::is_same_v<T, bool>;

// One flag or option of a Command, refined as it is declared: `sub.option(...).required()`.
class Option {
  public:
    Option& required();
    // The value's name in --help (by default TEXT, INT, UINT or FLOAT): "FILE", "N", "TICK:FILE.png".
    Option& typeName(const std::string& name);
    // --help shows the value the option starts with.
    Option& showDefault();
    // A list option reads "1,2,4" as three values.
    Option& delimiter(char separator);
    // A list option takes one value after each use, so the words after it stay positionals.
    Option& oneValueEach();
    // Given only together with `other`.
    Option& needs(const Option& other);
    // Never given together with `other`.
    Option& excludes(const Option& other);
    // Each value names a folder that exists.
    Option& existingFolder();
    // Each value is one of `choices`.
    Option& oneOf(const std::vector<std::string>& choices);
    // The value (FILE in --help) is a file to write, refused as the command line is read when it
    // cannot be (output_file.h): a run never ends unable to save what it made.
    Option& outputFile();
    // Each value checked by `problem` (what is wrong with it, or "" when it is fine); `label` is
    // shown after the type in --help.
    Option& check(std::function<std::string(const std::string&)> problem, const std::string& label = "");
    // How many times it was given on the command line.
    std::size_t count() const;
    bool given() const { return count() > 0; }

  private:
    friend class Command;
    Option(CLI::Option* option, std::string startText) : option_(option), startText_(std::move(startText)) {}
    CLI::Option* option_;
    std::string startText_;  // a number's starting value as --help shows it; "" for text
};

// A program's command line, or one subcommand of it.
class Command {
  public:
    // The program `name`, which --help describes with `description`.
    Command(const std::string& description, const std::string& name);
    ~Command();
    Command(const Command&) = delete;
    Command& operator=(const Command&) = delete;

    // A subcommand, "polarcade-bench scale"; it lives as long as this Command.
    Command& subcommand(const std::string& name, const std::string& description);
    // Exactly one subcommand must be named.
    void requireSubcommand();
    // Text --help prints after the options.
    void footer(const std::string& text);

    // A flag without a value: "-q,--quiet"; "!--no-time-goal" sets `value` to false.
    Option flag(const std::string& names, bool& value, const std::string& description);
    // An option with a text value, or a positional when `names` has no dash ("file").
    Option option(const std::string& names, std::string& value, const std::string& description);
    // An option or positional that takes several values (and may be repeated).
    Option option(const std::string& names, std::vector<std::string>& values, const std::string& description);
    // A numeric option: anything `range` does not hold is refused with the range in words.
    template <Numeric Number>
    Option option(const std::string& names, Number& value, const std::string& description,
                  std::type_identity_t<Range<Number>> range = {});
    // A numeric option that takes several values, each within `range`.
    template <Numeric Number>
    Option option(const std::string& names, std::vector<Number>& values, const std::string& description,
                  std::type_identity_t<Range<Number>> range = {});

    // Whether this subcommand was named on the command line.
    bool parsed() const;
    // How many times the option `name` ("--seed") was given.
    std::size_t count(const std::string& name) const;

    // Reads argv into the options, with --version added. Returns -1 to go on, otherwise the exit
    // code to return at once (0 after --help or --version, kBadInput after one line on stderr).
    int parse(int argc, char** argv);

  private:
    // What a numeric option needs from its type, erased so that only cli.cpp sees CLI11.
    struct NumberSpec {
        std::string typeWord;    // INT, UINT, FLOAT
        std::string rangeLabel;  // "INT in [1 - 99]", or "" for the whole type
        std::string startText;   // the starting value as --help shows it
        std::function<std::string(const std::string&)> problem;
        std::function<void(const std::vector<std::string>&)> store;  // after a parse that read it
    };
    template <Numeric Number>
    static NumberSpec numberSpec(const Range<Number>& range);
    static std::string typeWord(bool integral, bool isSigned);
    static std::string rangeLabel(const std::string& typeWord, const std::string& low,
                                  const std::string& high, bool lowOpen, bool lowUnbounded,
                                  bool highUnbounded);
    Option numberOption(const std::string& names, const std::string& description, bool list, NumberSpec spec);

    explicit Command(CLI::App* app);
    void storeNumbers();

    std::unique_ptr<CLI::App> owned_;  // the program's; a subcommand's belongs to its parent
    CLI::App* app_;
    std::vector<std::unique_ptr<Command>> subcommands_;
    struct Pending;
    std::vector<std::unique_ptr<Pending>> numbers_;  // numeric options, read as text, stored after parse
};

template <Numeric Number>
Command::NumberSpec Command::numberSpec(const Range<Number>& range) {
    NumberSpec spec;
    spec.typeWord = typeWord(std::is_integral_v<Number>, std::is_signed_v<Number>);
    spec.rangeLabel = rangeLabel(spec.typeWord, numberText(range.low), numberText(range.high), range.lowOpen,
                                 range.low == std::numeric_limits<Number>::lowest(),
                                 range.high == std::numeric_limits<Number>::max());
    spec.problem = [range](const std::string& text) {
        std::string problem;
        parseNumber(text, range, problem);
        return problem;
    };
    return spec;
}

template <Numeric Number>
Option Command::option(const std::string& names, Number& value, const std::string& description,
                       std::type_identity_t<Range<Number>> range) {
    NumberSpec spec = numberSpec(range);
    spec.startText = numberText(value);
    spec.store = [&value, range](const std::vector<std::string>& texts) {
        std::string problem;
        if (!texts.empty()) value = parseNumber(texts.back(), range, problem).value_or(value);
    };
    return numberOption(names, description, false, std::move(spec));
}

template <Numeric Number>
Option Command::option(const std::string& names, std::vector<Number>& values, const std::string& description,
                       std::type_identity_t<Range<Number>> range) {
    NumberSpec spec = numberSpec(range);
    spec.startText = "[";
    for (std::size_t i = 0; i < values.size(); ++i) spec.startText += (i ? "," : "") + numberText(values[i]);
    spec.startText += "]";
    spec.store = [&values, range](const std::vector<std::string>& texts) {
        std::string problem;
        values.clear();
        for (const std::string& text : texts)
            if (std::optional<Number> number = parseNumber(text, range, problem)) values.push_back(*number);
    };
    return numberOption(names, description, true, std::move(spec));
}

}  // namespace polar::cli
