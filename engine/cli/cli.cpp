// The one file that includes CLI11 (cli.h says why).
#include "cli.h"

#include <CLI/CLI.hpp>
#include <cctype>
#include <cstdio>

#include "output_file.h"
#include "polarcade_version.h"

namespace polar::cli {

// A numeric option as CLI11 holds it: text, checked by the range rule as it is read, and turned
// into the number once the parse has succeeded.
struct Command::Pending {
    CLI::Option* option = nullptr;
    std::string text;                // a single value
    std::vector<std::string> texts;  // a list
    bool list = false;
    std::function<void(const std::vector<std::string>&)> store;
};

namespace {

// Whether `app` or any of its subcommands, at any depth, has the option `name` ("--scale", "-j").
bool knowsOption(CLI::App& app, const std::string& name) {
    if (app.get_option_no_throw(name)) return true;
    for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
        if (knowsOption(*sub, name)) return true;
    return false;
}

// The first argument that looks like an option nothing in `app` has, or "". CLI11 reports a missing
// required argument before an unknown flag, which would blame the wrong thing ("sprite is required"
// for "gen --sprit x.png"); the unknown flag is the real mistake.
std::string unknownOption(CLI::App& app, int argc, char** argv) {
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--") break;
        if (arg.size() < 2 || arg[0] != '-') continue;
        if (std::isdigit(static_cast<unsigned char>(arg[1])) || arg[1] == '.') continue;  // a negative number
        const std::string name = arg[1] == '-' ? arg.substr(0, arg.find('=')) : arg.substr(0, 2);
        if (!knowsOption(app, name)) return name;
    }
    return "";
}

// A CLI11 check from a function that says what is wrong with a value ("" when nothing is).
CLI::Validator validator(std::function<std::string(const std::string&)> problem, const std::string& label) {
    return CLI::Validator([problem = std::move(problem)](std::string& value) { return problem(value); },
                          label);
}

}  // namespace

Option& Option::required() {
    option_->required();
    return *this;
}

Option& Option::typeName(const std::string& name) {
    option_->type_name(name);
    return *this;
}

Option& Option::showDefault() {
    if (startText_.empty())
        option_->capture_default_str();
    else
        option_->default_str(startText_);
    return *this;
}

Option& Option::delimiter(char separator) {
    option_->delimiter(separator);
    return *this;
}

Option& Option::oneValueEach() {
    option_->allow_extra_args(false);
    return *this;
}

Option& Option::needs(const Option& other) {
    option_->needs(other.option_);
    return *this;
}

Option& Option::excludes(const Option& other) {
    option_->excludes(other.option_);
    return *this;
}

Option& Option::existingFolder() {
    option_->check(CLI::ExistingDirectory);
    return *this;
}

Option& Option::oneOf(const std::vector<std::string>& choices) {
    option_->check(CLI::IsMember(choices));
    return *this;
}

Option& Option::outputFile() {
    option_->type_name("FILE");
    return check([](const std::string& path) {
        if (path.empty()) return std::string("expected a file in a writable folder, got nothing");
        const std::string problem = outputFileProblem(path);
        return problem.empty() ? problem : path + ": " + problem + "; expected a file in a writable folder";
    });
}

Option& Option::check(std::function<std::string(const std::string&)> problem, const std::string& label) {
    option_->check(validator(std::move(problem), label));
    return *this;
}

std::size_t Option::count() const {
    return option_->count();
}

Command::Command(const std::string& description, const std::string& name)
    : owned_(std::make_unique<CLI::App>(description, name)), app_(owned_.get()) {}

Command::Command(CLI::App* app) : app_(app) {}

Command::~Command() = default;

Command& Command::subcommand(const std::string& name, const std::string& description) {
    subcommands_.push_back(std::unique_ptr<Command>(new Command(app_->add_subcommand(name, description))));
    return *subcommands_.back();
}

void Command::requireSubcommand() {
    app_->require_subcommand(1);
}

void Command::footer(const std::string& text) {
    app_->footer(text);
}

Option Command::flag(const std::string& names, bool& value, const std::string& description) {
    return Option(app_->add_flag(names, value, description), "");
}

Option Command::option(const std::string& names, std::string& value, const std::string& description) {
    return Option(app_->add_option(names, value, description), "");
}

Option Command::option(const std::string& names, std::vector<std::string>& values,
                       const std::string& description) {
    return Option(app_->add_option(names, values, description), "");
}

std::string Command::typeWord(bool integral, bool isSigned) {
    return !integral ? "FLOAT" : isSigned ? "INT" : "UINT";
}

// As --help shows a range after the type: "INT in [1 - 99]", "FLOAT > 0", "UINT >= 1"; nothing
// for all the type holds.
std::string Command::rangeLabel(const std::string& typeWord, const std::string& low, const std::string& high,
                                bool lowOpen, bool lowUnbounded, bool highUnbounded) {
    if (lowUnbounded && highUnbounded) return "";
    if (highUnbounded) return typeWord + (lowOpen ? " > " : " >= ") + low;
    if (lowUnbounded) return typeWord + " <= " + high;
    return typeWord + " in " + (lowOpen ? "(" : "[") + low + " - " + high + "]";
}

Option Command::numberOption(const std::string& names, const std::string& description, bool list,
                             NumberSpec spec) {
    auto pending = std::make_unique<Pending>();
    pending->list = list;
    pending->store = std::move(spec.store);
    CLI::Option* option = list ? app_->add_option(names, pending->texts, description)
                               : app_->add_option(names, pending->text, description);
    option->type_name(spec.typeWord)->check(validator(std::move(spec.problem), spec.rangeLabel));
    pending->option = option;
    numbers_.push_back(std::move(pending));
    return Option(option, spec.startText);
}

bool Command::parsed() const {
    return app_->parsed();
}

std::size_t Command::count(const std::string& name) const {
    return app_->count(name);
}

void Command::storeNumbers() {
    for (const auto& pending : numbers_)
        if (pending->option->count() > 0)
            pending->store(pending->list ? pending->texts : std::vector<std::string>{pending->text});
    for (const auto& sub : subcommands_) sub->storeNumbers();
}

int Command::parse(int argc, char** argv) {
    CLI::App& app = *app_;
    if (!app.get_option_no_throw("--version"))
        app.set_version_flag("--version", app.get_name() + " " + kPolarcadeVersion,
                             "Print the version and exit");
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        const std::string unknown = unknownOption(app, argc, argv);
        if (!unknown.empty())
            std::fprintf(stderr, "%s: unknown option %s; see %s --help\n", app.get_name().c_str(),
                         unknown.c_str(), app.get_name().c_str());
        else
            std::fprintf(stderr, "%s: %s; see %s --help\n", app.get_name().c_str(), e.what(),
                         app.get_name().c_str());
        return kBadInput;
    }
    storeNumbers();
    return -1;
}

}  // namespace polar::cli
