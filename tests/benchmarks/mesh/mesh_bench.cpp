// drt_mesh_bench: the mesh figures of docs/meshes.md, measured in one run.
// For each size it generates a mesh (a height-field grid, or with --shape
// sphere a UV sphere with smooth normals; never a download), writes it as
// .drt text, OBJ and binary PLY (above 2M triangles PLY only: text and OBJ
// would be gigabytes) and measures in child processes (so each peak memory
// is its own):
//   text      parse of `mesh { triangle ... }` text by drt's front end (MB/s)
//   mesh2     parse of the same mesh as `mesh2 { vertex_vectors ... face_indices ... }` text
//   obj/ply   loading the model file into a compact mesh
//   raw       raw Embree: the same float arrays as a triangle geometry, committed
//   compact   drt: the compact mesh (made in memory) in a scene, built, traced
//   file      drt: `mesh { file }` of the PLY, loaded, built, traced: peak
//             memory all included (assimp's copy while reading, the mesh,
//             Embree's BVH, the renderer)
//   instances drt: 100 placements of the one mesh (Embree instances)
//   empty     the bare process, whose peak memory the others subtract
// and, when given drt binaries (--drt LABEL=PATH), `drt check` of both text
// scenes (CPU time, MB/s) and the whole `drt render` of the text scene (and
// of `mesh { file }` where the binary reads it) with its wall time and peak
// memory per triangle: an older binary beside a newer one compares them in
// one run.
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
#include <ctime>
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

// CPU time of this process so far (user + system, all threads).
double cpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + double(t.tv_nsec) / 1e9;
}

// Resident memory now (not the peak).
long residentKiB() {
    long pages = 0, resident = 0;
    if (FILE* f = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2)
            resident = 0;
        std::fclose(f);
    }
    return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

long peakKiB() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss;
}

bool sphereShape = false; // --shape sphere

// A mesh of about `triangles` triangles: a grid of 2 n^2, or a sphere of
// 2 r (2 r - 1) (r rings, 2 r segments).
std::shared_ptr<IndexedMesh> grid(long triangles) {
    if (sphereShape) {
        const int rings = std::max(2, int(std::lround(std::sqrt(triangles / 4.0))));
        return test::sphereMesh(rings, 2 * rings, true);
    }
    return test::gridMesh(std::max(1, int(std::lround(std::sqrt(triangles / 2.0)))));
}

std::string file(const std::string& dir, long n, const char* ext) {
    return fmt::format("{}/grid{}.{}", dir, n, ext);
}

const char* kSceneHead = "camera { location <0.5, 1.2, -0.4> look_at <0.5, 0, 0.5> angle 50 }\n"
                         "light_source { <3, 5, -2> color rgb 1 }\n";

