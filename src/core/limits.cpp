#include "core/limits.h"

#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <cstdio>
#include <unistd.h>

namespace drt {

namespace {
Limits& processLimits() {
    static Limits limits;
    return limits;
}
} // namespace

const Limits& defaultLimits() { return processLimits(); }
void setDefaultLimits(const Limits& limits) { processLimits() = limits; }

const std::vector<LimitInfo>& limitTable() {
    constexpr int64_t kInt = std::numeric_limits<int32_t>::max();
    static const std::vector<LimitInfo> table{
        {"include_depth", &Limits::includeDepth, 1000, "#include files open at once"},
        {"include_bytes", &Limits::includeBytes, int64_t(1) << 31, "bytes of one #include'd file"},
        {"call_depth", &Limits::callDepth, 2000, "POV-Ray macro calls and includes nested at once"},
        {"nesting_depth", &Limits::nestingDepth, 1000, "blocks and expressions nested in each other"},
        {"loop_iterations", &Limits::loopIterations, int64_t(1) << 40, "passes of one #while or #for loop"},
        {"passes_and_calls", &Limits::passesAndCalls, int64_t(1) << 40,
         "passes of all #while and #for loops and macro calls, together, in the whole read of a scene"},
        {"objects", &Limits::objects, kInt, "objects in a scene (CSG members and copies counted)"},
        {"memory_mb", &Limits::memoryMB, int64_t(1) << 30, "MB of memory a scene may fill while it is read"},
        {"string_length", &Limits::stringLength, kInt, "characters of one string value"},
        {"array_elements", &Limits::arrayElements, kInt, "elements of one array"},
        {"mesh_triangles", &Limits::meshTriangles, kInt, "triangles of one mesh"},
        {"errors", &Limits::errors, kInt, "errors printed per run"},
        {"quoted_line", &Limits::quotedLine, 1 << 20, "characters of a source line quoted under an error"},
        {"area_light_samples", &Limits::areaLightSamples, kInt, "samples of one area light (n1 * n2)"},
        {"trace_level", &Limits::traceLevel, 256, "max_trace_level (reflection and refraction depth)"},
        {"media_intervals", &Limits::mediaIntervals, 1 << 20, "intervals or samples of one media"},
        {"image_memory_mb", &Limits::imageMemoryMB, int64_t(1) << 30, "MB the image buffers of a render may take"},
        {"threads", &Limits::threads, 65536, "worker threads"},
    };
    return table;
}

const LimitInfo& limitInfo(int64_t Limits::*field) {
    for (const LimitInfo& info : limitTable())
        if (info.field == field) return info;
    return limitTable().front(); // unreachable: every field is in the table
}

std::string setLimit(Limits& limits, std::string_view assignment) {
    const size_t equals = assignment.find('=');
    if (equals == std::string_view::npos)
        return fmt::format("--limit wants NAME=VALUE, not '{}'", assignment);
    const std::string_view name = assignment.substr(0, equals);
    std::string_view value = assignment.substr(equals + 1);
    int64_t scale = 1;
    if (!value.empty()) {
        const char suffix = value.back();
        scale = suffix == 'k' ? 1000 : suffix == 'M' ? 1'000'000 : suffix == 'G' ? 1'000'000'000 : 1;
        if (scale != 1) value.remove_suffix(1);
    }
    for (const LimitInfo& info : limitTable()) {
        if (name != info.name) continue;
        int64_t number = 0;
        const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), number);
        if (ec != std::errc() || end != value.data() + value.size() || number < 1 ||
            number > info.ceiling / scale)
            return fmt::format("--limit {}: '{}' is not a whole number from 1 to {}", info.name,
                               assignment.substr(equals + 1), info.ceiling);
        limits.*info.field = number * scale;
        return "";
    }
    std::string names;
    for (const LimitInfo& info : limitTable()) names += std::string(names.empty() ? "" : ", ") + info.name;
    return fmt::format("--limit: no limit is called '{}' (limits: {})", name, names);
}

std::string limitHint(const Limits& limits, int64_t Limits::*field) {
    const LimitInfo& info = limitInfo(field);
    return fmt::format("limit {} = {}; raise it with --limit {}=N", info.name, limits.*field, info.name);
}

std::string limitExceeded(const Limits& limits, int64_t Limits::*field, std::string_view what, double value) {
    return fmt::format("{} {:.15g} is over the limit of {} ({})", what, value, limits.*field,
                       limitHint(limits, field));
}

std::string checkCount(std::string_view what, double value, double lowest, double highest) {
    if (std::isfinite(value) && std::trunc(value) >= lowest && std::trunc(value) <= highest) return "";
    return fmt::format("{} {:.15g} is out of range ({:.15g} to {:.15g})", what, value, lowest, highest);
}

uint64_t residentBytes() {
    // /proc/self/statm: size resident shared text lib data dirty, in pages.
    std::FILE* statm = std::fopen("/proc/self/statm", "r");
    if (!statm) return 0;
    unsigned long long size = 0, resident = 0;
    const int read = std::fscanf(statm, "%llu %llu", &size, &resident);
    std::fclose(statm);
    return read == 2 ? uint64_t(resident) * uint64_t(::sysconf(_SC_PAGESIZE)) : 0;
}

std::string checkMemory(const Limits& limits) {
    const uint64_t used = residentBytes() >> 20;
    if (used <= uint64_t(limits.memoryMB)) return "";
    return fmt::format("the scene takes {} MB of memory while it is read, over the limit of {} MB ({})", used,
                       limits.memoryMB, limitHint(limits, &Limits::memoryMB));
}

uint64_t saturatingBytes(uint64_t count, uint64_t size) {
    if (size != 0 && count > std::numeric_limits<uint64_t>::max() / size) return std::numeric_limits<uint64_t>::max();
    return count * size;
}

} // namespace drt
