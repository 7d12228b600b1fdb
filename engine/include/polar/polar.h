#pragma once
// The Polar engine on one page: everything Polar::engine offers. Include this and you have all of it.
// Drawing and the window are libraries of their own, each with a one-page header like this one:
//   polar/render/render.h      Polar::render    canvas, images, view, sprites, shapes, text (no SDL)
//   polar/platform/platform.h  Polar::platform  window, input events, audio, PNG files (SDL)
// Making and checking assets (bounds generation, pixel truth, random scenes) is Polar::authoring,
// polar/authoring/*.h: tools and tests need it, a running game does not.
//
// Conventions (math.h): x right, y up, angles counter-clockwise from +x, radians in code and degrees
// in files, M = T(position)·R(θ)·S(sx, sy); bound space is sprite pixels about the sprite's centre.
//
// World lifecycle
//   WorldDef def;  def.effects = kEffectPhysics | …;  def.restitution = 0.8;      how the world runs
//   def.accuracy = Accuracy::Bounds;  def.broadPhase = BroadPhase::Grid;            (the defaults)
//   World world(def);                                 empty; copyable and movable
//   world.step(1.0 / 60);                             advances dt seconds; allocates nothing when warm
//   world.stepCount();  world.def();  world.runs(kEffectCcd);  world.setBroadPhase(BroadPhase::Grid)
//   world.reserve(n);                                 room for n objects
//   def.workers = 4;                                  the step on 4 threads (own pool); 1: no threads
//   def.tasks = &myTaskSystem;                        or the game's TaskSystem (tasks.h), shared
//   world.workerCount();                              same bits at any count; small phases stay inline
//   ThreadPool pool(hardwareThreads());  runTask(pool, fn, count, minRange, context)   tasks.h
//
// Objects
//   ObjectDef o;  o.name, o.transform, o.velocity, o.spin, o.damping, o.bounds, o.flags
//   o.userData = myIndex;                             the game's own uint64; copied, never read or hashed
//   ObjectId id = world.add(o);                       a given name must be unique; "" is unnamed
//   world.remove(id) → bool;  world.find(id) → GameObject* (null when there is no such object)
//   world.findByName("ship") → GameObject*;  world.nameTaken("ship") → bool
//   world.objects() → span<GameObject>                creation order; edit fields in place
//   object.id;  object.has(kPhysics);  object.boundsOrEmpty() → const Bounds&
//   Transform t(position, radians, scale);            or Transform t; t.setPosition(p)
//   t.translate(d);  t.rotate(dθ);  t.scale(f) / t.scale(fx, fy)                 each its own factor
//   t.setPosition(p);  t.setRotation(θ);  t.setScale(s);  t.position(), rotation(), scaleFactors()
//   t.linear() → R·S;  t.matrix() → T·R·S;  t.apply(q) → p + R·S·q
//
// Flags (per object, ObjectFlags) and effects (per world, Effects)
//   kPhysics  kCollisions  kGhost  kContainer  kIgnoreContainers  kFast          kAllFlags
//   kEffectPhysics  kEffectCollisions  kEffectResponse  kEffectContainers  kEffectCcd   kAllEffects
//   world.setFlags(id, flags) → bool                  the way to change flags once added
//   effectsFor(flags) → Effects                       what a world must run for those flags to act
//   inertFlags(flags, effects) → ObjectFlags          the flags that would do nothing there
//   flagName(kFast) → "fast";  flagFromName("fast");  effectName(kEffectCcd);  effectFromName("ccd")
//
// Bounds (a Bound is one outline: a centre and radius samples; Bounds is an object's list of them)
//   Bound(centre, radius)                    a circle; CollisionRadii is the seed's name for Bound
//   Bound(centre, {{angle, r}, …}, interpolate)   radians; interpolate joins samples by chords
//   Bound::fromDegrees(centre, {{deg, r}, …}, interpolate)
//   Bound::check(degreeSamples, interpolate) → optional<SampleProblem>
//   bound.radius(φ);  bound.worldRadius(L, w);  bound.maxRadius();  bound.outlinePoint(φ)
//   makeBounds(bound) / makeBounds(Bounds{a, b}) → BoundsPtr;  circleBounds(r, centre) → BoundsPtr
//   boundOutline(bound, toTarget, tolerance) → vector<Vec2>   the outline the rule sees, for drawing
//   boundSamplePoints(bound, toTarget) → vector<Vec2>;  radiiOutline, radiiSamplePoints: the older names
//
// Collision queries
//   world.collidedWith(id) → span<const ObjectId>     what id touched in the last step, pair order
//   world.hits() → span<const PairReport>             the last step's hits: {a, b, test}, object indices
//   world.detect(all) → vector<PairReport>            one detection pass now; moves nothing
//   testObjects(a, b, accuracy) → PairTest            {hit, normal, distance, ra, rb, penetration, kind}
//   ContactKind::Contact (kept apart)  ContactKind::Container (held inside);  contactKindName(kind)
//   Accuracy::Bounds Circle Nearest Chord AllRadii Exact;  accuracyName(a);  accuracyFromName("exact")
//   BroadPhase::AllPairs Grid SortAndSweep;  broadPhaseName(m);  broadPhaseFromName("grid")
//
// Scene and bounds files (JSON with comments, "format": 1, unknown keys rejected)
//   loadScene(path, diskReader()) → Result<SceneDef>;  buildWorld(scene) → World
//   scene.objects[i] → SceneObject: an ObjectDef plus the .sprite and .boundsPath the file names
//   parseScene(SourceFile{path, text}, reader) → Result<SceneDef>
//   loadBounds(path, reader) → Result<BoundsPtr>;  parseBounds(file) → Result<BoundsSpec>
//   spec.radii[k] → BoundSpec {centre, interpolate, samples}   one bound as written (RadiiSpec: older name)
//   buildBounds(spec) → Bounds;  boundsToJson(spec) → string;  saveBounds(path, spec) → optional<Error>
//   writeFileAtomically(path, contents) → optional<Error>      readers see the old file or the new
//
// JSON (comments allowed; every value knows its file:line:column; members in file order)
//   JsonDoc::parse(SourceFile{path, text}) → Result<JsonDoc>;  doc.root() → JsonNode
//   node.kind() → JsonKind::Null Boolean Number String Array Object;  kindName() → "an array", …
//   node.isNull() isBoolean() isNumber() isInteger() isString() isArray() isObject()
//   node.boolean(expected) number(…) integer(…) string(…) vec2(…)   the wrong kind throws LoadFailure
//   node.size(), at(i), items(expected), members(expected), key()   elements; members in file order
//   node.find("k") → optional<JsonNode>;  has("k");  require("k", expected);  allowKeys({"a", "b"})
//   node.line(), column(), pointer() → "/objects/2";  error(what, expected) → Error;  fail(…) throws
//   doc.errorAt("/objects/2", what, expected) → Error;  catchLoadFailure<T>([&] { … }) → Result<T>
//   JsonWriter w(2);  w.beginObject().member("format", 1).key("a").beginArray().value(x).endArray()
//   w.endObject();  w.text() → string   members in the order written;  jsonNumberText(0.1) → "0.1"
//
// Errors (bad data comes back as a value: no exception leaves a loader, a restore or a step)
//   Result<T> r = …;  if (!r) print(r.error().message());  else use(*r);   r->field, r.ok()
//   r.error().message() → "file:line:column: what; expected …"
//   Error{file, line, column, what, expected};  resolveRelative(file, relativePath)
//   Only inside a loader is anything thrown: JsonNode's checked accessors and fail() throw
//   LoadFailure{error}, which the loader's catchLoadFailure<T> returns as its Result's Error (every
//   engine loader does; a game's own loader over JsonNode wraps its body the same way).
//
// Snapshots (rollback, seeking, tests; plain bytes for the program that made them, not a file format)
//   WorldSnapshot s;  saveSnapshot(world, s);          a warm save allocates nothing
//   restoreSnapshot(world, s) → optional<Error>       world.hash() as at the save; damage changes nothing
//   ByteWriter w = startSnapshotFrame(bytes, kind);  w.put(x);  endSnapshotFrame(w)   a game's own state
//   openSnapshotFrame(bytes, kind) → Result<ByteReader>;  in.get<T>();  in.ok()   kind: SnapshotKind
//
// Hashing (FNV-1a over exact bits)
//   world.hash() → uint64                             the rules, the next id and every object's state
//   objectHash(object) → uint64;  addObjectState(h, object);  StateHash h;  h.add(x);  h.value()
//
// Stats
//   world.lastStepStats()[kEffectPhysics] → {calls, objects, pairs, nanoseconds, bytes}
//   world.totalStats();  world.setTiming(true);  formatStepStats(world.totalStats(), world.stepCount())
//
// Math
//   Vec2, Mat2, Mat3 (Eigen);  kPi;  degToRad(d);  radToDeg(r);  reduceDegrees(d);  reduceRadians(r)
//   cross(a, b);  rotationMatrix(θ);  trig::sin / cos / sincos / atan2   bit-identical everywhere
//   splitmix64(state) → uint64                        one seeded step; the same sequence everywhere
#include "polar/accuracy.h"
#include "polar/atomic_file.h"
#include "polar/bound.h"
#include "polar/bound_outline.h"
#include "polar/bounds_file.h"
#include "polar/broad_phase.h"
#include "polar/collision.h"
#include "polar/effects.h"
#include "polar/error.h"
#include "polar/game_object.h"
#include "polar/json_doc.h"
#include "polar/json_writer.h"
#include "polar/math.h"
#include "polar/scene_file.h"
#include "polar/snapshot_bytes.h"
#include "polar/splitmix64.h"
#include "polar/state_hash.h"
#include "polar/step_stats.h"
#include "polar/tasks.h"
#include "polar/transform.h"
#include "polar/world.h"
#include "polar/world_hash.h"
#include "polar/world_snapshot.h"
