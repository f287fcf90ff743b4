// The sidecar NAME.golden.json: render settings and tolerances of one golden test.
//
//   key               type     default           meaning
//   scene             string   "NAME.drt"        scene file, relative to the sidecar
//   policy            string   "exact"           "exact" or "statistical"
//   format            string   "exr"             golden files: "exr", "png" or "both" (exact only)
//   width, height     int      the scene's       image size
//   spp               int      the scene's       samples per pixel of the test render
//   seed              int      the scene's       seed of the test render
//   sampler           string   the scene's       sampler name
//   threads           int      0 (all cores)     threads per render
//   fail              number   0                 exact: per-channel error a pixel may have
//   fail_percent      number   0                 exact: % of pixels allowed to exceed `fail`
//   alpha             number   0.01              statistical: false-alarm rate
//   tile_size         int      8                 statistical: edge of the tile z-tests
//   reference_spp     int      64 x spp          statistical: samples of the golden (--update)
//   reference_seed    int      seed + 1          statistical: seed of the golden (--update)
#include "golden/golden.h"

#include "sampling/sampler.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using nlohmann::json;

namespace drt::golden {

const char* policyName(Policy policy) {
    return policy == Policy::Exact ? "exact" : "statistical";
}

namespace {

const char* const kKeys[] = {"scene",        "policy", "format",    "width",         "height",
                             "spp",          "seed",   "sampler",   "threads",       "fail",
                             "fail_percent", "alpha",  "tile_size", "reference_spp", "reference_seed"};

// Reads `key` into `out` if present; throws std::runtime_error with the key's
// name when the value has the wrong type or lies outside [low, high].
template <typename T> void readNumber(const json& object, const char* key, T& out, double low, double high) {
    const auto it = object.find(key);
    if (it == object.end())
        return;
    const bool integral = std::is_integral_v<T>;
    if (!it->is_number() || (integral && !it->is_number_integer()))
        throw std::runtime_error(fmt::format("'{}' must be {}", key, integral ? "an integer" : "a number"));
    const double value = it->get<double>();
    if (!(value >= low && value <= high))
        throw std::runtime_error(fmt::format("'{}' must be between {} and {}", key, low, high));
    out = it->get<T>();
}

template <typename T>
void readOptional(const json& object, const char* key, std::optional<T>& out, double low, double high) {
    if (!object.contains(key))
        return;
    T value{};
    readNumber(object, key, value, low, high);
    out = value;
}

std::string readString(const json& object, const char* key) {
    const json& value = object.at(key);
    if (!value.is_string())
        throw std::runtime_error(fmt::format("'{}' must be a string", key));
    return value.get<std::string>();
}

void parseSettings(const json& object, GoldenSettings& s) {
    if (!object.is_object())
        throw std::runtime_error("the sidecar must hold one JSON object");
    for (const auto& item : object.items())
        if (std::find_if(std::begin(kKeys), std::end(kKeys),
                         [&](const char* k) { return item.key() == k; }) == std::end(kKeys))
            throw std::runtime_error(fmt::format("unknown key '{}'", item.key()));
    if (object.contains("scene"))
        s.scene = readString(object, "scene");
    if (object.contains("policy")) {
        const std::string policy = readString(object, "policy");
        if (policy == "exact")
            s.policy = Policy::Exact;
        else if (policy == "statistical")
            s.policy = Policy::Statistical;
        else
            throw std::runtime_error(
                fmt::format("policy '{}' is neither \"exact\" nor \"statistical\"", policy));
    }
    if (object.contains("format")) {
        s.format = readString(object, "format");
        if (s.format != "exr" && s.format != "png" && s.format != "both")
            throw std::runtime_error(
                fmt::format("format '{}' is not \"exr\", \"png\" or \"both\"", s.format));
        if (s.policy == Policy::Statistical && s.format != "exr")
            throw std::runtime_error("statistical goldens are stored as EXR (\"format\": \"exr\")");
    }
    readOptional(object, "width", s.width, 1, 65536);
    readOptional(object, "height", s.height, 1, 65536);
    readOptional(object, "spp", s.samplesPerPixel, 1, 1 << 24);
    readOptional(object, "seed", s.seed, 0, 1.8e19);
    if (object.contains("sampler")) {
        s.sampler = readString(object, "sampler");
        const auto& names = samplerNames();
        if (std::find(names.begin(), names.end(), *s.sampler) == names.end())
            throw std::runtime_error(fmt::format("unknown sampler '{}'", *s.sampler));
    }
    readNumber(object, "threads", s.threads, 0, 4096);
    readNumber(object, "fail", s.failThreshold, 0, 1e30);
    readNumber(object, "fail_percent", s.failPercent, 0, 100);
    readNumber(object, "alpha", s.alpha, 1e-12, 0.5);
    readNumber(object, "tile_size", s.tileSize, 1, 4096);
    readOptional(object, "reference_spp", s.referenceSamplesPerPixel, 1, 1 << 24);
    readOptional(object, "reference_seed", s.referenceSeed, 0, 1.8e19);
    if (s.policy == Policy::Exact && (object.contains("alpha") || object.contains("tile_size") ||
                                      object.contains("reference_spp") || object.contains("reference_seed")))
        throw std::runtime_error("alpha, tile_size, reference_spp and reference_seed apply only to the "
                                 "statistical policy");
    if (s.policy == Policy::Statistical && (object.contains("fail") || object.contains("fail_percent")))
        throw std::runtime_error("fail and fail_percent apply only to the exact policy");
}

} // namespace

std::string readSettings(const std::string& path, GoldenSettings& settings) {
    std::ifstream in(path);
    if (!in)
        return fmt::format("{}: cannot read the sidecar", path);
    try {
        const json object = json::parse(in);
        GoldenSettings parsed;
        parseSettings(object, parsed);
        settings = parsed;
    } catch (const json::parse_error& e) {
        // nlohmann's message names the line and column of the syntax error.
        return fmt::format("{}: not valid JSON: {}", path, e.what());
    } catch (const std::exception& e) {
        return fmt::format("{}: {}", path, e.what());
    }
    return "";
}

std::string writeSettings(const std::string& path, const GoldenSettings& s) {
    // ordered_json keeps the keys in the order of the table above.
    nlohmann::ordered_json object;
    if (!s.scene.empty())
        object["scene"] = s.scene;
    object["policy"] = policyName(s.policy);
    object["format"] = s.format;
    if (s.width)
        object["width"] = *s.width;
    if (s.height)
        object["height"] = *s.height;
    if (s.samplesPerPixel)
        object["spp"] = *s.samplesPerPixel;
    if (s.seed)
        object["seed"] = *s.seed;
    if (s.sampler)
        object["sampler"] = *s.sampler;
    object["threads"] = s.threads;
    if (s.policy == Policy::Exact) {
        object["fail"] = s.failThreshold;
        object["fail_percent"] = s.failPercent;
    } else {
        object["alpha"] = s.alpha;
        object["tile_size"] = s.tileSize;
        if (s.referenceSamplesPerPixel)
            object["reference_spp"] = *s.referenceSamplesPerPixel;
        if (s.referenceSeed)
            object["reference_seed"] = *s.referenceSeed;
    }
    const std::string temporary = path + ".tmp";
    {
        std::ofstream out(temporary);
        out << object.dump(2) << "\n";
        if (!out)
            return fmt::format("{}: cannot write the sidecar", path);
    }
    std::error_code ec;
    fs::rename(temporary, path, ec);
    if (ec) {
        fs::remove(temporary, ec);
        return fmt::format("{}: cannot write the sidecar: {}", path, ec.message());
    }
    return "";
}

} // namespace drt::golden
