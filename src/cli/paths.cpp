#include "cli/paths.h"

#include <filesystem>
#include <fmt/format.h>

namespace fs = std::filesystem;

namespace drt::cli {

bool sameFile(const std::string& a, const std::string& b) {
    std::error_code ec;
    if (fs::exists(a, ec) && fs::exists(b, ec) && fs::equivalent(a, b, ec)) return true;
    const fs::path ca = fs::weakly_canonical(fs::absolute(a, ec), ec);
    const fs::path cb = fs::weakly_canonical(fs::absolute(b, ec), ec);
    return ca.lexically_normal() == cb.lexically_normal();
}

std::string outputClash(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs) {
    for (size_t o = 0; o < outputs.size(); ++o) {
        const NamedPath& out = outputs[o];
        if (out.path.empty()) continue;
        for (const NamedPath& in : inputs)
            if (!in.path.empty() && sameFile(out.path, in.path))
                return fmt::format("the output {} '{}' is {} '{}': writing it would destroy the input", out.role,
                                   out.path, in.role, in.path);
        for (size_t other = 0; other < o; ++other)
            if (!outputs[other].path.empty() && sameFile(out.path, outputs[other].path))
                return fmt::format("the outputs {} '{}' and {} '{}' are the same file: one would replace the other",
                                   outputs[other].role, outputs[other].path, out.role, out.path);
    }
    return "";
}

} // namespace drt::cli
