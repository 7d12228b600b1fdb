#include "polar/scene_file.h"

#include <gtest/gtest.h>

#include <map>

#include "polar/bounds_file.h"

namespace polar {
namespace {

// Files held in memory, counting how often each is read.
struct MemoryFiles {
    std::map<std::string, std::string> files;
    std::shared_ptr<std::map<std::string, int>> reads = std::make_shared<std::map<std::string, int>>();

    FileReader reader() const {
        return [files = files, reads = reads](const std::string& path) -> std::optional<SourceFile> {
            ++(*reads)[path];
            auto it = files.find(path);
            if (it == files.end()) return std::nullopt;
            return SourceFile{path, it->second};
        };
    }
};

const char* kRock =
    R"({"format": 1, "radii": [{"centre": [0, 0], "interpolate": true, "samples": [[0, 30], [90, 24.5], [180, 31], [270, 22]]}]})";

Result<SceneDef> parse(const std::string& text, MemoryFiles files = {}) {
    files.files.emplace("game/bounds/rock.bounds.json", kRock);
    return parseScene(SourceFile{"game/scene.json", text}, files.reader());
}

// Asserts that the scene fails with an error at exactly `file:line:column` whose message holds each
// of `fragments` (what is wrong and what was expected).
void expectError(const std::string& text, const std::string& where, std::vector<std::string> fragments,
                 MemoryFiles files = {}) {
    Result<SceneDef> r = parse(text, files);
    ASSERT_FALSE(r.ok()) << "loaded but should not have:\n" << text;
    const Error& e = r.error();
    EXPECT_EQ(e.file + ":" + std::to_string(e.line) + ":" + std::to_string(e.column), where) << e.message();
    EXPECT_FALSE(e.expected.empty()) << e.message();
    EXPECT_EQ(e.message().rfind(where + ": ", 0), 0u) << e.message();
    EXPECT_NE(e.message().find("; expected "), std::string::npos) << e.message();
    for (const std::string& f : fragments)
        EXPECT_NE(e.message().find(f), std::string::npos) << e.message() << "\n  lacks: " << f;
}

// A scene with one object whose body is `object` (the text inside its braces), on line 3.
std::string oneObject(const std::string& object,
                      const std::string& effects = R"(["physics", "collisions", "response", "containers"])") {
    return "{\"format\": 1, \"effects\": " + effects + ",\n\"objects\": [\n{" + object + "}\n]}";
}

TEST(SceneFile, ReadsTheDocumentedExample) {
    Result<SceneDef> r = parse(
        R"({"format": 1, "effects": ["physics", "collisions", "response"], "restitution": 0.8, "objects": [{"name": "rock-1", "sprite": "sprites/rock.png", "bounds": "bounds/rock.bounds.json", "position": [120, 40], "rotation": 30, "scale": 1.5, "velocity": [10, 0], "spin": 45, "damping": 0.1, "flags": ["physics", "collisions"]}]})");
    ASSERT_TRUE(r.ok()) << r.error().message();
    EXPECT_EQ(r->path, "game/scene.json");
    EXPECT_EQ(r->world.effects, kEffectPhysics | kEffectCollisions | kEffectResponse);
    EXPECT_EQ(r->world.restitution, 0.8);
    ASSERT_EQ(r->objects.size(), 1u);
    const SceneObject& o = r->objects[0];
    EXPECT_EQ(o.name, "rock-1");
    EXPECT_EQ(o.sprite, "game/sprites/rock.png");  // relative to the scene file
    EXPECT_EQ(o.boundsPath, "game/bounds/rock.bounds.json");
    ASSERT_TRUE(o.bounds);
    ASSERT_EQ(o.bounds->size(), 1u);
    EXPECT_DOUBLE_EQ((*o.bounds)[0].radius(kPi), 31);
    EXPECT_EQ(o.transform.position(), Vec2(120, 40));
    EXPECT_NEAR(o.transform.rotation(), kPi / 6, 1e-15);
    EXPECT_EQ(o.transform.scaleFactors(), Vec2(1.5, 1.5));
    EXPECT_EQ(o.velocity, Vec2(10, 0));
    EXPECT_NEAR(o.spin, kPi / 4, 1e-15);  // degrees per second in the file, radians in code
    EXPECT_EQ(o.damping, 0.1);
    EXPECT_EQ(o.flags, kPhysics | kCollisions);
}

TEST(SceneFile, DefaultsForAnEmptyObject) {
    Result<SceneDef> r = parse(oneObject(R"("name": "x")"));
    ASSERT_TRUE(r.ok()) << r.error().message();
    const SceneObject& o = r->objects[0];
    EXPECT_EQ(o.transform.position(), Vec2(0, 0));
    EXPECT_EQ(o.transform.rotation(), 0.0);
    EXPECT_EQ(o.transform.scaleFactors(), Vec2(1, 1));
    EXPECT_EQ(o.velocity, Vec2(0, 0));
    EXPECT_EQ(o.flags, 0u);
    EXPECT_FALSE(o.bounds);
    Result<SceneDef> bare = parse(R"({"format": 1})");
    ASSERT_TRUE(bare.ok()) << bare.error().message();
    EXPECT_EQ(bare->world.effects, 0u);
    EXPECT_TRUE(bare->objects.empty());
}

TEST(SceneFile, ScaleIsANumberOrAPair) {
    Result<SceneDef> r = parse(
        R"({"format": 1, "objects": [{"name": "a", "scale": 2.5}, {"name": "b", "scale": [-1, 0.5]}]})");
    ASSERT_TRUE(r.ok()) << r.error().message();
    EXPECT_EQ(r->objects[0].transform.scaleFactors(), Vec2(2.5, 2.5));
    EXPECT_EQ(r->objects[1].transform.scaleFactors(), Vec2(-1, 0.5));  // a mirror
    expectError(oneObject(R"("name": "x", "scale": "big")"), "game/scene.json:3:24",
                {"found a string", "a number or [sx, sy]"});
    expectError(oneObject(R"("name": "x", "scale": [1, 2, 3])"), "game/scene.json:3:24",
                {"an array of 3 items", "[sx, sy]"});
}

TEST(SceneFile, AnglesOutsideTheCircleAreReduced) {
    Result<SceneDef> r = parse(R"({"format": 1, "objects": [
        {"name": "a", "rotation": -90}, {"name": "b", "rotation": 720}, {"name": "c", "rotation": 450},
        {"name": "d", "rotation": 180},
        {"name": "e", "bounds": {"radii": [{"samples": [[-90, 1], [720, 2]]}]}}]})");
    ASSERT_TRUE(r.ok()) << r.error().message();
    EXPECT_NEAR(r->objects[0].transform.rotation(), -kHalfPi, 1e-15);
    EXPECT_EQ(r->objects[1].transform.rotation(), 0.0);
    EXPECT_NEAR(r->objects[2].transform.rotation(), kHalfPi, 1e-15);
    EXPECT_NEAR(std::fabs(r->objects[3].transform.rotation()), kPi, 1e-15);
    const Bound& e = (*r->objects[4].bounds)[0];
    EXPECT_EQ(e.samples()[0].angle, 0.0);
    EXPECT_EQ(e.samples()[0].radius, 2);
    EXPECT_DOUBLE_EQ(e.samples()[1].angle, degToRad(270));
}

