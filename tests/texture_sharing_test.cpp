// Objects placed with equal textures share one (Object::texture, a
// SharedTexture; scene/texture_sharing.h): equal means every number has the
// same bits, so sharing never changes a pixel, and changing one object's
// texture never changes another's.
#include "lang/load.h"
#include "pov/load.h"
#include "render/render.h"
#include "scene/scene_walk.h"
#include "scene/texture_sharing.h"
#include "test_support.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>

namespace drt {
namespace {

Scene load(const std::string& text, const std::string& name = "sharing.drt") {
    Diagnostics diags;
    std::optional<Scene> scene = loadSceneText(text, name, diags, LoadOptions{});
    EXPECT_TRUE(scene) << diags.formatAll();
    return scene ? std::move(*scene) : Scene{};
}

const std::string kCamera = "camera { location <0, 0, -5> look_at <0, 0, 0> }\n"
                            "light_source { <0, 5, -5>, rgb 1 }\n";

TEST(TextureSharing, ObjectsWithEqualTexturesShareOne) {
    std::string text = kCamera;
    for (int i = 0; i < 50; ++i)
        text += fmt::format("sphere {{ <{}, 0, 0>, 0.4 pigment {{ rgb <1, 0, 0> }} finish {{ phong 0.5 }} }}\n", i);
    text += "sphere { <0, 2, 0>, 0.4 pigment { rgb <0, 1, 0> } finish { phong 0.5 } }\n";
    const Scene scene = load(text);
    ASSERT_EQ(scene.objects.size(), 51u);
    for (size_t i = 1; i < 50; ++i)
        EXPECT_TRUE(scene.objects[i].texture.sharedWith(scene.objects[0].texture)) << i;
    EXPECT_FALSE(scene.objects[50].texture.sharedWith(scene.objects[0].texture));
    EXPECT_EQ(scene.objects[0].texture->pigment.color.rgb.r, 1.0);
    EXPECT_EQ(scene.objects[50].texture->pigment.color.rgb.g, 1.0);
}

TEST(TextureSharing, ADeclaredTextureInBothDialectsIsSharedAndUntexturedObjectsShareTheDefault) {
    const Scene drt = load(kCamera + "#declare T = texture { pigment { checker rgb 1, rgb 0 } finish { diffuse 0.8 } }\n"
                                     "box { -1, 1 texture { T } }\nsphere { 0, 1 texture { T } }\n"
                                     "plane { y, -1 }\ndisc { 0, y, 1 }\n");
    ASSERT_EQ(drt.objects.size(), 4u);
    EXPECT_TRUE(drt.objects[0].texture.sharedWith(drt.objects[1].texture));
    EXPECT_TRUE(drt.objects[2].texture.sharedWith(drt.objects[3].texture));
    EXPECT_FALSE(drt.objects[0].texture.sharedWith(drt.objects[2].texture));

    Diagnostics diags;
    const std::optional<Scene> pov = loadPovSceneText(
        "camera { location <0, 0, -5> look_at 0 }\n#declare T = texture { pigment { rgb <0.2, 0.4, 0.6> } }\n"
        "#declare I = 0;\n#while (I < 20)\n  sphere { <I, 0, 0>, 0.4 texture { T } }\n  #declare I = I + 1;\n#end\n",
        "sharing.pov", diags);
    ASSERT_TRUE(pov) << diags.formatAll();
    ASSERT_EQ(pov->objects.size(), 20u);
    for (const Object& o : pov->objects) EXPECT_TRUE(o.texture.sharedWith(pov->objects[0].texture));
}

// Any number that differs, down to the sign of a zero, keeps textures apart.
TEST(TextureSharing, TexturesThatDifferInAnyNumberAreNotShared) {
    const char* const kVariants[] = {
        "pigment { rgb <1, 0, 0> }",
        "pigment { rgb <1, 0, -0> }",                      // -0: another bit pattern
        "pigment { rgb <1, 0, 0> } finish { ambient 0.2 }", // the finish
        "pigment { rgb <1, 0, 0> } normal { bumps 0.3 }",   // a normal
        "pigment { rgb <1, 0, 0> translate x }",            // the pattern space
        "pigment { rgbf <1, 0, 0, 0.5> }",                  // filter
        "pigment { checker rgb <1, 0, 0>, rgb 0 }",         // the pattern
        "texture { pigment { rgb <1, 0, 0> } } texture { pigment { rgbt <0, 0, 1, 0.5> } }", // a layer
        "finish { reflection { 0.1 } } pigment { rgb <1, 0, 0> }",
    };
    std::string text = kCamera;
    for (const char* variant : kVariants) text += std::string("sphere { 0, 1 ") + variant + " }\n";
    // The same texture written again is shared with the first.
    text += "sphere { 0, 1 pigment { rgb <1, 0, 0> } }\n";
    const Scene scene = load(text);
    const size_t n = std::size(kVariants);
    ASSERT_EQ(scene.objects.size(), n + 1);
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n; ++j)
            EXPECT_FALSE(scene.objects[i].texture.sharedWith(scene.objects[j].texture)) << i << ", " << j;
    EXPECT_TRUE(scene.objects[n].texture.sharedWith(scene.objects[0].texture));
    // sameTexture itself: equal to a copy, not to any variant.
    for (size_t i = 0; i < n; ++i) {
        const Texture copy = *scene.objects[i].texture;
        EXPECT_TRUE(sameTexture(copy, *scene.objects[i].texture)) << i;
        for (size_t j = 0; j < n; ++j) {
            if (j != i) {
                EXPECT_FALSE(sameTexture(copy, *scene.objects[j].texture)) << i << ", " << j;
            }
        }
    }
}

TEST(TextureSharing, EditingOneObjectsTextureLeavesTheOthers) {
    Scene scene = load(kCamera + "sphere { 0, 1 pigment { rgb 0.5 } }\nsphere { x, 1 pigment { rgb 0.5 } }\n");
    ASSERT_EQ(scene.objects.size(), 2u);
    ASSERT_TRUE(scene.objects[0].texture.sharedWith(scene.objects[1].texture));
    scene.objects[1].texture.edit().pigment.color.rgb = Color(0.25);
    EXPECT_FALSE(scene.objects[0].texture.sharedWith(scene.objects[1].texture));
    EXPECT_EQ(scene.objects[0].texture->pigment.color.rgb, Color(0.5));
    EXPECT_EQ(scene.objects[1].texture->pigment.color.rgb, Color(0.25));
    // A copied object shares until either is edited.
    Object copy = scene.objects[0];
    EXPECT_TRUE(copy.texture.sharedWith(scene.objects[0].texture));
    transformObjectTextures(copy, Transform::translate(Vec3(1, 0, 0)));
    EXPECT_FALSE(copy.texture.sharedWith(scene.objects[0].texture));
    EXPECT_TRUE(scene.objects[0].texture->pigment.toWorld.isIdentity());
    EXPECT_FALSE(copy.texture->pigment.toWorld.isIdentity());
    // Default-made objects share the default texture until edited.
    Object a, b;
    EXPECT_TRUE(a.texture.sharedWith(b.texture));
    a.texture.edit().finish.diffuse = 0.1;
    EXPECT_EQ(b.texture->finish.diffuse, Texture{}.finish.diffuse);
    EXPECT_EQ(Object{}.texture->finish.diffuse, Texture{}.finish.diffuse);
}

// A walk that may change textures visits a shared one once, for every object that has it.
TEST(TextureSharing, AChangingWalkVisitsASharedTextureOnce) {
    std::string text = kCamera;
    for (int i = 0; i < 10; ++i) text += fmt::format("sphere {{ <{}, 0, 0>, 0.4 pigment {{ rgb 1 }} }}\n", i);
    Scene scene = load(text);
    int visits = 0;
    forEachPigment(scene, [&](Pigment& p) {
        ++visits;
        p.color.rgb.r *= 0.5;
    });
    EXPECT_EQ(visits, 1);
    for (const Object& o : scene.objects) EXPECT_EQ(o.texture->pigment.color.rgb.r, 0.5);
    int constVisits = 0;
    forEachPigment(std::as_const(scene), [&](const Pigment&) { ++constVisits; });
    EXPECT_EQ(constVisits, 10); // a reading walk sees every object's texture
}

// Sharing changes no pixel: the same objects with textures that are equal but
// built apart render as with one declared texture shared from the start.
TEST(TextureSharing, SharedTexturesRenderTheSamePixels) {
    std::string written = kCamera + "plane { y, -1 pigment { checker rgb 1, rgb 0.2 scale 0.5 } }\n";
    std::string declared = kCamera + "plane { y, -1 pigment { checker rgb 1, rgb 0.2 scale 0.5 } }\n"
                                     "#declare T = texture { pigment { bozo color_map { [0 rgb 1] [1 rgb <1, 0, 0>] } "
                                     "scale 0.3 } finish { phong 0.6 } }\n";
    for (int i = -2; i <= 2; ++i) {
        const std::string at = fmt::format("<{}, 0, 0>", i);
        written += "sphere { " + at + ", 0.45 texture { pigment { bozo color_map { [0 rgb 1] [1 rgb <1, 0, 0>] } "
                                      "scale 0.3 } finish { phong 0.6 } } }\n";
        declared += "sphere { " + at + ", 0.45 texture { T } }\n";
    }
    const Scene a = load(written), b = load(declared);
    ASSERT_EQ(a.objects.size(), 6u);
    EXPECT_TRUE(a.objects[1].texture.sharedWith(a.objects[5].texture));
    RenderOptions options = test::tinyRenderOptions();
    options.width = 24;
    options.height = 16;
    options.samplesPerPixel = 4;
    const Image ia = render(a, options).color, ib = render(b, options).color;
    ASSERT_EQ(ia.pixels.size(), ib.pixels.size());
    EXPECT_EQ(ia.pixels, ib.pixels);
    double sum = 0;
    for (float v : ia.pixels) sum += v;
    EXPECT_GT(sum, 0.0); // lit: the comparison is of an image, not of black
}

} // namespace
} // namespace drt
