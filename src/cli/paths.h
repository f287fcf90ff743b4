// Refusing outputs that would overwrite an input or another output, however
// the paths are spelt (./a.pov and a.pov, symbolic links, hard links).
#pragma once

#include <string>
#include <vector>

namespace drt::cli {

struct NamedPath {
    std::string role; // "the scene", "--variance", ...
    std::string path; // "" : not given
};

// Whether two paths name the same file: the same canonical path (the file need
// not exist), or the same inode when both exist.
bool sameFile(const std::string& a, const std::string& b);

// "" or the first clash, e.g. "the output -o 'a.pov' is the scene './a.pov'
// itself: it would be overwritten".
std::string outputClash(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs);

} // namespace drt::cli