TEST(SceneFile, InlineBounds) {
    Result<SceneDef> r = parse(oneObject(
        R"("name": "x", "bounds": {"radii": [{"centre": [1, 2], "interpolate": true, "samples": [[0, 3], [120, 4], [240, 5]]}, {"samples": [[0, 9]]}]})"));
    ASSERT_TRUE(r.ok()) << r.error().message();
    const SceneObject& o = r->objects[0];
    EXPECT_TRUE(o.boundsPath.empty());
    ASSERT_TRUE(o.bounds);
    ASSERT_EQ(o.bounds->size(), 2u);
    EXPECT_EQ((*o.bounds)[0].centre(), Vec2(1, 2));
    EXPECT_TRUE((*o.bounds)[0].interpolate());
    EXPECT_EQ((*o.bounds)[1].radius(0.3), 9);
    // "format" may be given inline, and must then be 1.
    EXPECT_TRUE(parse(oneObject(R"("name": "x", "bounds": {"format": 1, "radii": []})")).ok());
    expectError(oneObject(R"("name": "x", "bounds": {"format": 3, "radii": []})"), "game/scene.json:3:36",
                {"unsupported format 3", "\"format\": 1"});
}

TEST(SceneFile, PathsAreRelativeToTheFileThatNamesThem) {
    MemoryFiles files;
    files.files["levels/one/scene.json"] = R"({"format": 1, "objects": [
        {"name": "a", "bounds": "../../shared/ship.bounds.json", "sprite": "../art/ship.png"},
        {"name": "b", "bounds": "local.bounds.json"}]})";
    files.files["shared/ship.bounds.json"] = R"({"format": 1, "radii": [{"samples": [[0, 4]]}]})";
    files.files["levels/one/local.bounds.json"] = R"({"format": 1, "radii": [{"samples": [[0, 6]]}]})";
    Result<SceneDef> r = loadScene("levels/one/scene.json", files.reader());
    ASSERT_TRUE(r.ok()) << r.error().message();
    EXPECT_EQ(r->objects[0].boundsPath, "shared/ship.bounds.json");
    EXPECT_EQ(r->objects[0].sprite, "levels/art/ship.png");
    EXPECT_EQ((*r->objects[0].bounds)[0].radius(0), 4);
    EXPECT_EQ(r->objects[1].boundsPath, "levels/one/local.bounds.json");
    EXPECT_EQ((*r->objects[1].bounds)[0].radius(0), 6);
}

