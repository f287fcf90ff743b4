// The .drt text of an image_map pigment and of a density_file pattern: the file
// by its absolute path, then the settings that differ from the defaults.
#include "lang/writer_detail.h"
#include "scene/density_file.h"
#include "scene/image_map.h"

#include <filesystem>

namespace drt::writer {

std::string quoted(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\', out += c;
        else if (c == '\n') out += "\\n";
        else if (c == '\t') out += "\\t";
        else out += c;
    }
    return out + "\"";
}

std::string imageMapText(const ImageMap& m, const std::string& textures) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const std::string path = fs::absolute(m.path.empty() ? m.file : m.path, ec).lexically_normal().string();
    std::string text = std::string(m.material ? " material_map { " : m.fileValues ? " image_pattern { " : " image_map { ") +
                       quoted(path);
    if (m.projection != ImageMap::Projection::Planar) text += " map_type " + std::to_string(int(m.projection));
    if (m.once) text += " once";
    if (m.interpolation != ImageMap::Interpolation::None)
        text += " interpolate " + std::to_string(int(m.interpolation));
    if (m.filterAll != 0) text += " filter all " + number(m.filterAll);
    if (m.transmitAll != 0) text += " transmit all " + number(m.transmitAll);
    for (const ImageMap::IndexAmount& a : m.indexFilter)
        text += " filter " + std::to_string(a.index) + ", " + number(a.amount);
    for (const ImageMap::IndexAmount& a : m.indexTransmit)
        text += " transmit " + std::to_string(a.index) + ", " + number(a.amount);
    if (m.gamma > 0 && !m.fileValues) text += " gamma " + number(m.gamma);
    return text + textures + " }";
}

std::string densityFileText(const DensityFile& d) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const std::string path = fs::absolute(d.path.empty() ? d.file : d.path, ec).lexically_normal().string();
    std::string text = " density_file df3 " + quoted(path);
    if (d.interpolation != DensityFile::Interpolation::None)
        text += " interpolate " + std::to_string(int(d.interpolation));
    return text;
}

} // namespace drt::writer
