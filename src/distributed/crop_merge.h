// Crop windows (drt render --crop) and their merging (drt merge): a farm
// renders parts of one image as separate jobs, each bit-identical to the same
// pixels of a full render, and merge assembles them after checking that they
// come from the same render (render_identity.h) and cover the image exactly once.
#pragma once

#include "image/image.h"
#include "render/render.h"

#include <string>
#include <vector>

namespace drt {

// --crop: "x0,x1,y0,y1", pixel bounds [x0, x1) x [y0, y1) as integers, or
// fractions of the image when any value has a decimal point
// ("0.0,0.5,0.0,1.0"; a bound is round(fraction * size), so fractions that
// meet give crops that meet). Returns "" or the problem.
std::string parseCropWindow(const std::string& text, int width, int height, PixelWindow& window);

// The parts' kinds, by their drt:content metadata.
enum class PartContent { Color, Variance, SampleCount };

struct MergedImages {
    Image color;
    Metadata colorMetadata;
    std::vector<Image> others;          // a variance image and/or a samples-per-pixel image
    std::vector<PartContent> otherKinds;
    std::vector<Metadata> otherMetadata;
    int parts = 0; // colour parts
};

// Reads and merges crop images. Refuses (returns the reason) unless every
// file is a drt crop of the same render (drt version, scene, settings, image
// size), the colour parts and each other kind present tile the image exactly
// once, and each file's size is its window's. `unreadable` tells a file that
// could not be read from a refusal.
std::string mergeCrops(const std::vector<std::string>& paths, MergedImages& merged, bool& unreadable);

} // namespace drt
