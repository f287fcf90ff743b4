// Shared helpers for drt's tests.
#pragma once

#include "accel/accel.h"
#include "core/diagnostics.h"
#include "pov/load.h"
#include "render/render.h"
#include "scene/scene.h"

#include <memory>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace drt::test {

// Absolute path of a file in the source tree, e.g. sourcePath("examples/minimal.drt").
std::string sourcePath(const std::string& relative);
// A fresh empty temporary folder for this test (removed at process exit is not
// guaranteed; it lives under the system temp folder).
std::string tempDir();
// Writes text to a file, creating folders as needed; returns the path.
std::string writeFile(const std::string& path, const std::string& text);
std::string readFile(const std::string& path);

// A 5x5 render at 1 sample per pixel, seed 3, one thread: for tests that read
// a closed-form value off the centre pixel.
inline RenderOptions tinyRenderOptions() {
    RenderOptions o;
    o.width = 5;
    o.height = 5;
    o.samplesPerPixel = 1;
    o.seed = 3;
    o.threads = 1;
    return o;
}

struct CommandResult {
    int exitCode = -1;
    std::string out; // stdout
    std::string err; // stderr
};
// A GoogleTest parameter name (letters, digits, '_') made from a description,
// so that parameterised tests read as Suite.Test/what_it_checks in ctest.
inline std::string testNameOf(const std::string& description) {
    std::string name;
    for (char c : description) {
        const bool word = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
        if (word)
            name += c;
        else if (!name.empty() && name.back() != '_')
            name += '_';
    }
    while (!name.empty() && name.back() == '_')
        name.pop_back();
    return name.empty() ? "case" : name;
}

// The path of the drt executable built with these tests.
std::string drtExecutable();
// Runs the drt executable with the given argument string (shell-quoted by the caller).
CommandResult runDrt(const std::string& arguments);
// What the dynamic loader says (LD_DEBUG=libs) of the libraries it opens for
// drt run with `arguments`: one line per search and load.
std::string librariesDrtLoads(const std::string& arguments);

// A scene text read in process (the .pov or the .drt front end), its
// diagnostics, and the texts of its #warning directives in order: how the
// expression tests read a value (`#warning str(E, 0, 9)`).
struct SceneRun {
    std::optional<Scene> scene;
    Diagnostics diags;
    std::vector<std::string> messages;
};
std::unique_ptr<SceneRun> readSceneText(const std::string& text, bool pov = true, const PovOptions& options = {});

// Checks (as GoogleTest failures) that the first error in `diags` says `message`
// at `file`:`line`:`column`, and that its printed form has that location and a
// caret under the column. Returns the error (null when there is none).
const Diagnostic* expectErrorAt(const Diagnostics& diags, const std::string& file, int line, int column,
                                const std::string& message);

// The scene with the files it names read (assets/assets.h), as drt render
// reads them after parsing; adds a test failure if that reports an error.
Scene withAssets(Scene scene);

// An object of the given shape and transform, with every other field at its default.
inline Object makeObject(Shape shape, Transform transform = {}) {
    Object o;
    o.shape = std::move(shape);
    o.transform = transform;
    return o;
}

// A scene holding just these objects.
inline Scene sceneOf(std::vector<Object> objects) {
    Scene s;
    s.objects = std::move(objects);
    return s;
}

// Builds (and drops) an accelerator for `scene`: for tests of the errors a
// build throws. The scene outlives the accelerator, as Accelerator requires.
inline void buildAccelerator(const Scene& scene) {
    Accelerator accel(scene);
}

// A uniformly distributed random unit vector.
inline Vec3 randomUnitVector(std::mt19937& rng) {
    std::normal_distribution<double> g;
    return normalize(Vec3{g(rng), g(rng), g(rng)});
}

// Spawns one ray in a random direction to each side of the surface at `hit`
// (reached from `origin`) and counts, in `selfHits`, those that hit the same
// surface again at their own spawn point (within 1e-5 of `scale`).
inline void countSelfHits(const Accelerator& accel, const Hit& hit, const Vec3& origin, double scale,
                          std::mt19937& rng, int& rays, int& selfHits) {
    const Vec3 outward = dot(hit.geometricNormal, origin - hit.point) > 0 ? hit.geometricNormal : -hit.geometricNormal;
    for (int side : {1, -1}) {
        Vec3 d = randomUnitVector(rng);
        if (dot(d, side * outward) < 0) d = -d;
        Ray spawned;
        spawned.direction = d;
        spawned.origin = Accelerator::offsetOrigin(hit, d);
        Hit again;
        ++rays;
        if (accel.intersect(spawned, again) && length(again.point - hit.point) < 1e-5 * scale &&
            dot(again.geometricNormal, hit.geometricNormal) > 0.99)
            ++selfHits;
    }
}

// The first hit of the ray from `origin` along `direction` at `time`, if any.
inline std::optional<Hit> trace(const Accelerator& accel, Vec3 origin, Vec3 direction, double time = 0) {
    Ray ray;
    ray.origin = origin;
    ray.direction = direction;
    ray.time = time;
    Hit hit;
    if (!accel.intersect(ray, hit)) return std::nullopt;
    return hit;
}

} // namespace drt::test
