// Every example scene and every ```drt block in the docs parses without errors.
//
// Convention: a fence tagged exactly ```drt holds a complete scene and is parsed
// on its own; fences with any other tag (```text, ```sh, ...) are not parsed.
#include "lang/load.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

namespace fs = std::filesystem;

namespace drt {
namespace {

struct Snippet {
    std::string file;
    int line = 0; // line of the opening fence
    std::string text;
};

// The ```drt blocks of a Markdown text.
std::vector<Snippet> drtFences(const std::string& file, const std::string& markdown) {
    std::vector<Snippet> out;
    std::istringstream in(markdown);
    std::string line;
    int number = 0;
    Snippet* open = nullptr;
    bool inOtherFence = false;
    while (std::getline(in, line)) {
        ++number;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const bool fence = line.rfind("```", 0) == 0;
        if (open) {
            if (fence) open = nullptr;
            else open->text += line + "\n";
        } else if (inOtherFence) {
            if (fence) inOtherFence = false;
        } else if (line == "```drt") {
            out.push_back({file, number, ""});
            open = &out.back();
        } else if (fence) {
            inOtherFence = true;
        }
    }
    return out;
}

TEST(Docs, FenceExtractionFindsOnlyDrtBlocks) {
    const auto fences = drtFences("t.md", "text\n```drt\nsphere { 0, 1 }\n```\n```sh\nls\n```\n```drt\nplane { y, 0 }\n```\n");
    ASSERT_EQ(fences.size(), 2u);
    EXPECT_EQ(fences[0].line, 2);
    EXPECT_EQ(fences[0].text, "sphere { 0, 1 }\n");
    EXPECT_EQ(fences[1].text, "plane { y, 0 }\n");
}

TEST(Docs, EveryDrtFenceInTheDocsParses) {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(test::sourcePath("docs"))) {
        if (entry.path().extension() != ".md") continue;
        for (const Snippet& s : drtFences(entry.path().string(), test::readFile(entry.path().string()))) {
            ++count;
            Diagnostics diags;
            const auto scene = loadSceneText(s.text, s.file + " (block at line " + std::to_string(s.line) + ")",
                                             diags, entry.path().parent_path().string());
            EXPECT_TRUE(scene && !diags.hasErrors()) << diags.formatAll();
        }
    }
    // language.md alone has a block for every section.
    EXPECT_GE(count, 10);
}

TEST(Docs, EveryExampleSceneParses) {
    const fs::path examples = test::sourcePath("examples");
    if (!fs::exists(examples)) GTEST_FAIL() << "no examples/ folder";
    int count = 0;
    for (const auto& entry : fs::recursive_directory_iterator(examples)) {
        if (entry.path().extension() != ".drt") continue;
        ++count;
        Diagnostics diags;
        const auto scene = loadSceneFile(entry.path().string(), diags);
        EXPECT_TRUE(scene && !diags.hasErrors()) << entry.path() << "\n" << diags.formatAll();
    }
    RecordProperty("examples", count);
}

} // namespace
} // namespace drt