TEST(SceneFile, LoadsFromDiskWithRelativePaths) {
    Result<SceneDef> r = loadScene(std::string(POLAR_TEST_DATA) + "/scenes/shared_bounds.json", diskReader());
    ASSERT_TRUE(r.ok()) << r.error().message();
    ASSERT_EQ(r->objects.size(), 3u);
    EXPECT_EQ(r->objects[0].boundsPath, std::string(POLAR_TEST_DATA) + "/bounds/rock.bounds.json");
    EXPECT_DOUBLE_EQ((*r->objects[0].bounds)[0].radius(kHalfPi), 24.5);
    // Two spellings of the same file share one Bounds.
    EXPECT_EQ(r->objects[0].bounds.get(), r->objects[1].bounds.get());
    EXPECT_NE(r->objects[0].bounds.get(), r->objects[2].bounds.get());  // inline bounds are its own
}

TEST(SceneFile, ObjectsNamingTheSameBoundsFileShareIt) {
    MemoryFiles files;
    Result<SceneDef> r = parse(R"({"format": 1, "objects": [
        {"name": "a", "bounds": "bounds/rock.bounds.json"},
        {"name": "b", "bounds": "./bounds/../bounds/rock.bounds.json"},
        {"name": "c"},
        {"name": "d", "bounds": "bounds/rock.bounds.json"}]})",
                               files);
    ASSERT_TRUE(r.ok()) << r.error().message();
    EXPECT_EQ(r->objects[0].bounds.get(), r->objects[1].bounds.get());
    EXPECT_EQ(r->objects[0].bounds.get(), r->objects[3].bounds.get());
    EXPECT_EQ((*files.reads)["game/bounds/rock.bounds.json"], 1);  // read once
    World world = buildWorld(*r);
    EXPECT_EQ(&world.objects()[0].boundsOrEmpty(), &world.objects()[3].boundsOrEmpty());
}

TEST(SceneFile, BuildWorldKeepsFileOrder) {
    Result<SceneDef> r = parse(R"({"format": 1, "effects": ["collisions"], "restitution": 0.25, "objects": [
        {"name": "z"}, {"name": "a"}, {"name": "m", "position": [5, 6]}]})");
    ASSERT_TRUE(r.ok()) << r.error().message();
    World world = buildWorld(*r);
    ASSERT_EQ(world.objects().size(), 3u);
    EXPECT_EQ(world.objects()[0].name, "z");
    EXPECT_EQ(world.objects()[1].name, "a");
    EXPECT_EQ(world.objects()[2].name, "m");
    EXPECT_LT(world.objects()[0].id, world.objects()[1].id);
    EXPECT_LT(world.objects()[1].id, world.objects()[2].id);
    EXPECT_EQ(world.findByName("m")->transform.position(), Vec2(5, 6));
    EXPECT_EQ(world.def().restitution, 0.25);
    EXPECT_TRUE(world.runs(kEffectCollisions));
    EXPECT_FALSE(world.runs(kEffectPhysics));
}

// One test per error kind of part 7, each at its exact place.

TEST(SceneFileErrors, NonFiniteNumber) {
    expectError(oneObject(R"("name": "x", "position": [1e999, 0])"), "game/scene.json:3:28",
                {"non-finite", "a finite number"});
    expectError(oneObject(R"("name": "x", "bounds": {"radii": [{"samples": [[0, -1e500]]}]})"),
                "game/scene.json:3:53", {"non-finite"});
}

