// The .drt text of a user-defined function (scene/function.h), for the writer.
#pragma once

#include "scene/function.h"

#include <map>
#include <set>
#include <string>

namespace drt::writer {

// The body of `function { ... }` (its parameters are written by
// functionHead): one expression, calls of other functions written out in
// place, patterns and pigments as `pattern { ... } (a, b, c)`.
std::string functionText(const Function& f, std::set<std::string>& problems);
// "function " or "function(a, b) " as needed for f's parameters.
std::string functionHead(const Function& f);

} // namespace drt::writer

namespace drt::lang {
// The names of the functions a function body may call, shared by the reader and the writer.
const std::map<std::string, FnMath1>& functionMath1Words();
const std::map<std::string, FnMath2>& functionMath2Words();
} // namespace drt::lang
