// drt_mesh_bench: the mesh figures of docs/performance-meshes.md, measured in
// one run. For each size it generates a height-field grid (never a download),
// writes it as .drt text, OBJ and binary PLY, and measures in child processes
// (so each peak memory is its own):
//   text    parse of `mesh { triangle ... }` text by drt's front end (MB/s)
//   obj/ply loading the model file into a compact mesh
//   raw     raw Embree: the same float arrays as a triangle geometry, committed
//   compact drt: the compact mesh in a scene, Accelerator built, image traced
//   empty   the bare process, whose peak memory the others subtract
// and, when given drt binaries (--drt LABEL=PATH), the whole `drt render` of
// the text scene (and of `mesh { file }` where the binary reads it) with its
// wall time and peak memory per triangle.
#include "assets/assets.h"
#include "lang/load.h"
#include "mesh_generators.h"
#include "render/render.h"

#include <embree3/rtcore.h>
#include <fmt/format.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace {

using namespace drt;
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

long peakKiB() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss;
}

// A grid of about `triangles` triangles (2 n^2).
std::shared_ptr<IndexedMesh> grid(long triangles) {
    return test::gridMesh(std::max(1, int(std::lround(std::sqrt(triangles / 2.0)))));
}

std::string file(const std::string& dir, long n, const char* ext) {
    return fmt::format("{}/grid{}.{}", dir, n, ext);
}

const char* kSceneHead = "camera { location <0.5, 1.2, -0.4> look_at <0.5, 0, 0.5> angle 50 }\n"
                         "light_source { <3, 5, -2> color rgb 1 }\n";

void writeFiles(const std::string& dir, long n) {
    const auto m = grid(n);
    const auto v = [&](uint32_t i) { return m->positions[i]; };
    std::string text = kSceneHead;
    text += "mesh {\n";
    for (size_t t = 0; t < m->triangleCount(); ++t) {
        const auto tri = m->triangle(t);
        text += fmt::format("  triangle {{ <{},{},{}>, <{},{},{}>, <{},{},{}> }}\n", v(tri[0]).x, v(tri[0]).y,
                            v(tri[0]).z, v(tri[1]).x, v(tri[1]).y, v(tri[1]).z, v(tri[2]).x, v(tri[2]).y,
                            v(tri[2]).z);
    }
    text += "  pigment { color rgb <0.8, 0.7, 0.6> }\n}\n";
    std::ofstream(file(dir, n, "drt")) << text;
    std::ofstream(file(dir, n, "file.drt")) << kSceneHead << "mesh { file \"" << file(dir, n, "ply")
                                            << "\" pigment { color rgb <0.8, 0.7, 0.6> } }\n";
    std::string obj;
    for (const Float3& p : m->positions)
        obj += fmt::format("v {} {} {}\n", p.x, p.y, p.z);
    for (size_t t = 0; t < m->triangleCount(); ++t) {
        const auto tri = m->triangle(t);
        obj += fmt::format("f {} {} {}\n", tri[0] + 1, tri[1] + 1, tri[2] + 1);
    }
    std::ofstream(file(dir, n, "obj")) << obj;
    std::ofstream ply(file(dir, n, "ply"), std::ios::binary);
    ply << "ply\nformat binary_little_endian 1.0\nelement vertex " << m->positions.size()
        << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << m->triangleCount()
        << "\nproperty list uchar int vertex_indices\nend_header\n";
    ply.write(reinterpret_cast<const char*>(m->positions.data()),
              std::streamsize(m->positions.size() * sizeof(Float3)));
    for (size_t t = 0; t < m->triangleCount(); ++t) {
        const char three = 3;
        ply.write(&three, 1);
        ply.write(reinterpret_cast<const char*>(&m->indices[3 * t]), 3 * sizeof(uint32_t));
    }
}

Scene gridScene(std::shared_ptr<const IndexedMesh> mesh) {
    Scene scene;
    scene.camera.location = {0.5, 1.2, -0.4};
    scene.camera.lookAt = Vec3{0.5, 0, 0.5};
    scene.camera.angle = 50;
    Light light;
    light.position = {3, 5, -2};
    scene.lights.push_back(light);
    Object o;
    Mesh m;
    m.indexed = std::move(mesh);
    o.shape = m;
    o.texture.pigment.color = ColorFT{Color(0.8, 0.7, 0.6), 0, 0};
    scene.objects.push_back(o);
    return scene;
}