TEST(SceneFileErrors, WrongType) {
    expectError(oneObject(R"("name": "x", "position": "here")"), "game/scene.json:3:27",
                {"found a string", "a position [x, y]"});
    expectError(oneObject(R"("name": "x", "rotation": "30")"), "game/scene.json:3:27",
                {"found a string", "a rotation in degrees"});
    expectError(oneObject(R"("name": 7)"), "game/scene.json:3:10", {"found a number", "non-empty name"});
    expectError(oneObject(R"("name": "x", "flags": "physics")"), "game/scene.json:3:24",
                {"found a string", "an array of flag names"});
    expectError(oneObject(R"("name": "x", "velocity": [1, true])"), "game/scene.json:3:31",
                {"found a boolean", "a velocity"});
    expectError(oneObject(R"("name": "x", "bounds": 12)"), "game/scene.json:3:25",
                {"found a number", "a bounds file path or an inline bounds object"});
    expectError("{\"format\": 1, \"objects\": {}}", "game/scene.json:1:26",
                {"found an object", "an array of objects"});
    expectError("{\"format\": 1, \"effects\": \"physics\"}", "game/scene.json:1:26",
                {"found a string", "an array of effect names"});
    expectError("{\"format\": 1, \"restitution\": \"high\"}", "game/scene.json:1:30",
                {"found a string", "a restitution between 0 and 1"});
}

TEST(SceneFileErrors, RadiusNotPositive) {
    expectError(oneObject(R"("name": "x", "bounds": {"radii": [{"samples": [[0, 1], [90, 0]]}]})"),
                "game/scene.json:3:57", {"radius 0 is not positive", "a radius > 0"});
}

TEST(SceneFileErrors, SameAngleAfterReducingModulo360) {
    expectError(oneObject(R"("name": "x", "bounds": {"radii": [{"samples": [[10, 1], [370, 2]]}]})"),
                "game/scene.json:3:58",
                {"angle 370 is the same direction as 10", "one sample per direction"});
}

TEST(SceneFileErrors, InterpolateWithFewerThanThreeSamples) {
    expectError(
        oneObject(
            R"("name": "x", "bounds": {"radii": [{"interpolate": true, "samples": [[10, 1], [100, 2]]}]})"),
        "game/scene.json:3:69", {"interpolate needs at least 3 samples", "3 or more samples"});
}

TEST(SceneFileErrors, InterpolateWithAGapOf180OrMore) {
    expectError(
        oneObject(
            R"("name": "x", "bounds": {"radii": [{"interpolate": true, "samples": [[0, 1], [90, 2], [300, 2]]}]})"),
        "game/scene.json:3:78", {"a gap of 210 degrees from angle 90", "star-shaped"});
}

TEST(SceneFileErrors, DuplicateObjectName) {
    expectError(
        "{\"format\": 1, \"objects\": [\n  {\"name\": \"rock\"},\n  {\"name\": \"ship\"},\n  {\"name\": "
        "\"rock\"}]}",
        "game/scene.json:4:12",
        {"duplicate object name \"rock\" (first used on line 2)", "a name no other object has"});
}

TEST(SceneFileErrors, EmptyObjectName) {
    expectError(oneObject(R"("position": [1, 2], "name": "")"), "game/scene.json:3:30",
                {"an empty object name", "non-empty name"});
    expectError(oneObject(R"("position": [1, 2])"), "game/scene.json:3:1",
                {"missing key \"name\"", "non-empty \"name\""});
}

TEST(SceneFileErrors, UnknownFlag) {
    expectError(oneObject(R"("name": "x", "flags": ["collisions", "ghosted"])"), "game/scene.json:3:39",
                {"unknown flag \"ghosted\"",
                 "one of \"physics\", \"collisions\", \"ghost\", \"container\", \"ignore_containers\""});
}

TEST(SceneFileErrors, UnknownKey) {
    expectError(oneObject(R"("name": "x", "positon": [1, 2])"), "game/scene.json:3:15",
                {"unknown key \"positon\"", "\"position\""});
    expectError(
        "{\"format\": 1,\n  \"effect\": []}", "game/scene.json:2:3",
        {"unknown key \"effect\"",
         "one of \"format\", \"effects\", \"broad_phase\", \"restitution\", \"objects\", \"accuracy\""});
}

