// What makes two renders' pixels the same: the drt version, the scene and
// every setting that changes a pixel. Crops are merged, and checkpoints
// resumed, only when these match; the thread count, tile size and number of
// processes never change a pixel, so they are not part of it.
#pragma once

#include "image/image.h"
#include "render/render.h"

#include <optional>
#include <string>

namespace drt {

struct RenderIdentity {
    std::string version;    // drt's
    // SHA-1 (hex) of the scene text and its includes (sceneTextSha1,
    // render/provenance.h): an edited include is another scene.
    std::string sceneHash;
    // "size=320x240 spp=16 seed=0 sampler=sobol adaptive=off" (or
    // "adaptive=error:0.02,min:16,max:1024"): the settings in one line.
    std::string settings;
    bool operator==(const RenderIdentity&) const = default;
};

RenderIdentity renderIdentity(const RenderOptions& options, const std::string& sceneHash);

// What differs between `here` and `there` in words ("seed=1 here, seed=2 in
// 'part.exr'"), or "" when they are the same.
std::string describeDifference(const RenderIdentity& here, const RenderIdentity& there, const std::string& thereName);

// The image metadata of a render's identity and window (keys drt:version,
// drt:scene_sha1, drt:settings; drt:crop "x0,x1,y0,y1" and drt:full_size
// "WxH" for a crop), and back. readIdentity returns none when a key is missing.
void addIdentity(Metadata& metadata, const RenderIdentity& identity, const std::optional<PixelWindow>& crop,
                 int width, int height);
std::optional<RenderIdentity> readIdentity(const Metadata& metadata);

// "x0,x1,y0,y1" and back (none if malformed).
std::string formatWindow(const PixelWindow& window);
std::optional<PixelWindow> parseWindow(const std::string& text);

// The value of `key` in metadata, or none.
std::optional<std::string> metadataValue(const Metadata& metadata, const std::string& key);

} // namespace drt
