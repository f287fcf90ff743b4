// mesh-file = "mesh" "{" "file" string { object-modifier } "}": a model file
// (OBJ, PLY, glTF 2.0) whose triangles are read after parsing
// (assets/model_load.cpp). The file is found beside the including file, then
// beside the scene.
#include "lang/parser.h"

#include <filesystem>

namespace fs = std::filesystem;

namespace drt {

Mesh Parser::meshFile() {
    advance(); // file
    const Token file = expect(TokenKind::String, "the model file name in quotes");
    auto source = std::make_shared<MeshSource>();
    source->kind = MeshSource::Kind::ModelFile;
    source->loc = file.loc;
    std::error_code ec;
    for (const std::string& dir : {sources_.back().dir, sources_.front().dir}) {
        const fs::path candidate =
            fs::path(file.text).is_absolute() ? fs::path(file.text) : fs::path(dir) / file.text;
        if (fs::is_regular_file(candidate, ec)) {
            source->path = fs::absolute(candidate, ec).lexically_normal().string();
            break;
        }
    }
    if (source->path.empty())
        fail(file.loc, "cannot find model file '" + file.text + "'");
    Mesh m;
    m.source = std::move(source);
    return m;
}

} // namespace drt