// One measurement in this (child) process; prints "key value" lines.
int measure(const std::string& mode, long n, const std::string& dir, int threads) {
    const long startKiB = peakKiB();
    std::printf("start_kib %ld\n", startKiB);
    if (mode == "empty")
        return 0;
    if (mode == "text") {
        Diagnostics diags;
        const auto start = Clock::now();
        const auto scene = loadSceneFile(file(dir, n, "drt"), diags);
        const double s = secondsSince(start);
        if (!scene)
            return 1;
        std::printf("seconds %.6f\nmb_per_s %.2f\n", s,
                    double(std::filesystem::file_size(file(dir, n, "drt"))) / 1e6 / s);
    } else if (mode == "obj" || mode == "ply") {
        Scene scene;
        auto source = std::make_shared<MeshSource>();
        source->kind = MeshSource::Kind::ModelFile;
        source->path = file(dir, n, mode.c_str());
        Mesh m;
        m.source = source;
        Object o;
        o.shape = m;
        scene.objects.push_back(o);
        Diagnostics diags;
        const auto start = Clock::now();
        if (!resolveAssets(scene, diags))
            return 1;
        std::printf("seconds %.6f\n", secondsSince(start));
    } else if (mode == "raw") {
        const auto mesh = grid(n);
        RTCDevice device = rtcNewDevice(fmt::format("threads={}", threads).c_str());
        const auto start = Clock::now();
        RTCScene scene = rtcNewScene(device);
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, mesh->positions.data(), 0,
                                   sizeof(Float3), mesh->positions.size());
        rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh->indices.data(), 0,
                                   3 * sizeof(uint32_t), mesh->triangleCount());
        rtcCommitGeometry(g);
        rtcAttachGeometry(scene, g);
        rtcReleaseGeometry(g);
        rtcCommitScene(scene);
        std::printf("build_seconds %.6f\n", secondsSince(start));
        rtcReleaseScene(scene);
        rtcReleaseDevice(device);
    } else if (mode == "compact") {
        const Scene scene = gridScene(grid(n));
        RenderOptions options;
        options.width = 320;
        options.height = 240;
        options.samplesPerPixel = 2;
        options.threads = threads;
        std::vector<double> build, trace;
        for (int r = 0; r < 3; ++r) {
            const RenderResult result = render(scene, options);
            build.push_back(result.stats.buildSeconds);
            trace.push_back(result.stats.renderSeconds);
        }
        std::sort(build.begin(), build.end());
        std::sort(trace.begin(), trace.end());
        std::printf("build_seconds %.6f\ntrace_seconds %.6f\n", build[1], trace[1]);
    } else {
        std::fprintf(stderr, "unknown mode %s\n", mode.c_str());
        return 2;
    }
    std::printf("peak_kib %ld\n", peakKiB());
    return 0;
}

struct Child {
    mutable std::map<std::string, double> values; // read with [] (0 when missing)
    double wallSeconds = 0;
    long peakKiB = 0; // the child's ru_maxrss
    bool ok = false;
    std::string err;
};

// Runs argv, collecting "key value" lines from its stdout.
Child run(const std::vector<std::string>& args) {
    Child child;
    int out[2], errPipe[2];
    if (pipe(out) != 0 || pipe(errPipe) != 0)
        return child;
    const auto start = Clock::now();
    const pid_t pid = fork();
    if (pid == 0) {
        dup2(out[1], 1);
        dup2(errPipe[1], 2);
        close(out[0]);
        close(errPipe[0]);
        std::vector<char*> argv;
        for (const std::string& a : args)
            argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        execv(argv[0], argv.data());
        _exit(127);
    }
    close(out[1]);
    close(errPipe[1]);
    std::string text, err;
    char buffer[4096];
    for (ssize_t got; (got = read(out[0], buffer, sizeof buffer)) > 0;)
        text.append(buffer, size_t(got));
    for (ssize_t got; (got = read(errPipe[0], buffer, sizeof buffer)) > 0;)
        err.append(buffer, size_t(got));
    close(out[0]);
    close(errPipe[0]);
    int status = 0;
    rusage usage{};
    wait4(pid, &status, 0, &usage);
    child.wallSeconds = secondsSince(start);
    child.peakKiB = usage.ru_maxrss;
    child.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
    child.err = err;
    size_t at = 0;
    while (at < text.size()) {
        const size_t end = text.find('\n', at);
        const std::string line = text.substr(at, end == std::string::npos ? std::string::npos : end - at);
        char key[64];
        double value = 0;
        if (std::sscanf(line.c_str(), "%63s %lf", key, &value) == 2)
            child.values[key] = value;
        if (end == std::string::npos)
            break;
        at = end + 1;
    }
    // drt render's summary: "... (build N ms, trace M ms)".
    if (const size_t b = err.find("(build "); b != std::string::npos) {
        double buildMs = 0, traceMs = 0;
        if (std::sscanf(err.c_str() + b, "(build %lf ms, trace %lf ms)", &buildMs, &traceMs) == 2) {
            child.values["build_seconds"] = buildMs / 1000;
            child.values["trace_seconds"] = traceMs / 1000;
        }
    }
    return child;
}

} // namespace

