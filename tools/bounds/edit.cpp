// polarcade-bounds edit: opens the bounds editor (tools/bounds/editor/) on a sprite, in a window or
// headless from a script, and moves events and pictures between it and the window or files.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "bounds_tool.h"
#include "cli.h"
#include "editor/editor.h"
#include "editor/script.h"
#include "files/assets.h"
#include "polar/image_extensions.h"
#include "polar/platform/image_file.h"
#include "polar/platform/png_io.h"
#include "polar/platform/window.h"

namespace polar::bounds_tool {
namespace {

namespace fs = std::filesystem;
using editor::Editor;
using editor::EditorSetup;

int fail(const Error& error) {
    std::fprintf(stderr, "%s\n", error.message().c_str());
    return cli::kBadInput;
}

// Every sprite of the game's assets with valid bounds, as a partner to test against; none when
// there is no asset folder (the sprite itself is still a partner).
std::vector<editor::Partner> assetPartners() {
    std::vector<editor::Partner> partners;
    Result<std::string> root = game::AssetFs::findRoot();
    if (!root) return partners;
    game::AssetFs assets(*root);
    for (const std::string& logical : assets.list("sprites")) {
        const std::string_view stem = withoutImageExtension(logical);
        if (stem.empty()) continue;
        const std::string boundsLogical = std::string(stem) + ".bounds.json";
        Result<BoundsPtr> bounds = loadBounds(boundsLogical, assets.reader());
        std::optional<std::string> file = assets.resolve(logical);
        if (!bounds || !file) continue;
        Result<render::Image> image = render::loadImage(*file);
        Result<RgbaImage> pixels = loadRgbaImage(*file);
        if (!image || !pixels) continue;
        partners.push_back({logical, std::move(*image),
                            std::make_shared<const OpaquePixels>(alphaMaskOf(*pixels)), *bounds});
    }
    return partners;
}

std::optional<Error> writePicture(const Editor& editor, const std::string& path) {
    render::Canvas canvas(Editor::kWidth, Editor::kHeight);
    editor.draw(canvas);
    return render::savePng(canvas, path);
}

// The file F12 writes: NAME-edit-K.png in the working folder, K the first number not yet taken.
std::string screenshotName(const std::string& sprite) {
    const std::string stem = fs::path(sprite).stem().string();
    for (int k = 1;; ++k) {
        std::string name = stem + "-edit-" + std::to_string(k) + ".png";
        std::error_code ec;
        if (!fs::exists(name, ec)) return name;
    }
}

int runHeadless(Editor& editor, const EditArgs& args) {
    if (!args.script.empty()) {
        std::optional<SourceFile> file = diskReader()(args.script);
        if (!file) return fail(Error{args.script, 0, 0, "cannot read the script", "a readable script file"});
        Result<std::vector<editor::ScriptStep>> steps = editor::parseScript(*file);
        if (!steps) return fail(steps.error());
        for (const editor::ScriptStep& step : *steps) {
            if (const auto* shot = std::get_if<editor::Screenshot>(&step)) {
                if (std::optional<Error> error = writePicture(editor, shot->path)) return fail(*error);
                std::printf("wrote %s\n", shot->path.c_str());
                continue;
            }
            editor.handle(std::get<platform::Event>(step));
            if (editor.takeScreenshotRequest()) {
                const std::string path = screenshotName(args.sprite);
                if (std::optional<Error> error = writePicture(editor, path)) return fail(*error);
                std::printf("wrote %s\n", path.c_str());
            }
            if (editor.finished()) break;
        }
    }
    if (!args.screenshot.empty()) {
        if (std::optional<Error> error = writePicture(editor, args.screenshot)) return fail(*error);
        std::printf("wrote %s\n", args.screenshot.c_str());
    }
    return 0;
}

int runWindow(Editor& editor, const EditArgs& args) {
    if (std::optional<Error> problem = platform::Window::displayProblem())
        return fail(Error{"", 0, 0, "cannot open the editor's window: " + problem->what,
                          "a display (X11 or Wayland), or --script and --screenshot to run without one"});
    platform::WindowSettings settings;
    settings.title = editor.title();
    settings.canvasWidth = Editor::kWidth;
    settings.canvasHeight = Editor::kHeight;
    Result<std::unique_ptr<platform::Window>> opened = platform::Window::open(settings);
    if (!opened) return fail(opened.error());
    platform::Window& window = **opened;
    render::Canvas canvas(Editor::kWidth, Editor::kHeight);
    bool redraw = true;
    std::string title = editor.title();
    while (!editor.finished()) {
        while (std::optional<platform::Event> event = window.pollEvent()) {
            editor.handle(*event);
            redraw = true;
        }
        if (editor.takeScreenshotRequest()) {
            const std::string path = screenshotName(args.sprite);
            std::optional<Error> error = writePicture(editor, path);
            editor.say(error ? "screenshot not written: " + error->message() : "wrote screenshot " + path,
                       error.has_value());
        }
        if (editor.title() != title) {
            title = editor.title();
            window.setTitle(title);
        }
        if (redraw) {
            editor.draw(canvas);
            window.present(canvas);
            redraw = false;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(8));
    }
    return 0;
}

}  // namespace

void addEdit(cli::Command& app, EditArgs& args) {
    std::string keys;
    for (const std::string& line : editor::editorKeys()) keys += "\n  " + line;
    app.footer(
        "Edit a sprite's bounds in a window drawn by the game's renderer: the outline exactly as the "
        "collision "
        "rule sees it, in view's colours, with spokes, centres and the angle convention. The panel shows the "
        "fit "
        "as gen prints it (worst and mean slack, worst miss) and check's warnings, live. A partner sprite "
        "from the "
        "assets (or the same one) shows hit or miss at any accuracy level beside the pixel truth, with the "
        "overlapping opaque pixels highlighted. With no bounds file (or a broken one, whose message is shown "
        "and "
        "printed) the editor starts from gen's fit; the file is written only by Ctrl+S, atomically, as gen "
        "writes "
        "it, so a game with hot reload picks it up. With --script the editor runs headless: it replays the "
        "script's events, writes its screenshots and exits."
        "\n\nKeys:" +
        keys +
        "\n\nScript commands, one a line ('#' starts a comment; X Y in pixels of the 960x600 canvas):"
        "\n  move X Y; press|release|click left|middle|right X Y; drag BUTTON X1 Y1 X2 Y2 [MOVES];"
        "\n  wheel DY; key [ctrl+][shift+][alt+]KEY (e.g. key ctrl+z, key delete); down KEY; up KEY;"
        "\n  quit (the window's close button); screenshot FILE.png (relative to the script)");
    app.option("sprite", args.sprite,
               "Sprite image (PNG, or any format polarcade reads: GIF, WebP, TGA, BMP and more)")
        .required();
    app.option("bounds", args.bounds,
               "The bounds file to edit (default: NAME.bounds.json beside the sprite)");
    app.option("--radii", args.radii, "Radii for gen's fit when there is no file or it is broken (1..16)",
               {1, 16});
    app.flag("--container", args.container, "Container bounds (as gen --container)");
    app.option("--threshold", args.threshold, "Alpha above which a pixel is opaque (0..254)", {0, 254});
    app.option("--script", args.script, "Run headless: replay this script's events, then exit");
    app.option("--screenshot", args.screenshot,
               "Headless: write the editor's picture here at the end (.png)");
}

int runEdit(const EditArgs& args) {
    Result<RgbaImage> pixels = loadRgbaImage(args.sprite);
    if (!pixels) return fail(pixels.error());
    Result<render::Image> image = render::loadImage(args.sprite);
    if (!image) return fail(image.error());

    EditorSetup setup;
    setup.boundsPath = args.bounds.empty() ? defaultBoundsPath(args.sprite) : args.bounds;
    setup.image = std::move(*image);
    setup.sprite.mask = alphaMaskOf(*pixels);
    setup.sprite.threshold = static_cast<std::uint8_t>(args.threshold);
    setup.sprite.container = args.container;
    setup.sprite.opaque = PixelSet::opaque(setup.sprite.mask, setup.sprite.threshold);

    std::error_code ec;
    if (fs::exists(setup.boundsPath, ec)) {
        std::optional<SourceFile> file = diskReader()(setup.boundsPath);
        Result<BoundsSpec> spec =
            file ? parseBounds(*file)
                 : Result<BoundsSpec>(
                       Error{setup.boundsPath, 0, 0, "cannot read the file", "a readable bounds file"});
        if (spec) {
            setup.start = *spec;
            setup.onDisk = *spec;
        } else {
            setup.loadProblem = spec.error().message();
            std::fprintf(stderr, "%s\n", setup.loadProblem.c_str());
            std::fprintf(stderr, "%s: starting from gen's fit; the file is written only when you save\n",
                         setup.boundsPath.c_str());
        }
    }
    if (!setup.onDisk) {
        BoundsGenOptions options;
        options.radii = args.radii;
        options.container = args.container;
        options.threshold = setup.sprite.threshold;
        Result<GeneratedBounds> fit = generateBounds(setup.sprite.mask, options);
        if (fit) {
            setup.start = fit->spec;
        } else {
            // No opaque pixels to fit: a circle to start from.
            BoundSpec circle;
            circle.interpolate = true;
            const double r = std::max(1.0, std::min(setup.sprite.mask.width, setup.sprite.mask.height) / 2.0);
            for (int i = 0; i < 8; ++i) circle.samples.push_back({45.0 * i, r});
            setup.start.radii = {circle};
            std::fprintf(stderr, "%s: %s; starting from a circle\n", args.sprite.c_str(),
                         fit.error().what.c_str());
        }
    }

    setup.partners.push_back({"same sprite", setup.image, nullptr, nullptr});
    setup.partners.back().pixels =
        std::make_shared<const OpaquePixels>(setup.sprite.mask, setup.sprite.threshold);
    for (editor::Partner& p : assetPartners()) setup.partners.push_back(std::move(p));

    Editor editor(std::move(setup));
    if (!args.script.empty() || !args.screenshot.empty()) return runHeadless(editor, args);
    return runWindow(editor, args);
}

}  // namespace polar::bounds_tool
