#include "distributed/crop_merge.h"

#include "distributed/render_identity.h"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <optional>
#include <sstream>

namespace drt {

std::string parseCropWindow(const std::string& text, int width, int height, PixelWindow& window) {
    std::vector<std::string> fields;
    std::stringstream in(text);
    for (std::string field; std::getline(in, field, ',');) fields.push_back(field);
    if (fields.size() != 4)
        return fmt::format("--crop '{}': give four values x0,x1,y0,y1 (pixels, or fractions such as 0.0,0.5,0.0,1.0)",
                           text);
    const bool fractions = text.find('.') != std::string::npos;
    double values[4];
    for (int i = 0; i < 4; ++i) {
        size_t used = 0;
        try {
            values[i] = std::stod(fields[size_t(i)], &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used == 0 || used != fields[size_t(i)].size() || !std::isfinite(values[i]))
            return fmt::format("--crop '{}': '{}' is not a number", text, fields[size_t(i)]);
        if (!fractions && values[i] != std::floor(values[i]))
            return fmt::format("--crop '{}': pixel bounds are whole numbers", text);
    }
    if (fractions) {
        for (double v : values)
            if (v < 0 || v > 1) return fmt::format("--crop '{}': fractions are between 0 and 1", text);
        const auto bound = [](double fraction, int size) { return int(std::floor(fraction * size + 0.5)); };
        window = {bound(values[0], width), bound(values[1], width), bound(values[2], height), bound(values[3], height)};
    } else {
        window = {int(values[0]), int(values[1]), int(values[2]), int(values[3])};
    }
    if (window.empty() || window.x0 < 0 || window.y0 < 0 || window.x1 > width || window.y1 > height)
        return fmt::format("--crop '{}': the window x {}..{}, y {}..{} is not a non-empty part of the {}x{} image",
                           text, window.x0, window.x1, window.y0, window.y1, width, height);
    return "";
}

namespace {

struct Part {
    std::string path;
    Image image;
    Metadata metadata;
    RenderIdentity identity;
    PixelWindow window;
    PartContent content = PartContent::Color;
};

std::string contentName(PartContent content) {
    switch (content) {
    case PartContent::Color: return "colour";
    case PartContent::Variance: return "variance";
    case PartContent::SampleCount: return "samples-per-pixel";
    }
    return "";
}

std::string readPart(const std::string& path, Part& part, bool& unreadable) {
    part.path = path;
    if (std::string problem = readImage(path, part.image, &part.metadata); !problem.empty()) {
        unreadable = true;
        return problem;
    }
    const auto identity = readIdentity(part.metadata);
    const auto crop = metadataValue(part.metadata, "drt:crop");
    const auto size = metadataValue(part.metadata, "drt:full_size");
    if (!identity) return fmt::format("'{}' was not rendered by drt (it has no drt:settings metadata)", path);
    if (!crop || !size) return fmt::format("'{}' is not a crop (it was rendered without --crop)", path);
    part.identity = *identity;
    const auto window = parseWindow(*crop);
    if (!window) return fmt::format("'{}' has a malformed drt:crop '{}'", path, *crop);
    part.window = *window;
    if (part.image.width != window->width() || part.image.height != window->height())
        return fmt::format("'{}' is {}x{} but its crop window {} is {}x{}", path, part.image.width,
                           part.image.height, *crop, window->width(), window->height());
    const std::string content = metadataValue(part.metadata, "drt:content").value_or("");
    part.content = content == "variance of the mean"  ? PartContent::Variance
                   : content == "samples per pixel" ? PartContent::SampleCount
                                                    : PartContent::Color;
    return "";
}

// Places the parts of one kind into one image, each pixel exactly once.
std::string assemble(const std::vector<const Part*>& parts, int width, int height, Image& out) {
    const Part& first = *parts.front();
    out = Image(width, height, first.image.channels);
    std::vector<int> owner(size_t(width) * size_t(height), -1);
    for (size_t i = 0; i < parts.size(); ++i) {
        const Part& part = *parts[i];
        if (part.image.channels != first.image.channels)
            return fmt::format("'{}' has {} channels, '{}' has {}", part.path, part.image.channels, first.path,
                               first.image.channels);
        const PixelWindow& w = part.window;
        if (w.x1 > width || w.y1 > height || w.x0 < 0 || w.y0 < 0)
            return fmt::format("'{}': crop {} lies outside the {}x{} image", part.path, formatWindow(w), width, height);
        for (int y = w.y0; y < w.y1; ++y)
            for (int x = w.x0; x < w.x1; ++x) {
                int& o = owner[size_t(y) * size_t(width) + size_t(x)];
                if (o >= 0)
                    return fmt::format("'{}' (crop {}) and '{}' (crop {}) overlap, first at pixel ({}, {})",
                                       parts[size_t(o)]->path, formatWindow(parts[size_t(o)]->window), part.path,
                                       formatWindow(w), x, y);
                o = int(i);
                for (int c = 0; c < out.channels; ++c) out.at(x, y, c) = part.image.at(x - w.x0, y - w.y0, c);
            }
    }
    size_t missing = 0;
    int firstX = -1, firstY = -1;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            if (owner[size_t(y) * size_t(width) + size_t(x)] < 0 && missing++ == 0) firstX = x, firstY = y;
    if (missing > 0)
        return fmt::format("the {} parts leave {} of the {}x{} image's pixels uncovered, first at ({}, {})",
                           contentName(first.content), missing, width, height, firstX, firstY);
    return "";
}

// The merged file's metadata: the first part's drt keys without the crop,
// with the counts and times of all parts added up.
Metadata mergedMetadata(const std::vector<const Part*>& parts) {
    Metadata out;
    const auto sum = [&](const std::string& key) -> std::optional<std::string> {
        double total = 0;
        bool integral = true;
        for (const Part* part : parts) {
            const auto value = metadataValue(part->metadata, key);
            if (!value) return std::nullopt;
            try {
                total += std::stod(*value);
            } catch (const std::exception&) {
                return std::nullopt;
            }
            integral = integral && value->find('.') == std::string::npos;
        }
        return integral ? fmt::format("{}", uint64_t(total)) : fmt::format("{:.3f}", total);
    };
    for (const auto& [key, value] : parts.front()->metadata) {
        if (key == "drt:crop" || key == "drt:full_size") continue;
        if (key.rfind("drt:", 0) != 0 && key != "Software") continue;
        const bool additive = key == "drt:render_seconds" || key == "drt:samples_taken" ||
                              key == "drt:nonfinite_samples" || key == "drt:nonfinite_pixels";
        out.emplace_back(key, additive ? sum(key).value_or(value) : value);
    }
    out.emplace_back("drt:merged_parts", std::to_string(parts.size()));
    return out;
}

} // namespace

std::string mergeCrops(const std::vector<std::string>& paths, MergedImages& merged, bool& unreadable) {
    unreadable = false;
    if (paths.empty()) return "no parts to merge";
    std::vector<Part> parts(paths.size());
    for (size_t i = 0; i < paths.size(); ++i)
        if (std::string problem = readPart(paths[i], parts[i], unreadable); !problem.empty()) return problem;
    const Part& first = parts.front();
    const std::string size = metadataValue(first.metadata, "drt:full_size").value_or("");
    int width = 0, height = 0;
    char x = 0;
    if (!(std::istringstream(size) >> width >> x >> height) || x != 'x' || width < 1 || height < 1)
        return fmt::format("'{}' has a malformed drt:full_size '{}'", first.path, size);
    std::map<PartContent, std::vector<const Part*>> byKind;
    for (const Part& part : parts) {
        if (std::string difference = describeDifference(first.identity, part.identity, part.path);
            !difference.empty())
            return difference + fmt::format(" (compared with '{}')", first.path);
        if (metadataValue(part.metadata, "drt:full_size").value_or("") != size)
            return fmt::format("'{}' is a crop of a {} image, '{}' of a {} image", part.path,
                               metadataValue(part.metadata, "drt:full_size").value_or("?"), first.path, size);
        byKind[part.content].push_back(&part);
    }
    if (!byKind.count(PartContent::Color)) return "no colour parts among the files (only variance or spp images)";
    for (const auto& [kind, group] : byKind) {
        Image image;
        if (std::string problem = assemble(group, width, height, image); !problem.empty()) return problem;
        if (kind == PartContent::Color) {
            merged.color = std::move(image);
            merged.colorMetadata = mergedMetadata(group);
            merged.parts = int(group.size());
        } else {
            merged.others.push_back(std::move(image));
            merged.otherKinds.push_back(kind);
            merged.otherMetadata.push_back(mergedMetadata(group));
        }
    }
    return "";
}

} // namespace drt
