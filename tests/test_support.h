// Shared helpers for drt's tests.
#pragma once

#include "scene/scene.h"

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

struct CommandResult {
    int exitCode = -1;
    std::string out; // stdout
    std::string err; // stderr
};
// Runs the drt executable with the given argument string (shell-quoted by the caller).
CommandResult runDrt(const std::string& arguments);

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

} // namespace drt::test
