// The documentation matches the repository: every relative link in README.md
// and docs/ resolves (files and #anchors), every Markdown table is well
// formed, docs/index.md shows every example with its picture, and no file
// points outside the repository or to the issue tracker.
#include "test_support.h"

#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace drt {
namespace {

struct Link {
    int line = 0;
    std::string target;
};

// The lines of a Markdown text outside fenced code blocks, with their numbers.
std::vector<std::pair<int, std::string>> proseLines(const std::string& markdown) {
    std::vector<std::pair<int, std::string>> out;
    std::istringstream in(markdown);
    std::string line;
    int number = 0;
    bool fenced = false;
    while (std::getline(in, line)) {
        ++number;
        if (line.rfind("```", 0) == 0) {
            fenced = !fenced;
            continue;
        }
        if (!fenced)
            out.emplace_back(number, line);
    }
    return out;
}

// Inline code spans removed (a link inside backticks is text, not a link).
std::string withoutCode(const std::string& line) {
    return std::regex_replace(line, std::regex("`[^`]*`"), "``");
}

std::vector<Link> linksOf(const std::string& markdown) {
    std::vector<Link> links;
    static const std::regex link(R"(\]\(([^)\s]+)(?:\s+"[^"]*")?\))");
    for (const auto& [number, line] : proseLines(markdown)) {
        const std::string text = withoutCode(line);
        for (std::sregex_iterator it(text.begin(), text.end(), link), end; it != end; ++it)
            links.push_back({number, (*it)[1].str()});
    }
    return links;
}

// GitHub's anchor of a heading: lower case, punctuation dropped, spaces to '-'.
std::string anchorOf(const std::string& heading) {
    std::string anchor;
    for (unsigned char c : heading) {
        if (std::isalnum(c) || c == '-' || c == '_')
            anchor += char(std::tolower(c));
        else if (c == ' ')
            anchor += '-';
        else if (c >= 0x80)
            anchor += char(c); // letters of other scripts are kept
    }
    return anchor;
}

std::set<std::string> anchorsOf(const std::string& markdown) {
    std::set<std::string> anchors;
    std::map<std::string, int> seen;
    for (const auto& [number, line] : proseLines(markdown)) {
        const size_t hashes = line.find_first_not_of('#');
        if (hashes == 0 || hashes == std::string::npos || line[hashes] != ' ')
            continue;
        const std::string base = anchorOf(line.substr(hashes + 1));
        const int n = seen[base]++;
        anchors.insert(n == 0 ? base : base + "-" + std::to_string(n));
    }
    return anchors;
}

std::vector<fs::path> markdownFiles() {
    std::vector<fs::path> files{test::sourcePath("README.md")};
    for (const auto& entry : fs::recursive_directory_iterator(test::sourcePath("docs")))
        if (entry.path().extension() == ".md")
            files.push_back(entry.path());
    return files;
}

TEST(DocsLinks, LinkAndAnchorExtraction) {
    const std::string md = "# A title, with `code`!\n## Twice\n## Twice\nsee [x](a.md#b) and ![i](img/p.png) "
                           "and `[not](a link)`\n```\n[no](fence.md)\n```\n";
    const auto links = linksOf(md);
    ASSERT_EQ(links.size(), 2u);
    EXPECT_EQ(links[0].target, "a.md#b");
    EXPECT_EQ(links[1].target, "img/p.png");
    EXPECT_EQ(anchorsOf(md), (std::set<std::string>{"a-title-with-code", "twice", "twice-1"}));
}

TEST(DocsLinks, EveryRelativeLinkResolves) {
    int checked = 0;
    for (const fs::path& file : markdownFiles()) {
        const std::string text = test::readFile(file.string());
        for (const Link& link : linksOf(text)) {
            const std::string& target = link.target;
            if (target.find("://") != std::string::npos || target.rfind("mailto:", 0) == 0)
                continue;
            ++checked;
            const std::string where = file.string() + ":" + std::to_string(link.line) + ": " + target;
            const size_t hash = target.find('#');
            const std::string pathPart = target.substr(0, hash);
            const fs::path resolved = pathPart.empty() ? file : (file.parent_path() / pathPart).lexically_normal();
            ASSERT_TRUE(fs::exists(resolved)) << where << " does not exist";
            const fs::path root = fs::path(test::sourcePath("")).lexically_normal();
            EXPECT_EQ(resolved.string().rfind(root.string(), 0), 0u) << where << " leaves the repository";
            if (hash != std::string::npos && resolved.extension() == ".md") {
                const auto anchors = anchorsOf(test::readFile(resolved.string()));
                EXPECT_TRUE(anchors.count(target.substr(hash + 1))) << where << ": no such heading";
            }
        }
    }
    EXPECT_GT(checked, 50);
}

