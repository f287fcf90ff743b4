// Text and JSON reports of a comparison. The JSON is written by hand: the
// object is flat and small, and no JSON library is among drt's dependencies.
#include "compare/compare.h"

#include <cmath>
#include <fmt/format.h>

namespace drt {

namespace {

// JSON has no NaN or Inf: those print as null.
std::string number(double v) {
    return std::isfinite(v) ? fmt::format("{:.9g}", v) : "null";
}

std::string quoted(const std::string& s) {
    std::string out = "\"";
    for (char ch : s) {
        const auto c = static_cast<unsigned char>(ch);
        if (c == '"' || c == '\\')
            out += {'\\', ch};
        else if (c < 0x20)
            out += fmt::format("\\u{:04x}", c);
        else
            out += ch;
    }
    return out + "\"";
}

} // namespace

std::string channelName(int channel) {
    static const char* const names[] = {"R", "G", "B", "A"};
    if (channel >= 0 && channel < 4)
        return names[channel];
    return fmt::format("channel {}", channel);
}

std::string formatCompareText(const CompareResult& r) {
    std::string s;
    if (r.status == CompareStatus::SizeMismatch || r.status == CompareStatus::FileError)
        return fmt::format("{}: {}\n", compareStatusName(r.status), r.message);
    s += fmt::format("  size:              {}x{}, {} channels compared\n", r.width, r.height, r.channels);
    s += fmt::format("  NaN/Inf pixels:    {}\n", r.nonFinitePixels);
    s += fmt::format("  RMSE:              {:.6g}\n", r.rmse);
    s += fmt::format("  relMSE:            {:.6g}  (robust, worst 0.1% dropped: {:.6g})\n", r.relMse,
                     r.robustRelMse);
    s += fmt::format("  mean signed error: {:.6g}  (mean absolute: {:.6g})\n", r.meanSignedError,
                     r.meanAbsoluteError);
    if (r.maxErrorX >= 0)
        s += fmt::format("  max error:         {:.6g} at pixel ({}, {}) channel {}\n", r.maxError,
                         r.maxErrorX, r.maxErrorY, channelName(r.maxErrorChannel));
    s += fmt::format("  PSNR (sRGB):       {}\n",
                     std::isfinite(r.psnr) ? fmt::format("{:.2f} dB", r.psnr) : "inf");
    s += fmt::format("  pixels over fail:  {}, over warn: {}\n", r.failingPixels, r.warningPixels);
    if (r.statistical) {
        std::string zs;
        for (size_t c = 0; c < r.globalZ.size(); ++c)
            zs += fmt::format("{}{} {:.2f}", zs.empty() ? "" : ", ", channelName(int(c)), r.globalZ[c]);
        s += fmt::format("  global z:          {}  (|z| limit {:.2f})\n", zs, r.globalZThreshold);
        s += fmt::format("  tile tests:        {} of {} biased (|z| limit {:.2f}); worst z {:.2f} at ({}, "
                         "{}) channel {}\n",
                         r.failingTiles, r.tileTests, r.tileZThreshold, r.worstTile.z, r.worstTile.x0,
                         r.worstTile.y0, channelName(r.worstTile.channel));
        s += fmt::format("  outlier pixels:    {}\n", r.outlierPixels);
    }
    s += compareStatusName(r.status);
    if (!r.message.empty())
        s += ": " + r.message;
    return s + "\n";
}

std::string formatCompareJson(const CompareResult& r, const std::string& candidatePath,
                              const std::string& referencePath) {
    std::string s = "{\n";
    auto field = [&](const std::string& name, const std::string& value) {
        s += fmt::format("  {}: {},\n", quoted(name), value);
    };
    field("candidate", quoted(candidatePath));
    field("reference", quoted(referencePath));
    field("status", quoted(compareStatusName(r.status)));
    field("exit_code", std::to_string(static_cast<int>(r.status)));
    field("message", quoted(r.message));
    field("width", std::to_string(r.width));
    field("height", std::to_string(r.height));
    field("channels", std::to_string(r.channels));
    field("nonfinite_pixels", std::to_string(r.nonFinitePixels));
    field("rmse", number(r.rmse));
    field("relmse", number(r.relMse));
    field("robust_relmse", number(r.robustRelMse));
    field("mean_signed_error", number(r.meanSignedError));
    field("mean_absolute_error", number(r.meanAbsoluteError));
    field("max_error", number(r.maxError));
    field("max_error_pixel", fmt::format("[{}, {}]", r.maxErrorX, r.maxErrorY));
    field("max_error_channel", std::to_string(r.maxErrorChannel));
    field("psnr", number(r.psnr));
    field("failing_pixels", std::to_string(r.failingPixels));
    field("warning_pixels", std::to_string(r.warningPixels));
    if (r.statistical) {
        std::string zs;
        for (double z : r.globalZ)
            zs += (zs.empty() ? "" : ", ") + number(z);
        field("global_z", "[" + zs + "]");
        field("global_z_threshold", number(r.globalZThreshold));
        field("tile_tests", std::to_string(r.tileTests));
        field("failing_tiles", std::to_string(r.failingTiles));
        field("tile_z_threshold", number(r.tileZThreshold));
        field("worst_tile",
              fmt::format("{{\"x\": {}, \"y\": {}, \"channel\": {}, \"mean_error\": {}, \"z\": {}}}",
                          r.worstTile.x0, r.worstTile.y0, r.worstTile.channel, number(r.worstTile.meanError),
                          number(r.worstTile.z)));
        field("outlier_pixels", std::to_string(r.outlierPixels));
    }
    field("statistical", r.statistical ? "true" : "false");
    s.erase(s.size() - 2); // the last ",\n"
    return s + "\n}\n";
}

} // namespace drt