int main(int argc, char** argv) {
    std::vector<long> sizes = {1000, 100000, 1000000};
    std::vector<std::pair<std::string, std::string>> drts;
    std::string dir = "mesh-bench";
    int threads = 2;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--one" && i + 4 < argc)
            return measure(argv[i + 1], std::atol(argv[i + 2]), argv[i + 3], std::atoi(argv[i + 4]));
        if (a == "--sizes" && i + 1 < argc) {
            sizes.clear();
            for (const char* p = argv[++i]; *p;) {
                char* end = nullptr;
                sizes.push_back(std::strtol(p, &end, 10));
                p = *end == ',' ? end + 1 : end;
            }
        } else if (a == "--drt" && i + 1 < argc) {
            const std::string spec = argv[++i];
            const size_t eq = spec.find('=');
            drts.emplace_back(spec.substr(0, eq), spec.substr(eq + 1));
        } else if (a == "--dir" && i + 1 < argc) {
            dir = argv[++i];
        } else if (a == "--threads" && i + 1 < argc) {
            threads = std::atoi(argv[++i]);
        } else {
            std::fprintf(
                stderr,
                "usage: drt_mesh_bench [--sizes 1000,100000,1000000] [--drt LABEL=PATH]... [--dir DIR] "
                "[--threads T]\n");
            return 2;
        }
    }
    std::filesystem::create_directories(dir);
    const std::string self = std::filesystem::canonical("/proc/self/exe").string();
    const auto one = [&](const std::string& mode, long n) {
        return run({self, "--one", mode, std::to_string(n), dir, std::to_string(threads)});
    };
    const Child empty = one("empty", 0);
    std::printf(
        "| triangles | measure | seconds | peak bytes per triangle | note |\n|---|---|---|---|---|\n");
    std::map<long, double> traceOf;
    for (long n : sizes) {
        const bool files = n <= 2'000'000; // text and OBJ of 10M triangles would be gigabytes
        if (files)
            writeFiles(dir, n);
        const long triangles = long(grid(n)->triangleCount());
        const auto perTriangle = [&](const Child& c) {
            return double(c.peakKiB - empty.peakKiB) * 1024.0 / triangles;
        };
        const auto row = [&](const char* what, double seconds, double bytes, const std::string& note) {
            std::printf("| %ld | %s | %.3f | %.0f | %s |\n", triangles, what, seconds, bytes, note.c_str());
            std::fflush(stdout);
        };
        if (files) {
            const Child text = one("text", n);
            row("parse .drt text (front end)", text.values["seconds"], perTriangle(text),
                fmt::format("{:.1f} MB/s", text.values["mb_per_s"]));
            for (const char* format : {"obj", "ply"}) {
                const Child c = one(format, n);
                row(format == std::string("obj") ? "load OBJ (assimp)" : "load binary PLY (assimp)",
                    c.values["seconds"], perTriangle(c), c.ok ? "" : "failed: " + c.err);
            }
        }
        const Child raw = one("raw", n);
        row("BVH build, raw Embree", raw.values["build_seconds"], perTriangle(raw), "");
        const Child compact = one("compact", n);
        traceOf[n] = compact.values["trace_seconds"];
        row("BVH build, drt compact mesh", compact.values["build_seconds"], perTriangle(compact),
            fmt::format("{:.2f}x raw Embree; all included (mesh, BVH, renderer)",
                        compact.values["build_seconds"] / raw.values["build_seconds"]));
        row("trace 320x240, 2 spp", compact.values["trace_seconds"], 0,
            fmt::format("{:.2f}x the smallest size",
                        compact.values["trace_seconds"] / traceOf[sizes.front()]));
        for (const auto& [label, path] : drts) {
            if (!files)
                continue;
            for (const char* scene : {"drt", "file.drt"}) {
                const Child c =
                    run({path, "render", file(dir, n, scene), "-o", dir + "/out.png", "--width", "320",
                         "--height", "240", "--spp", "2", "--threads", std::to_string(threads)});
                const std::string what = fmt::format(
                    "{} render {}", label, scene == std::string("drt") ? "text mesh" : "mesh { file }");
                if (!c.ok) {
                    row(what.c_str(), 0, 0, "cannot read it");
                    continue;
                }
                row(what.c_str(), c.wallSeconds, perTriangle(c),
                    fmt::format("build {:.3f} s, trace {:.3f} s", c.values["build_seconds"],
                                c.values["trace_seconds"]));
            }
        }
    }
    return 0;
}