// Unescaped '|' outside code spans: the cell separators of a table row.
int columnsOf(const std::string& row) {
    int pipes = 0;
    bool code = false;
    for (size_t i = 0; i < row.size(); ++i) {
        if (row[i] == '`')
            code = !code;
        else if (row[i] == '\\')
            ++i;
        else if (row[i] == '|' && !code)
            ++pipes;
    }
    return pipes - 1;
}

TEST(DocsLinks, EveryTableIsWellFormed) {
    EXPECT_EQ(columnsOf("| a | `b \\| c` | d |"), 3);
    for (const fs::path& file : markdownFiles()) {
        const auto lines = proseLines(test::readFile(file.string()));
        int headerColumns = 0;
        for (size_t i = 0; i < lines.size(); ++i) {
            const auto& [number, line] = lines[i];
            const std::string where = file.string() + ":" + std::to_string(number);
            const bool row = line.rfind("|", 0) == 0;
            const bool previousRow = i > 0 && lines[i - 1].second.rfind("|", 0) == 0 &&
                                     lines[i - 1].first == number - 1;
            if (!row) {
                headerColumns = 0;
                continue;
            }
            if (!previousRow) {
                // A table starts: header, then a |---| separator line.
                ASSERT_TRUE(i + 1 < lines.size() && lines[i + 1].second.rfind("|-", 0) == 0)
                    << where << ": a table row outside a table (a table needs a header and a |---| line)";
                EXPECT_TRUE(i == 0 || lines[i - 1].second.empty() || lines[i - 1].first != number - 1)
                    << where << ": a table must follow a blank line";
                headerColumns = columnsOf(line);
                continue;
            }
            EXPECT_EQ(columnsOf(line), headerColumns) << where << ": " << line;
        }
    }
}

TEST(DocsLinks, IndexShowsEveryExampleWithItsPicture) {
    const std::string index = test::readFile(test::sourcePath("docs/index.md"));
    int examples = 0;
    for (const auto& entry : fs::directory_iterator(test::sourcePath("examples"))) {
        if (entry.path().extension() != ".drt" && entry.path().extension() != ".pov")
            continue;
        ++examples;
        const std::string name = entry.path().stem().string();
        const std::string file = entry.path().filename().string();
        EXPECT_NE(index.find("(../examples/" + file + ")"), std::string::npos)
            << "docs/index.md does not link examples/" << file;
        EXPECT_NE(index.find("(images/" + name + ".png)"), std::string::npos)
            << "docs/index.md does not show images/" << name << ".png";
        EXPECT_TRUE(fs::exists(test::sourcePath("docs/images/" + name + ".png")))
            << "no picture docs/images/" << name << ".png for examples/" << file;
    }
    EXPECT_GE(examples, 20);
}

// Notes outside the repository and issue numbers mean nothing to a reader of
// the repository: documents and comments stand alone.
TEST(DocsLinks, NoFilePointsOutsideTheRepository) {
    const std::regex outside(R"(\.\./shared|[A-Z]+-NOTES\.md|[A-Z]+-NOTES\b)");
    const std::regex issue(R"(\b[Ii]ssues? #?\d+|\(#\d+\))");
    int scanned = 0;
    for (const char* folder : {"src", "tests", "docs", "grammar", "examples", ".ci"}) {
        for (const auto& entry : fs::recursive_directory_iterator(test::sourcePath(folder))) {
            const std::string ext = entry.path().extension().string();
            static const std::set<std::string> textual = {".cpp", ".h", ".md", ".drt", ".pov", ".inc", ".ebnf",
                                                          ".txt", ".sh", ".json", ".vim", ""};
            if (!entry.is_regular_file() || !textual.count(ext) || entry.path().filename() == "docs_links_test.cpp")
                continue;
            ++scanned;
            std::istringstream in(test::readFile(entry.path().string()));
            std::string line;
            for (int number = 1; std::getline(in, line); ++number) {
                EXPECT_FALSE(std::regex_search(line, outside)) << entry.path().string() << ":" << number << ": " << line;
                EXPECT_FALSE(std::regex_search(line, issue)) << entry.path().string() << ":" << number << ": " << line;
            }
        }
    }
    for (const char* file : {"README.md", "CMakeLists.txt"}) {
        const std::string text = test::readFile(test::sourcePath(file));
        EXPECT_FALSE(std::regex_search(text, outside)) << file;
        EXPECT_FALSE(std::regex_search(text, issue)) << file;
    }
    EXPECT_GT(scanned, 100);
}

} // namespace
} // namespace drt
