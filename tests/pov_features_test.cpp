// Smaller POV-Ray front-end features: finish crand and the bounds behind
// min_extent / max_extent.
#include "pov/load.h"

#include <gtest/gtest.h>

namespace drt {
namespace {

std::optional<Scene> load(const std::string& text, Diagnostics& diags) {
    return loadPovSceneText(text, "f.pov", diags, PovOptions{});
}

TEST(PovFeatures, CrandIsReadWithoutAWarning) {
    Diagnostics diags;
    const auto s = load("sphere { 0, 1 finish { crand 0.25 diffuse 0.7 } }", diags);
    ASSERT_TRUE(s) << diags.formatAll();
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    EXPECT_EQ(s->objects.at(0).texture.finish.crand, 0.25);
    EXPECT_EQ(s->objects.at(0).texture.finish.diffuse, 0.7);
}

} // namespace
} // namespace drt