// `withText`: also the .drt text and the OBJ (small sizes only).
void writeFiles(const std::string& dir, long n, bool withText) {
    const auto m = grid(n);
    const auto v = [&](uint32_t i) { return m->positions[i]; };
    std::ofstream(file(dir, n, "file.drt")) << kSceneHead << "mesh { file \"" << file(dir, n, "ply")
                                            << "\" pigment { color rgb <0.8, 0.7, 0.6> } }\n";
    const bool normals = !m->normals.empty();
    std::ofstream ply(file(dir, n, "ply"), std::ios::binary);
    ply << "ply\nformat binary_little_endian 1.0\nelement vertex " << m->positions.size()
        << "\nproperty float x\nproperty float y\nproperty float z\n"
        << (normals ? "property float nx\nproperty float ny\nproperty float nz\n" : "") << "element face "
        << m->triangleCount() << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (size_t i = 0; i < m->positions.size(); ++i) {
        ply.write(reinterpret_cast<const char*>(&m->positions[i]), sizeof(Float3));
        if (normals)
            ply.write(reinterpret_cast<const char*>(&m->normals[i]), sizeof(Float3));
    }
    for (size_t t = 0; t < m->triangleCount(); ++t) {
        const char three = 3;
        ply.write(&three, 1);
        ply.write(reinterpret_cast<const char*>(&m->indices[3 * t]), 3 * sizeof(uint32_t));
    }
    if (!withText)
        return;
    std::string text = kSceneHead;
    text += "mesh {\n";
    for (size_t t = 0; t < m->triangleCount(); ++t) {
        const auto tri = m->triangle(t);
        if (normals) {
            const auto n = [&](uint32_t i) { return m->normals[i]; };
            text += fmt::format(
                "  smooth_triangle {{ <{},{},{}>, <{},{},{}>, <{},{},{}>, <{},{},{}>, <{},{},{}>, "
                "<{},{},{}> }}\n",
                v(tri[0]).x, v(tri[0]).y, v(tri[0]).z, n(tri[0]).x, n(tri[0]).y, n(tri[0]).z, v(tri[1]).x,
                v(tri[1]).y, v(tri[1]).z, n(tri[1]).x, n(tri[1]).y, n(tri[1]).z, v(tri[2]).x, v(tri[2]).y,
                v(tri[2]).z, n(tri[2]).x, n(tri[2]).y, n(tri[2]).z);
        } else {
            text += fmt::format("  triangle {{ <{},{},{}>, <{},{},{}>, <{},{},{}> }}\n", v(tri[0]).x,
                                v(tri[0]).y, v(tri[0]).z, v(tri[1]).x, v(tri[1]).y, v(tri[1]).z, v(tri[2]).x,
                                v(tri[2]).y, v(tri[2]).z);
        }
    }
    text += "  pigment { color rgb <0.8, 0.7, 0.6> }\n}\n";
    std::ofstream(file(dir, n, "drt")) << text;
    std::string mesh2 = fmt::format("{}mesh2 {{\n  vertex_vectors {{ {}", kSceneHead, m->positions.size());
    for (const Float3& p : m->positions)
        mesh2 += fmt::format(",\n    <{},{},{}>", p.x, p.y, p.z);
    if (normals) {
        mesh2 += fmt::format("\n  }}\n  normal_vectors {{ {}", m->normals.size());
        for (const Float3& p : m->normals)
            mesh2 += fmt::format(",\n    <{},{},{}>", p.x, p.y, p.z);
    }
    mesh2 += fmt::format("\n  }}\n  face_indices {{ {}", m->triangleCount());
    for (size_t t = 0; t < m->triangleCount(); ++t) {
        const auto tri = m->triangle(t);
        mesh2 += fmt::format(",\n    <{},{},{}>", tri[0], tri[1], tri[2]);
    }
    mesh2 += "\n  }\n  pigment { color rgb <0.8, 0.7, 0.6> }\n}\n";
    std::ofstream(file(dir, n, "mesh2.drt")) << mesh2;
    std::string obj;
    for (const Float3& p : m->positions)
        obj += fmt::format("v {} {} {}\n", p.x, p.y, p.z);
    for (const Float3& p : m->normals)
        obj += fmt::format("vn {} {} {}\n", p.x, p.y, p.z);
    for (size_t t = 0; t < m->triangleCount(); ++t) {
        const auto tri = m->triangle(t);
        if (normals)
            obj += fmt::format("f {0}//{0} {1}//{1} {2}//{2}\n", tri[0] + 1, tri[1] + 1, tri[2] + 1);
        else
            obj += fmt::format("f {} {} {}\n", tri[0] + 1, tri[1] + 1, tri[2] + 1);
    }
    std::ofstream(file(dir, n, "obj")) << obj;
}

// The mesh placed `copies` times (1, or a 10 x 10 layout of copies scaled to
// a tenth, covering what one covers), or read from `modelFile`.
Scene gridScene(std::shared_ptr<const IndexedMesh> mesh, int copies = 1, const std::string& modelFile = "") {
    Scene scene;
    scene.camera.location = {0.5, 1.2, -0.4};
    scene.camera.lookAt = Vec3{0.5, 0, 0.5};
    scene.camera.angle = 50;
    Light light;
    light.position = {3, 5, -2};
    scene.lights.push_back(light);
    Object o;
    Mesh m;
    if (modelFile.empty()) {
        m.indexed = std::move(mesh);
    } else {
        auto source = std::make_shared<MeshSource>();
        source->kind = MeshSource::Kind::ModelFile;
        source->path = modelFile;
        m.source = source;
    }
    o.shape = m;
    o.texture.edit().pigment.color = ColorFT{Color(0.8, 0.7, 0.6), 0, 0};
    if (copies == 1) {
        scene.objects.push_back(o);
        return scene;
    }
    for (int i = 0; i < 10; ++i)
        for (int j = 0; j < copies / 10; ++j) {
            o.transform = Transform::scale({0.1, 0.1, 0.1}).then(Transform::translate({0.1 * i, 0, 0.1 * j}));
            scene.objects.push_back(o);
        }
    return scene;
}

// Renders `scene` three times at 320 x 240, 2 spp; prints the median build and
// trace times.
void renderThrice(const Scene& scene, int threads) {
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
}

