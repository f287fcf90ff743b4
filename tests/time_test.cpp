// Time beyond object motion: moving cameras and lights, the animation
// identifiers in both dialects, frames and their clocks, POV-Ray .ini files,
// motion from a scene's own clock dependence, and `drt render --frames`.
#include "animation/animation.h"
#include "animation/ini.h"
#include "cli/app.h"
#include "cli/commands.h"
#include "image/image.h"
#include "lang/load.h"
#include "lang/writer.h"
#include "pov/load.h"
#include "render/camera_path.h"
#include "render/light_path.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace drt {
namespace {

void expectNear(const Vec3& a, const Vec3& b, double tolerance = 1e-9) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

// The scene in the dialect `name`'s extension selects, at clock `frame`.
Scene parseAs(const std::string& name, const std::string& text, const FrameClock& frame) {
    Diagnostics d;
    LoadOptions o;
    o.frame = frame;
    std::optional<Scene> s = loadSceneText(text, name, d, o);
    EXPECT_FALSE(d.hasErrors()) << d.formatAll();
    return s ? *s : Scene{};
}
Scene parseDrt(const std::string& text, const FrameClock& frame = {}) { return parseAs("t.drt", text, frame); }
Scene parsePov(const std::string& text, const FrameClock& frame = {}) { return parseAs("t.pov", text, frame); }

RenderOptions small(int spp = 4) {
    RenderOptions o;
    o.width = 24;
    o.height = 18;
    o.samplesPerPixel = spp;
    o.seed = 3;
    return o;
}

// ---------------------------------------------------------------- syntax

TEST(Time, CameraAndLightMotionInBothDialects) {
    const std::string drt = "camera { location <0, 1, -5> look_at <0, 1, 0> translate <1, 0, 0> "
                            "motion { rotate y*30 } translate <0, 2, 0> shutter_open 0 shutter_close 1 }\n"
                            "light_source { <0, 5, 0>, rgb 1 translate x motion { translate <4, 0, 0> } "
                            "area_light x, z, 2, 2 }\n";
    const std::string pov = "camera { location <0, 1, -5> look_at <0, 1, 0> translate <1, 0, 0> "
                            "motion { rotate y*30 } translate <0, 2, 0> }\n"
                            "light_source { <0, 5, 0>, rgb 1 translate x motion { translate <4, 0, 0> } "
                            "area_light x, z, 2, 2 }\n";
    for (const Scene& s : {parseDrt(drt), parsePov(pov)}) {
        ASSERT_EQ(s.camera.motion.size(), 1u);
        // The transform before the motion places the camera; the motion and
        // the transform after it move it over time.
        const CameraPath path(s, 40, 30);
        expectNear(path.at(0).location, {1, 3, -5});
        expectNear(path.at(1).location, Transform::rotate({0, 30, 0}).point({1, 1, -5}) + Vec3{0, 2, 0});
        ASSERT_EQ(s.lights.size(), 1u);
        ASSERT_TRUE(lightMoves(s.lights[0]));
        expectNear(lightAt(s.lights[0], 0).position, {1, 5, 0});
        expectNear(lightAt(s.lights[0], 0.5).position, {3, 5, 0});
        EXPECT_FALSE(lightMoves(lightAt(s.lights[0], 0.5)));
    }
}

TEST(Time, ConvertKeepsCameraAndLightMotion) {
    // A POV-Ray scene's moving camera and lights, written as .drt and read
    // back: the same poses at every time.
    const Scene pov = parsePov("camera { location <0, 1, -5> look_at <0, 1, 0> translate <1, 0, 0> "
                               "motion { at 0.5 rotate y*20 at 1 rotate y*50 translate x } translate <0, 2, 0> "
                               "shutter_open 0 shutter_close 1 }\n"
                               "light_source { <0, 5, 0>, rgb 1 area_light x, z, 2, 2 motion { rotate y*90 } "
                               "translate z }\n"
                               "union { light_source { <1, 4, 0>, rgb 0.5 motion { translate x } } "
                               "sphere { 0, 1 } translate y }\n");
    const std::string text = writeDrtScene(pov);
    const Scene drt = parseDrt(text);
    ASSERT_EQ(drt.lights.size(), 2u) << text;
    const CameraPath a(pov, 40, 30), b(drt, 40, 30);
    for (double t : {0.0, 0.3, 0.5, 0.8, 1.0}) {
        expectNear(a.at(t).location, b.at(t).location);
        expectNear(a.at(t).direction, b.at(t).direction);
        expectNear(a.at(t).up, b.at(t).up);
        for (size_t i = 0; i < 2; ++i) {
            expectNear(lightAt(pov.lights[i], t).position, lightAt(drt.lights[i], t).position);
        }
        expectNear(lightAt(drt.lights[0], t).area->axis1, Transform::rotate({0, 90 * t, 0}).vector({1, 0, 0}));
    }
    // A light in a union: the union's transform goes after the light's motion.
    expectNear(lightAt(drt.lights[1], 1).position, {2, 5, 0});
    // The looks_like shape of a moving light moves with it.
    const Scene looks = parsePov("light_source { <0, 3, 0>, rgb 1 looks_like { sphere { 0, 0.2 } } "
                                 "motion { translate x } translate y }\n");
    ASSERT_EQ(looks.objects.size(), 1u);
    const Object& shape = looks.objects[0];
    expectNear(placementAt(shape.transform, shape.motion, 1).point({0, 0, 0}), lightAt(looks.lights[0], 1).position);
}

TEST(Time, CameraAndLightMotionErrorsAreLocated) {
    const auto firstError = [](const std::string& text, const std::string& name) {
        Diagnostics d;
        EXPECT_FALSE(loadSceneText(text, name, d, LoadOptions{}));
        return d.all().empty() ? std::string() : d.formatAll();
    };
    EXPECT_NE(firstError("camera { location <0, 0, -5>\n  motion { at 1.5 rotate y*10 } }\n", "c.drt")
                  .find("c.drt:2:15: error: motion key times must be in [0, 1]"),
              std::string::npos);
    EXPECT_NE(firstError("light_source { <0, 5, 0>, rgb 1 motion { wobble x } }\n", "l.drt")
                  .find("l.drt:1:42: error:"),
              std::string::npos);
    EXPECT_NE(firstError("light_source { <0, 3, 0>, rgb 1 motion { translate x }\n  looks_like { sphere { 0, 1 } } }\n",
                         "k.pov")
                  .find("k.pov:2:3: error: 'looks_like' after 'motion'"),
              std::string::npos);
}

TEST(Time, ObjectMotionInThePovDialect) {
    const Scene s = parsePov("sphere { <3, 0, 0>, 1 translate <-3, 0, 0> motion { at 0.5 rotate y*180 at 1 rotate "
                             "y*360 } translate <3, 0, 0> }\n"
                             "union { sphere { 0, 1 motion { translate x } } translate y }\n");
    ASSERT_EQ(s.objects.size(), 2u);
    const Object& o = s.objects[0];
    ASSERT_EQ(o.motion.size(), 1u);
    EXPECT_EQ(o.motion[0].motion.keys.size(), 3u);
    expectNear(placementAt(o.transform, o.motion, 0.25).point({3, 0, 0}), {3, 0, 0}); // spins about its centre
    // A union holding a moving member becomes its members, each with the
    // union's transforms after its own motion.
    const Object& member = s.objects[1];
    ASSERT_EQ(member.motion.size(), 1u);
    expectNear(placementAt(member.transform, member.motion, 1).point({0, 0, 0}), {1, 1, 0});
}

TEST(Time, ClockIdentifiersInBothDialects) {
    FrameClock f;
    f.clock = 0.25;
    f.clockDelta = 0.125;
    f.clockOn = true;
    f.frameNumber = 3;
    f.initialFrame = 1;
    f.finalFrame = 9;
    f.initialClock = -1;
    f.finalClock = 2;
    const std::string body = "sphere { <clock, clock_delta, clock_on>, 1 }\n"
                             "sphere { <frame_number, initial_frame, final_frame>, 1 }\n"
                             "sphere { <initial_clock, final_clock, 0>, 1 }\n";
    for (const Scene& s : {parseDrt(body, f), parsePov(body, f)}) {
        ASSERT_EQ(s.objects.size(), 3u);
        expectNear(std::get<Sphere>(s.objects[0].shape).center, {0.25, 0.125, 1});
        expectNear(std::get<Sphere>(s.objects[1].shape).center, {3, 1, 9});
        expectNear(std::get<Sphere>(s.objects[2].shape).center, {-1, 2, 0});
        EXPECT_TRUE(s.readsClock);
    }
    // A scene that reads only the frame number does not read the clock.
    EXPECT_FALSE(parseDrt("sphere { <frame_number, 0, 0>, 1 }", f).readsClock);
    EXPECT_FALSE(parsePov("sphere { <frame_number, 0, 0>, 1 }", f).readsClock);
    // Still-image defaults (POV-Ray's).
    const Scene d = parseDrt("sphere { <clock, clock_delta, frame_number>, 1 }");
    expectNear(std::get<Sphere>(d.objects[0].shape).center, {0, 1, 0});
    // A #declare'd name wins in .drt (older scenes may use the word).
    EXPECT_EQ(std::get<Sphere>(parseDrt("#declare clock = 5;\nsphere { <clock, 0, 0>, 1 }").objects[0].shape).center.x, 5);
}

// ---------------------------------------------------------------- zero-length shutters

TEST(Time, ZeroLengthShutterIsTheStillCameraAndLightsBitForBit) {
    const std::string moving = "camera { location <0, 1.5, -5> look_at <0, 0.5, 0> angle 50 "
                               "motion { at 0.5 rotate y*10 translate <0.3, 0, 0> at 1 rotate y*25 } "
                               "shutter_open 0.4 shutter_close 0.4 }\n"
                               "light_source { <-3, 5, -3>, rgb 1 area_light x*2, z*2, 3, 3 "
                               "motion { rotate y*40 translate <1, 0, 0> } }\n"
                               "plane { y, 0 pigment { checker rgb 1, rgb 0.2 } }\n"
                               "sphere { <0, 0.5, 0>, 0.5 pigment { rgb <1, 0.3, 0.2> } }\n";
    Scene a = parseDrt(moving);
    // The same camera and light placed still where they are at time 0.4.
    Scene b = a;
    b.camera.transform = placementAt(a.camera.transform, a.camera.motion, 0.4);
    b.camera.motion.clear();
    b.lights[0] = lightAt(a.lights[0], 0.4);
    const RenderResult ra = render(a, small()), rb = render(b, small());
    EXPECT_EQ(ra.color.pixels, rb.color.pixels);
    EXPECT_EQ(ra.variance.pixels, rb.variance.pixels);
    EXPECT_FALSE(ra.stats.effects.motionBlur);
    // With the shutter open they move, and the image changes.
    a.camera.shutterClose = 1;
    const RenderResult open = render(a, small());
    EXPECT_TRUE(open.stats.effects.motionBlur);
    EXPECT_NE(open.color.pixels, ra.color.pixels);
}

TEST(Time, CameraKeysInterpolateTheCameraAsWritten) {
    Scene s;
    s.camera.location = {0, 0, -5};
    s.camera.lookAt = Vec3{0, 0, 0};
    s.camera.angle = 40;
    CameraSpec later = s.camera;
    later.location = {2, 0, -5};
    later.angle = 60;
    later.aperture = 0.2;
    s.cameraKeys = {{0, s.camera}, {1, later}};
    s.camera.shutterClose = 1;
    const CameraPath path(s, 40, 30);
    EXPECT_TRUE(path.moving());
    EXPECT_TRUE(path.hasLens());
    const ResolvedCamera mid = path.at(0.5);
    expectNear(mid.location, {1, 0, -5});
    EXPECT_NEAR(mid.lensRadius, 0.05, 1e-12);
    // angle 50 at the middle: |direction| = 0.5 |right| / tan(25 degrees).
    EXPECT_NEAR(length(mid.direction), 0.5 * length(mid.right) / std::tan(25 * kPi / 180), 1e-9);
}

// ---------------------------------------------------------------- frames

TEST(Time, FrameClocksFollowPovRay) {
    Animation a;
    a.initialFrame = 0;
    a.finalFrame = 9;
    a.initialClock = 0;
    a.finalClock = 1;
    for (int k = 0; k <= 9; ++k) {
        const FrameClock f = frameClockOf(a, k);
        EXPECT_EQ(f.clock, 1.0 * k / 9); // exactly the one-frame clock k/9
        EXPECT_EQ(f.clockDelta, 1.0 / 9);
        EXPECT_EQ(f.frameNumber, k);
        EXPECT_TRUE(f.clockOn);
    }
    a.cyclic = true; // the last frame stops a step short
    EXPECT_DOUBLE_EQ(frameClockOf(a, 9).clock, 0.9);
    a.subsetStart = 3;
    a.subsetEnd = 20;
    EXPECT_EQ(firstRenderedFrame(a), 3);
    EXPECT_EQ(lastRenderedFrame(a), 9);
    EXPECT_EQ(animationProblem(a), "");
    a.subsetStart = 12;
    EXPECT_NE(animationProblem(a).find("holds no frame"), std::string::npos);
    Animation backwards;
    backwards.initialFrame = 5;
    backwards.finalFrame = 2;
    EXPECT_NE(animationProblem(backwards).find("before the initial frame"), std::string::npos);
}

TEST(Time, FrameFileNames) {
    EXPECT_EQ(frameFileName("out_%04d.png", 7, 119), "out_0007.png");
    EXPECT_EQ(frameFileName("f%d.exr", 12, 99), "f12.exr");
    EXPECT_EQ(frameFileName("dir.v2/anim.png", 7, 119), "dir.v2/anim007.png"); // POV-Ray's numbering
    EXPECT_EQ(frameFileName("anim", 3, 10), "anim03");
    EXPECT_EQ(frameFileName("100%%_%02d.png", 4, 10), "100%_04.png");
    EXPECT_TRUE(isFramePattern("a%03d.png"));
    EXPECT_FALSE(isFramePattern("a%s.png"));
    EXPECT_FALSE(isFramePattern("a%d_%d.png"));
    EXPECT_FALSE(isFramePattern("plain.png"));
}

TEST(Time, IniFilesGiveTheAnimation) {
    Diagnostics d;
    const std::optional<IniSettings> ini =
        readIniText("; an animation\n[scene]\nInput_File_Name=spin.pov\nOutput_File_Name = frames/spin.png\n"
                    "Width=64\nheight=48\nInitial_Frame=1\nFinal_Frame=30\nInitial_Clock=0\nFinal_Clock=2\n"
                    "Subset_Start_Frame=0.5\n+EF25\nCyclic_Animation=on\nAntialias=on\n+L/opt/inc\n",
                    "a.ini", d, "/scenes");
    ASSERT_TRUE(ini) << d.formatAll();
    EXPECT_EQ(*ini->input, "/scenes/spin.pov");
    EXPECT_EQ(*ini->output, "/scenes/frames/spin.png");
    EXPECT_EQ(*ini->width, 64);
    EXPECT_EQ(*ini->height, 48);
    EXPECT_EQ(ini->libraryPaths, std::vector<std::string>{"/opt/inc"});
    Animation a;
    EXPECT_TRUE(applyIni(*ini, a));
    EXPECT_EQ(a.initialFrame, 1);
    EXPECT_EQ(a.finalFrame, 30);
    EXPECT_EQ(a.finalClock, 2);
    EXPECT_TRUE(a.cyclic);
    EXPECT_EQ(*a.subsetStart, 16); // half way through frames 1..30, rounded
    EXPECT_EQ(*a.subsetEnd, 25);
    EXPECT_EQ(d.warningCount(), 1); // Antialias is ignored, with a warning
    // Bad values: the line and column of the value.
    Diagnostics bad;
    EXPECT_FALSE(readIniText("Final_Frame=ten\n", "b.ini", bad));
    ASSERT_EQ(bad.all().size(), 1u);
    EXPECT_EQ(bad.all()[0].loc.line, 1);
    EXPECT_EQ(bad.all()[0].loc.column, 13);
    EXPECT_NE(bad.all()[0].message.find("needs a number"), std::string::npos);
    Diagnostics missing;
    EXPECT_FALSE(readIniFile("/no/such/file.ini", missing));
    EXPECT_TRUE(missing.hasErrors());
}

// ---------------------------------------------------------------- motion from the clock

SceneEvaluator textEvaluator(const std::string& text, bool pov = false) {
    return [text, pov](const FrameClock& frame, Diagnostics& d) -> std::optional<Scene> {
        LoadOptions o;
        o.frame = frame;
        return loadSceneText(text, pov ? "t.pov" : "t.drt", d, o);
    };
}

TEST(Time, MotionFromTheClockFollowsTheScene) {
    // A ball moved with the clock, one turned about a centre, one whose centre
    // is computed from the clock; the shutter is half the frame interval.
    const std::string text = "camera { location <0, 2, -8> look_at <0, 0, 0> shutter_open 0 shutter_close 0.5 }\n"
                             "light_source { <clock * 4, 5, 0>, rgb 1 }\n"
                             "sphere { 0, 0.5 translate <clock * 2, 0, 0> }\n"
                             "sphere { <2, 0, 0>, 0.3 rotate y * 360 * clock }\n"
                             "sphere { <cos(clock * pi), sin(clock * pi), 0>, 0.2 }\n"
                             "box { -1, 1 translate <0, -3, 0> }\n";
    FrameClock f;
    f.clock = 0.25;
    f.clockDelta = 0.5;
    Diagnostics d;
    FrameReport report;
    const std::optional<Scene> s = evaluateFrame(textEvaluator(text), f, {}, d, &report);
    ASSERT_TRUE(s) << d.formatAll();
    EXPECT_EQ(report.objectsFromClock, 3);
    EXPECT_EQ(report.lightsFromClock, 1);
    EXPECT_FALSE(report.cameraFromClock);
    EXPECT_TRUE(report.unpaired.empty());
    EXPECT_GE(report.evaluations, 5);
    EXPECT_TRUE(s->objects[3].motion.empty()); // the box does not move
    // Scene time t is clock 0.25 + 0.5 t.
    for (double t : {0.0, 0.1, 0.25, 0.4, 0.5}) {
        const double clock = 0.25 + 0.5 * t;
        const Object& a = s->objects[0];
        expectNear(placementAt(a.transform, a.motion, t).point({0, 0, 0}), {clock * 2, 0, 0}, 1e-9);
        const Object& b = s->objects[1];
        // An orbit is followed exactly (the path turns about its straightest point).
        expectNear(placementAt(b.transform, b.motion, t).point({2, 0, 0}),
                   Transform::rotate({0, 360 * clock, 0}).point({2, 0, 0}), 1e-6);
        const Object& c = s->objects[2];
        // A centre computed from the clock: a translation path through the
        // samples, within the 1e-3 of the size the sampling promises.
        expectNear(placementAt(c.transform, c.motion, t).point(std::get<Sphere>(c.shape).center),
                   {std::cos(clock * kPi), std::sin(clock * kPi), 0}, 1e-3 * 0.4 * std::sqrt(3.0));
        expectNear(lightAt(s->lights[0], t).position, {clock * 4, 5, 0}, 1e-9);
    }
}

TEST(Time, MotionFromTheClockInThePovDialectAndWhatCannotBePaired) {
    const std::string text = "camera { location <clock, 2, -8> look_at <0, 0, 0> }\n"
                             "#if (clock < 0.3) sphere { 0, 1 } #end\n"
                             "torus { 1 + clock, 0.2 }\n"
                             "#declare I = 0;\n#while (I < 3) sphere { <I, clock, 0>, 0.2 } #declare I = I + 1; #end\n";
    FrameClock f;
    f.clock = 0.2;
    f.clockDelta = 1;
    FrameOptions shutter;
    shutter.shutter = 0.5;
    Diagnostics d;
    FrameReport report;
    const std::optional<Scene> s = evaluateFrame(textEvaluator(text, true), f, shutter, d, &report);
    ASSERT_TRUE(s) << d.formatAll();
    EXPECT_TRUE(report.cameraFromClock);
    EXPECT_EQ(s->camera.shutterClose, 0.5);
    ASSERT_GE(s->cameraKeys.size(), 3u);
    // The loop's spheres pair by their order at one place in the text.
    EXPECT_EQ(report.objectsFromClock, 3);
    ASSERT_EQ(s->objects.size(), 5u);
    for (int i = 2; i < 5; ++i) {
        const Object& o = s->objects[i];
        expectNear(placementAt(o.transform, o.motion, 0.5).point(std::get<Sphere>(o.shape).center),
                   {double(i - 2), 0.7, 0}, 1e-9);
    }
    // The sphere vanishes at clock 0.3 and the torus changes shape: both held still, and named.
    ASSERT_EQ(report.unpaired.size(), 2u);
    EXPECT_NE(report.unpaired[0].find("2:"), std::string::npos);
    EXPECT_NE(report.unpaired[0].find("absent"), std::string::npos);
    EXPECT_NE(report.unpaired[1].find("shape changes"), std::string::npos);
    EXPECT_TRUE(s->objects[0].motion.empty());
    EXPECT_TRUE(s->objects[1].motion.empty());
    // No shutter: one evaluation, the scene as it is.
    FrameReport still;
    ASSERT_TRUE(evaluateFrame(textEvaluator(text, true), f, {}, d, &still));
    EXPECT_EQ(still.evaluations, 1);
}

TEST(Time, AnEvaluationFailingWithinTheShutterIsAnError) {
    const std::string text = "camera { location <0, 0, -5> shutter_open 0 shutter_close 1 }\n"
                             "sphere { 0, 1 - clock }\n"; // radius 0 at clock 1
    Diagnostics d;
    const std::optional<Scene> s = evaluateFrame(textEvaluator(text), FrameClock{}, {}, d);
    EXPECT_FALSE(s && !d.hasErrors());
    EXPECT_NE(d.formatAll().find("evaluated at clock 1"), std::string::npos) << d.formatAll();
}

// ---------------------------------------------------------------- drt render --frames

struct TempDir {
    fs::path path = fs::temp_directory_path() / fmt::format("drt-time-test-{}", ::getpid());
    TempDir() { fs::create_directories(path); }
    ~TempDir() { fs::remove_all(path); }
};

// The pixels of an image file (its metadata holds the render time, so the
// files themselves differ).
std::vector<float> filePixels(const fs::path& p) {
    Image image;
    const std::string problem = readImage(p.string(), image);
    EXPECT_EQ(problem, "") << p;
    EXPECT_FALSE(image.pixels.empty()) << p;
    return image.pixels;
}

int renderCli(std::vector<std::string> args, std::string* errors = nullptr) {
    args.insert(args.begin(), {"drt", "render"});
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    testing::internal::CaptureStderr();
    const int status = cli::runCommandLine(static_cast<int>(argv.size()), argv.data());
    const std::string err = testing::internal::GetCapturedStderr();
    if (errors) *errors = err;
    return status;
}

TEST(Time, FrameKOfARunIsTheOneFrameRenderAtItsClockByteForByte) {
    TempDir dir;
    const fs::path scene = dir.path / "anim.drt";
    std::ofstream(scene) << "render { width 24 height 18 samples 4 }\n"
                            "camera { location <0, 1, -5> look_at <0, 0.5, 0> }\n"
                            "light_source { <-3, 5, -3>, rgb 1 }\n"
                            "sphere { <0, 0.5, 0>, 0.5 pigment { rgb <1, 0.4, 0.2> } translate <clock * 2 - 1, 0, 0> }\n"
                            "box { <-2, -0.1, -1>, <2, 0, 3> pigment { checker rgb 1, rgb 0.3 } rotate y * 90 * clock }\n";
    ASSERT_EQ(renderCli({scene.string(), "-o", (dir.path / "f_%02d.exr").string(), "--frames", "0..9", "--clock", "0..1",
                         "-q"}),
              0);
    for (int k = 0; k <= 9; ++k) ASSERT_TRUE(fs::exists(dir.path / fmt::format("f_{:02d}.exr", k))) << k;
    // Whatever the thread count and tile size.
    ASSERT_EQ(renderCli({scene.string(), "-o", (dir.path / "t_%02d.exr").string(), "--frames", "0..9", "--clock",
                         "0..1", "--threads", "1", "--tile-size", "5", "-q"}),
              0);
    for (int k = 0; k <= 9; ++k)
        EXPECT_EQ(filePixels(dir.path / fmt::format("t_{:02d}.exr", k)),
                  filePixels(dir.path / fmt::format("f_{:02d}.exr", k)))
            << k;
    for (int k : {0, 4, 9}) {
        const fs::path one = dir.path / fmt::format("one_{}.exr", k);
        ASSERT_EQ(renderCli({scene.string(), "-o", one.string(), "--clock", fmt::format("{:.17g}", k / 9.0), "-q"}), 0);
        EXPECT_EQ(filePixels(one), filePixels(dir.path / fmt::format("f_{:02d}.exr", k))) << k;
    }
    // With motion blur from the clock: a frame alone (its subset) is the same frame.
    ASSERT_EQ(renderCli({scene.string(), "-o", (dir.path / "b_%d.exr").string(), "--frames", "0..9", "--shutter",
                         "0.5", "--subset", "3..5", "-q"}),
              0);
    ASSERT_EQ(renderCli({scene.string(), "-o", (dir.path / "alone.exr").string(), "--frames", "0..9", "--shutter",
                         "0.5", "--subset", "4..4", "-q"}),
              0);
    EXPECT_EQ(filePixels(dir.path / "alone.exr"), filePixels(dir.path / "b_4.exr"));
    EXPECT_FALSE(fs::exists(dir.path / "b_2.exr"));
    // ... and the one-frame render at its clock and clock step.
    ASSERT_EQ(renderCli({scene.string(), "-o", (dir.path / "one_blur.exr").string(), "--clock",
                         fmt::format("{:.17g}", 4 / 9.0), "--clock-delta", fmt::format("{:.17g}", 1 / 9.0),
                         "--shutter", "0.5", "-q"}),
              0);
    EXPECT_EQ(filePixels(dir.path / "one_blur.exr"), filePixels(dir.path / "b_4.exr"));
    EXPECT_NE(filePixels(dir.path / "b_4.exr"), filePixels(dir.path / "f_04.exr")); // the blur is there
}

TEST(Time, IniAnimationsAndTimeErrorsOnTheCommandLine) {
    TempDir dir;
    std::ofstream(dir.path / "spin.pov") << "camera { location <0, 2, -6> look_at 0 }\n"
                                            "light_source { <3, 5, -4>, rgb 1 }\n"
                                            "box { -1, 1 pigment { rgb <1, 0.5, 0> } rotate y * 90 * clock }\n";
    std::ofstream(dir.path / "spin.ini") << "Input_File_Name=spin.pov\nWidth=16\nHeight=12\nInitial_Frame=1\n"
                                            "Final_Frame=12\nSubset_Start_Frame=11\n";
    ASSERT_EQ(renderCli({(dir.path / "spin.ini").string(), "-o", (dir.path / "spin.png").string(), "--spp", "1",
                         "-q"}),
              0);
    EXPECT_TRUE(fs::exists(dir.path / "spin11.png"));
    EXPECT_TRUE(fs::exists(dir.path / "spin12.png"));
    EXPECT_FALSE(fs::exists(dir.path / "spin10.png"));
    std::string err;
    EXPECT_EQ(renderCli({(dir.path / "spin.pov").string(), "-o", "x.png", "--frames", "1-5"}, &err), 2);
    EXPECT_NE(err.find("--frames needs a frame range A..B"), std::string::npos) << err;
    EXPECT_EQ(renderCli({(dir.path / "spin.pov").string(), "-o", "x.png", "--frames", "5..1"}, &err), 2);
    EXPECT_NE(err.find("before the initial frame"), std::string::npos) << err;
    EXPECT_EQ(renderCli({(dir.path / "spin.pov").string(), "-o", "x.png", "--clock", "0..1"}, &err), 2);
    EXPECT_NE(err.find("a clock range needs a frame range"), std::string::npos) << err;
    std::ofstream(dir.path / "bad.ini") << "Input_File_Name=spin.pov\nFinal_Frame=x\n";
    EXPECT_EQ(renderCli({(dir.path / "bad.ini").string(), "-o", "x.png"}, &err), 1);
    EXPECT_NE(err.find("bad.ini:2:13: error: 'final_frame' needs a number"), std::string::npos) << err;
    std::ofstream(dir.path / "noscene.ini") << "Final_Frame=3\n";
    EXPECT_EQ(renderCli({(dir.path / "noscene.ini").string(), "-o", "x.png"}, &err), 1);
    EXPECT_NE(err.find("no Input_File_Name"), std::string::npos) << err;
    EXPECT_EQ(renderCli({(dir.path / "spin.pov").string(), "-o", "x.png", "--frames", "1..5", "--subset", "7..9"},
                        &err),
              2);
    EXPECT_NE(err.find("holds no frame of 1..5"), std::string::npos) << err;
    EXPECT_EQ(renderCli({(dir.path / "spin.pov").string(), "--frames", "1..5"}, &err), 2);
    EXPECT_NE(err.find("--output is required"), std::string::npos) << err;
    // The .ini's Output_File_Name when no -o is given; neither is an error.
    std::ofstream(dir.path / "named.ini") << "Input_File_Name=spin.pov\nOutput_File_Name=named_.png\nWidth=8\n"
                                             "Height=6\nInitial_Frame=1\nFinal_Frame=2\n";
    ASSERT_EQ(renderCli({(dir.path / "named.ini").string(), "--spp", "1", "-q"}, &err), 0) << err;
    EXPECT_TRUE(fs::exists(dir.path / "named_1.png"));
    EXPECT_TRUE(fs::exists(dir.path / "named_2.png"));
    std::ofstream(dir.path / "unnamed.ini") << "Input_File_Name=spin.pov\nFinal_Frame=2\n";
    EXPECT_EQ(renderCli({(dir.path / "unnamed.ini").string()}, &err), 2);
    EXPECT_NE(err.find("no Output_File_Name and no --output"), std::string::npos) << err;
}

} // namespace
} // namespace drt
