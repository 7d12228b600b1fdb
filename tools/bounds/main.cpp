// polarcade-bounds: generate, check and view sprite bound files (.bounds.json).
#include "bounds_tool.h"
#include "cli.h"

int main(int argc, char** argv) {
    using namespace polar::bounds_tool;
    polar::cli::Command app{
        "Tools for sprite bound files (.bounds.json): generate them from a sprite's alpha channel, "
        "check them with the game's own loader, view them over the sprite, edit them in a window.",
        "polarcade-bounds"};
    app.requireSubcommand();
    app.footer(
        "Bound space: one unit per sprite pixel, origin at the sprite's centre, x right, y up, angles in "
        "degrees counter-clockwise from +x.\nSee `polarcade-bounds SUBCOMMAND --help`.");
    GenArgs gen;
    CheckArgs check;
    polar::cli::Command& genCommand = app.subcommand("gen", "Generate bounds from a sprite's alpha channel");
    addGen(genCommand, gen);
    polar::cli::Command& checkCommand =
        app.subcommand("check", "Check bounds (and scene) files with the game's loader");
    addCheck(checkCommand, check);
    ViewArgs view;
    polar::cli::Command& viewCommand =
        app.subcommand("view", "Draw a bounds file over its sprite as the collision rule sees it");
    addView(viewCommand, view);
    EditArgs edit;
    polar::cli::Command& editCommand = app.subcommand(
        "edit", "Edit a sprite's bounds in a window: drag samples, fit, test against a partner");
    addEdit(editCommand, edit);
    if (int code = app.parse(argc, argv); code >= 0) return code;
    if (genCommand.parsed()) return runGen(gen);
    if (checkCommand.parsed()) return runCheck(check);
    if (viewCommand.parsed()) return runView(view);
    if (editCommand.parsed()) return runEdit(edit);
    return polar::cli::kBadInput;
}