// One measurement in this (child) process; prints "key value" lines.
int measure(const std::string& mode, long n, const std::string& dir, int threads) {
    const long startKiB = peakKiB();
    std::printf("start_kib %ld\n", startKiB);
    if (mode == "empty")
        return 0;
    if (mode == "text" || mode == "mesh2") {
        const std::string path = file(dir, n, mode == "text" ? "drt" : "mesh2.drt");
        Diagnostics diags;
        const auto start = Clock::now();
        const double cpuStart = cpuSeconds();
        const auto scene = loadSceneFile(path, diags);
        const double s = secondsSince(start), cpu = cpuSeconds() - cpuStart;
        if (!scene)
            return 1;
        std::printf("seconds %.6f\ncpu_seconds %.6f\nmb_per_s %.2f\n", s, cpu,
                    double(std::filesystem::file_size(path)) / 1e6 / cpu);
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
        std::printf("seconds %.6f\nresident_kib %ld\n", secondsSince(start), residentKiB());
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
    } else if (mode == "compact" || mode == "instances") {
        renderThrice(gridScene(grid(n), mode == "compact" ? 1 : 100), threads);
    } else if (mode == "file") {
        Scene scene = gridScene(nullptr, 1, file(dir, n, "ply"));
        Diagnostics diags;
        const auto start = Clock::now();
        if (!resolveAssets(scene, diags))
            return 1;
        std::printf("load_seconds %.6f\n", secondsSince(start));
        renderThrice(scene, threads);
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
    double cpuSeconds = 0; // user + system
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
    child.cpuSeconds = double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                       double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) / 1e6;
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
    // drt render's summary: "... (build N ms, trace M s)" (each in ms or s).
    if (const size_t b = err.find("(build "); b != std::string::npos) {
        double build = 0, trace = 0;
        char buildUnit[4] = "", traceUnit[4] = "";
        if (std::sscanf(err.c_str() + b, "(build %lf %3[ms], trace %lf %3[ms])", &build, buildUnit, &trace,
                        traceUnit) == 4) {
            child.values["build_seconds"] = buildUnit == std::string("ms") ? build / 1000 : build;
            child.values["trace_seconds"] = traceUnit == std::string("ms") ? trace / 1000 : trace;
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
        } else if (a == "--shape" && i + 1 < argc &&
                   (argv[i + 1] == std::string("sphere") || argv[i + 1] == std::string("grid"))) {
            sphereShape = argv[++i] == std::string("sphere");
        } else {
            std::fprintf(
                stderr,
                "usage: drt_mesh_bench [--sizes 1000,100000,1000000] [--drt LABEL=PATH]... [--dir DIR] "
                "[--threads T] [--shape grid|sphere]\n");
            return 2;
        }
    }
    std::filesystem::create_directories(dir);
    const std::string self = std::filesystem::canonical("/proc/self/exe").string();
    const auto one = [&](const std::string& mode, long n) {
        return run({self, "--one", mode, std::to_string(n), dir, std::to_string(threads)});
    };
    const Child empty = one("empty", 0);
    // Each drt binary's peak on a scene without the mesh (camera and light),
    // which its rows subtract.
    std::ofstream(dir + "/empty.drt") << kSceneHead;
    std::map<std::string, long> emptyKiBOf, emptyCheckKiBOf;
    for (const auto& [label, path] : drts)
        emptyCheckKiBOf[label] = run({path, "check", dir + "/empty.drt"}).peakKiB;
    for (const auto& [label, path] : drts)
        emptyKiBOf[label] = run({path, "render", dir + "/empty.drt", "-o", dir + "/out.png", "--width", "32",
                                 "--height", "24", "--spp", "1"})
                                .peakKiB;
    std::printf(
        "| triangles | measure | seconds | peak bytes per triangle | note |\n|---|---|---|---|---|\n");
    std::map<long, double> traceOf;
    for (long n : sizes) {
        const bool text = n <= 2'000'000; // text and OBJ of 10M triangles would be gigabytes
        writeFiles(dir, n, text);
        const long triangles = long(grid(n)->triangleCount());
        const auto perTriangle = [&](const Child& c) {
            return double(c.peakKiB - empty.peakKiB) * 1024.0 / triangles;
        };
        const auto row = [&](const char* what, double seconds, double bytes, const std::string& note) {
            std::printf("| %ld | %s | %.3f | %.0f | %s |\n", triangles, what, seconds, bytes, note.c_str());
            std::fflush(stdout);
        };
        const auto failed = [](const Child& c) { return c.ok ? std::string() : "failed: " + c.err; };
        if (text) {
            const Child c = one("text", n);
            row("parse `mesh { triangle }` text (front end)", c.values["cpu_seconds"], perTriangle(c),
                fmt::format("CPU time; {:.1f} MB/s; wall {:.3f} s", c.values["mb_per_s"], c.values["seconds"]) +
                    failed(c));
            const Child c2 = one("mesh2", n);
            row("parse `mesh2` text (front end)", c2.values["cpu_seconds"], perTriangle(c2),
                fmt::format("CPU time; {:.1f} MB/s; wall {:.3f} s", c2.values["mb_per_s"], c2.values["seconds"]) +
                    failed(c2));
            for (const auto& [label, path] : drts)
                for (const char* scene : {"drt", "mesh2.drt"}) {
                    const std::string name = file(dir, n, scene);
                    const Child check = run({path, "check", name});
                    const std::string what = fmt::format("`{} check` {} text", label,
                                                         scene == std::string("drt") ? "mesh" : "mesh2");
                    row(what.c_str(), check.cpuSeconds,
                        double(check.peakKiB - emptyCheckKiBOf[label]) * 1024.0 / triangles,
                        check.ok ? fmt::format("CPU time; {:.1f} MB/s; wall {:.2f} s",
                                               double(std::filesystem::file_size(name)) / 1e6 / check.cpuSeconds,
                                               check.wallSeconds)
                                 : "failed: " + check.err);
                }
        }
        for (const char* format : {"obj", "ply"}) {
            if (format == std::string("obj") && !text)
                continue;
            const Child c = one(format, n);
            row(format == std::string("obj") ? "load OBJ (assimp)" : "load binary PLY (assimp)",
                c.values["seconds"], perTriangle(c),
                fmt::format("CPU {:.3f} s; resident after {:.0f} B/tri", c.cpuSeconds,
                            (c.values["resident_kib"] - double(empty.peakKiB)) * 1024.0 / triangles) +
                    failed(c));
        }
        const Child raw = one("raw", n);
        row("BVH build, raw Embree", raw.values["build_seconds"], perTriangle(raw), failed(raw));
        const Child compact = one("compact", n);
        traceOf[n] = compact.values["trace_seconds"];
        row("BVH build, drt (mesh made in memory)", compact.values["build_seconds"], perTriangle(compact),
            fmt::format("{:.2f}x raw Embree; peak: mesh, BVH, renderer",
                        compact.values["build_seconds"] / raw.values["build_seconds"]) +
                failed(compact));
        row("trace 320x240, 2 spp", compact.values["trace_seconds"], 0,
            fmt::format("{:.2f}x the smallest size",
                        compact.values["trace_seconds"] / traceOf[sizes.front()]));
        const Child fromFile = one("file", n);
        row("render `mesh { file }` of the PLY: load + build + trace",
            fromFile.values["load_seconds"] + fromFile.values["build_seconds"] +
                fromFile.values["trace_seconds"],
            perTriangle(fromFile),
            fmt::format("load {:.3f} s, build {:.3f} s, trace {:.3f} s; peak all included",
                        fromFile.values["load_seconds"], fromFile.values["build_seconds"],
                        fromFile.values["trace_seconds"]) +
                failed(fromFile));
        const Child copies = one("instances", n);
        row("100 placements of the mesh: build", copies.values["build_seconds"], perTriangle(copies),
            fmt::format("peak {:.2f}x one placement's; trace {:.3f} s",
                        double(copies.peakKiB - empty.peakKiB) / double(compact.peakKiB - empty.peakKiB),
                        copies.values["trace_seconds"]) +
                failed(copies));
        for (const auto& [label, path] : drts) {
            for (const char* scene : {"drt", "file.drt"}) {
                if (scene == std::string("drt") && !text)
                    continue;
                const Child c =
                    run({path, "render", file(dir, n, scene), "-o", dir + "/out.png", "--width", "320",
                         "--height", "240", "--spp", "2", "--threads", std::to_string(threads)});
                const std::string what = fmt::format(
                    "`{} render` {}", label, scene == std::string("drt") ? "text mesh" : "mesh { file }");
                if (!c.ok) {
                    row(what.c_str(), 0, 0, "cannot read it");
                    continue;
                }
                row(what.c_str(), c.wallSeconds, double(c.peakKiB - emptyKiBOf[label]) * 1024.0 / triangles,
                    fmt::format("wall time; build {:.3f} s, trace {:.3f} s; peak over the empty scene's",
                                c.values["build_seconds"], c.values["trace_seconds"]));
            }
        }
    }
    return 0;
}
