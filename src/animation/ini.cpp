#include "animation/ini.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace drt {

namespace {

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

std::string trim(const std::string& s) {
    const size_t a = s.find_first_not_of(" \t\r");
    if (a == std::string::npos) return "";
    const size_t b = s.find_last_not_of(" \t\r");
    return s.substr(a, b - a + 1);
}

// The switch forms (+KFI10) of the keys drt reads, longest first.
const std::vector<std::pair<std::string, std::string>>& switches() {
    static const std::vector<std::pair<std::string, std::string>> table = {
        {"kfi", "initial_frame"}, {"kff", "final_frame"}, {"kc", "cyclic_animation"}, {"ki", "initial_clock"},
        {"kf", "final_clock"},    {"sf", "subset_start_frame"}, {"ef", "subset_end_frame"}, {"k", "clock"},
        {"w", "width"},           {"h", "height"},      {"i", "input_file_name"}, {"o", "output_file_name"},
        {"l", "library_path"}};
    return table;
}

struct Reader {
    Diagnostics& diagnostics;
    int file;
    std::string baseDir;
    IniSettings out;

    SourceLoc at(int line, size_t column) const { return {file, line, static_cast<int>(column) + 1}; }

    std::optional<double> number(const std::string& value, SourceLoc loc, const std::string& key) {
        std::istringstream in(value);
        double v = 0;
        std::string rest;
        if (!(in >> v) || (in >> rest) || !std::isfinite(v)) {
            diagnostics.error(loc, "'" + key + "' needs a number, not '" + value + "'");
            return std::nullopt;
        }
        return v;
    }
    std::optional<int> integer(const std::string& value, SourceLoc loc, const std::string& key) {
        const std::optional<double> v = number(value, loc, key);
        if (!v) return std::nullopt;
        if (*v != std::floor(*v) || std::fabs(*v) > 1e9) {
            diagnostics.error(loc, "'" + key + "' needs a whole number, not '" + value + "'");
            return std::nullopt;
        }
        return static_cast<int>(*v);
    }
    std::optional<bool> boolean(const std::string& value, SourceLoc loc, const std::string& key) {
        const std::string v = lower(value);
        if (v == "on" || v == "true" || v == "yes" || v == "1" || v.empty()) return true;
        if (v == "off" || v == "false" || v == "no" || v == "0") return false;
        diagnostics.error(loc, "'" + key + "' needs on or off, not '" + value + "'");
        return std::nullopt;
    }
    std::string path(const std::string& value) const {
        std::string v = value;
        if (v.size() >= 2 && v.front() == '"' && v.back() == '"') v = v.substr(1, v.size() - 2);
        return fs::path(v).is_absolute() ? v : (fs::path(baseDir) / v).lexically_normal().string();
    }

    void set(const std::string& key, const std::string& value, SourceLoc keyLoc, SourceLoc valueLoc) {
        if (key == "input_file_name") out.input = path(value);
        else if (key == "output_file_name") out.output = path(value);
        else if (key == "library_path") out.libraryPaths.push_back(path(value));
        else if (key == "width") out.width = integer(value, valueLoc, key);
        else if (key == "height") out.height = integer(value, valueLoc, key);
        else if (key == "initial_frame") out.initialFrame = integer(value, valueLoc, key);
        else if (key == "final_frame") out.finalFrame = integer(value, valueLoc, key);
        else if (key == "initial_clock") out.initialClock = number(value, valueLoc, key);
        else if (key == "final_clock") out.finalClock = number(value, valueLoc, key);
        else if (key == "clock") out.clock = number(value, valueLoc, key);
        else if (key == "cyclic_animation") out.cyclic = boolean(value, valueLoc, key);
        else if (key == "subset_start_frame" || key == "subset_end_frame") {
            const std::optional<double> v = number(value, valueLoc, key);
            const bool fraction = value.find('.') != std::string::npos && v && *v >= 0 && *v <= 1;
            if (v && !fraction && *v != std::floor(*v))
                diagnostics.error(valueLoc, "'" + key + "' needs a frame number or a fraction between 0 and 1");
            (key == "subset_start_frame" ? out.subsetStart : out.subsetEnd) = v;
            (key == "subset_start_frame" ? out.subsetStartFraction : out.subsetEndFraction) = fraction;
        } else diagnostics.warning(keyLoc, "POV-Ray option '" + key + "' is ignored by drt");
    }

    void line(const std::string& raw, int number) {
        std::string text = raw.substr(0, raw.find(';'));
        const std::string t = trim(text);
        if (t.empty() || t.front() == '[') return;
        const size_t first = text.find_first_not_of(" \t");
        if (t.front() == '+' || t.front() == '-') { // a switch: +KFI10
            const std::string body = lower(t.substr(1));
            for (const auto& [prefix, key] : switches()) {
                if (body.rfind(prefix, 0) != 0) continue;
                const std::string value = trim(t.substr(1 + prefix.size()));
                const bool on = t.front() == '+';
                if (key == "cyclic_animation") out.cyclic = on;
                else set(key, value, at(number, first), at(number, first + 1 + prefix.size()));
                return;
            }
            diagnostics.warning(at(number, first), "POV-Ray switch '" + t + "' is ignored by drt");
            return;
        }
        const size_t eq = text.find('=');
        if (eq == std::string::npos) { // a bare file name: POV-Ray's input file
            out.input = path(t);
            return;
        }
        const std::string key = lower(trim(text.substr(0, eq)));
        const std::string value = trim(text.substr(eq + 1));
        const size_t valueColumn = text.find_first_not_of(" \t", eq + 1);
        set(key, value, at(number, first), at(number, valueColumn == std::string::npos ? eq + 1 : valueColumn));
    }
};

} // namespace

std::optional<IniSettings> readIniText(const std::string& text, const std::string& name, Diagnostics& diagnostics,
                                       const std::string& baseDir) {
    const int file = diagnostics.files().add(name, text);
    Reader reader{diagnostics, file, baseDir, {}};
    std::istringstream in(text);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) reader.line(line, number);
    if (diagnostics.hasErrors()) return std::nullopt;
    return reader.out;
}

std::optional<IniSettings> readIniFile(const std::string& path, Diagnostics& diagnostics) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        diagnostics.error({}, "cannot read '" + path + "'");
        return std::nullopt;
    }
    std::stringstream text;
    text << in.rdbuf();
    const std::string dir = fs::path(path).parent_path().string();
    return readIniText(text.str(), path, diagnostics, dir.empty() ? "." : dir);
}

bool applyIni(const IniSettings& ini, Animation& a) {
    bool any = false;
    const auto take = [&any](auto& to, const auto& from) {
        if (from) to = *from, any = true;
    };
    take(a.initialFrame, ini.initialFrame);
    take(a.finalFrame, ini.finalFrame);
    take(a.initialClock, ini.initialClock);
    take(a.finalClock, ini.finalClock);
    take(a.cyclic, ini.cyclic);
    // POV-Ray: a subset between 0 and 1 with a decimal point is a fraction of the frames.
    const auto frameOf = [&](double v, bool fraction) {
        return fraction ? a.initialFrame + static_cast<int>(std::lround(v * (a.finalFrame - a.initialFrame)))
                        : static_cast<int>(v);
    };
    if (ini.subsetStart) a.subsetStart = frameOf(*ini.subsetStart, ini.subsetStartFraction), any = true;
    if (ini.subsetEnd) a.subsetEnd = frameOf(*ini.subsetEnd, ini.subsetEndFraction), any = true;
    return any;
}

} // namespace drt