TEST(SceneFileErrors, MissingBoundsFile) {
    expectError(oneObject(R"("name": "x", "bounds": "bounds/gone.bounds.json")"), "game/scene.json:3:25",
                {"cannot read bounds file \"game/bounds/gone.bounds.json\"", "relative to this scene"});
}

TEST(SceneFileErrors, MissingSceneFile) {
    Result<SceneDef> r = loadScene(std::string(POLAR_TEST_DATA) + "/scenes/not-there.json", diskReader());
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(
        r.error().message().rfind(std::string(POLAR_TEST_DATA) + "/scenes/not-there.json: cannot read", 0),
        0u)
        << r.error().message();
}

TEST(SceneFileErrors, ErrorInsideANamedBoundsFileNamesThatFile) {
    MemoryFiles files;
    files.files["game/bounds/bad.bounds.json"] =
        "{\"format\": 1,\n \"radii\": [{\"samples\": [[0, 1], [360, 2]]}]}";
    expectError(oneObject(R"("name": "x", "bounds": "bounds/bad.bounds.json")"),
                "game/bounds/bad.bounds.json:2:33", {"angle 360 is the same direction as 0"}, files);
}

TEST(SceneFileErrors, UnsupportedFormat) {
    expectError("{\"format\": 2, \"objects\": []}", "game/scene.json:1:12",
                {"unsupported format 2", "\"format\": 1"});
    expectError("{\"objects\": []}", "game/scene.json:1:1", {"missing key \"format\"", "\"format\": 1"});
    expectError("{\"format\": 0, \"objects\": []}", "game/scene.json:1:12", {"unsupported format 0"});
}

TEST(SceneFileErrors, UnknownEffect) {
    expectError(
        "{\"format\": 1,\n  \"effects\": [\"physics\", \"gravity\"]}", "game/scene.json:2:26",
        {"unknown effect \"gravity\"", "one of \"physics\", \"collisions\", \"response\", \"containers\""});
}

TEST(SceneFileErrors, SyntaxError) {
    expectError("{\"format\": 1,\n  \"objects\": [{\"name\": \"x\"]}", "game/scene.json:2:27",
                {"syntax error", "expected"});
}

TEST(SceneFileErrors, DuplicateKey) {
    expectError(oneObject(R"("name": "x", "position": [1, 2], "position": [3, 4])"), "game/scene.json:3:35",
                {"duplicate key \"position\"", "each key once"});
}

TEST(SceneFileErrors, RestitutionAndDampingOutOfRange) {
    expectError("{\"format\": 1, \"restitution\": 1.5}", "game/scene.json:1:30",
                {"restitution 1.5 is out of range", "between 0 and 1"});
    expectError(oneObject(R"("name": "x", "damping": -1)"), "game/scene.json:3:26",
                {"a negative damping", "≥ 0"});
}

// Both ends of a range are inside it (assets/README.md, "Scenes"): a restitution of 0 and of 1, a
// damping of 0; a step past either end is refused at the value.
TEST(SceneFile, RestitutionAndDampingAtTheEndsOfTheirRanges) {
    for (const char* restitution : {"0", "1"}) {
        Result<SceneDef> r = parse(std::string("{\"format\": 1, \"restitution\": ") + restitution + "}");
        ASSERT_TRUE(r.ok()) << restitution << ": " << r.error().message();
        EXPECT_EQ(r->world.restitution, std::stod(restitution));
    }
    expectError("{\"format\": 1, \"restitution\": -0.001}", "game/scene.json:1:30",
                {"restitution -0.001 is out of range", "between 0 and 1"});
    expectError("{\"format\": 1, \"restitution\": 1.001}", "game/scene.json:1:30",
                {"restitution 1.001 is out of range"});
    Result<SceneDef> still = parse(oneObject(R"("name": "x", "damping": 0)"));
    ASSERT_TRUE(still.ok()) << still.error().message();
    EXPECT_EQ(still->objects[0].damping, 0.0);
    expectError(oneObject(R"("name": "x", "damping": -0.001)"), "game/scene.json:3:26",
                {"a negative damping"});
}

TEST(SceneFile, CommentsAreAccepted) {
    Result<SceneDef> r = parse(R"(// a test scene
{
  "format": 1, /* the only format */
  "objects": [
    {"name": "a", // first
     "position": [1, /* x */ 2]}
  ]
})");
    ASSERT_TRUE(r.ok()) << r.error().message();
    EXPECT_EQ(r->objects[0].transform.position(), Vec2(1, 2));
}

}  // namespace
}  // namespace polar
