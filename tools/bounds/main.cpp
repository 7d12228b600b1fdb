// polarcade-bounds: generate, check and view sprite bound files (.bounds.json).
#include "bounds_tool.h"
#include "cli.h"

int main(int argc, char** argv) {
    using namespace polar::bounds_tool;
    CLI::App app{
        "Tools for sprite bound files (.bounds.json): generate them from a sprite's alpha channel, "
        "check them with the game's own loader, view them over the sprite, edit them in a window.",
        "polarcade-bounds"};
    app.require_subcommand(1);
    app.footer(
        "Bound space: one unit per sprite pixel, origin at the sprite's centre, x right, y up, angles in "
        "degrees counter-clockwise from +x.\nSee `polarcade-bounds SUBCOMMAND --help`.");
    GenArgs gen;
    CheckArgs check;
    CLI::App* genCommand = app.add_subcommand("gen", "Generate bounds from a sprite's alpha channel");
    addGen(*genCommand, gen);
    CLI::App* checkCommand =
        app.add_subcommand("check", "Check bounds (and scene) files with the game's loader");
    addCheck(*checkCommand, check);
    ViewArgs view;
    CLI::App* viewCommand =
        app.add_subcommand("view", "Draw a bounds file over its sprite as the collision rule sees it");
    addView(*viewCommand, view);
    EditArgs edit;
    CLI::App* editCommand = app.add_subcommand(
        "edit", "Edit a sprite's bounds in a window: drag samples, fit, test against a partner");
    addEdit(*editCommand, edit);
    if (int code = polar::cli::parse(app, argc, argv); code >= 0) return code;
    if (genCommand->parsed()) return runGen(gen);
    if (checkCommand->parsed()) return runCheck(check);
    if (viewCommand->parsed()) return runView(view);
    if (editCommand->parsed()) return runEdit(edit);
    return polar::cli::kBadInput;
}
