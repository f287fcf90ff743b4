// The editor grammars in grammar/ (a TextMate grammar for VS Code and other
// TextMate-based editors, and a Vim syntax file) are generated from
// grammar/drt.ebnf by the functions below. The tests check that every keyword
// of the grammar is highlighted by both, and that the committed files are what
// the generator makes from the current grammar. After a grammar change:
//   DRT_WRITE_EDITOR_GRAMMARS=1 build/tests/drt_tests --gtest_filter='EditorGrammars.*'
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <map>
#include <regex>
#include <set>
#include <sstream>

namespace drt {
namespace {

// What a keyword is, by where the grammar uses it; the first that applies wins.
enum class Kind { Directive, Function, Boolean, Constant, Block, Keyword };

using Keywords = std::map<std::string, Kind>;

struct Token {
    std::string text;
    bool terminal = false; // a quoted "..." or '...'
};

// The grammar's rules: name -> tokens of its right-hand side. EBNF comments
// (* ... *) are dropped; a rule ends at an unquoted ';'.
std::map<std::string, std::vector<Token>> parseRules(const std::string& ebnf) {
    std::vector<Token> tokens;
    for (size_t i = 0; i < ebnf.size();) {
        const char c = ebnf[i];
        if (ebnf.compare(i, 2, "(*") == 0) {
            const size_t end = ebnf.find("*)", i + 2);
            i = end == std::string::npos ? ebnf.size() : end + 2;
        } else if (c == '"' || c == '\'') {
            const size_t end = ebnf.find(c, i + 1);
            tokens.push_back({ebnf.substr(i + 1, end - i - 1), true});
            i = end + 1;
        } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
            size_t end = i;
            while (end < ebnf.size() && (std::isalnum(static_cast<unsigned char>(ebnf[end])) || ebnf[end] == '_'))
                ++end;
            tokens.push_back({ebnf.substr(i, end - i), false});
            i = end;
        } else if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
        } else {
            tokens.push_back({std::string(1, c), false});
            ++i;
        }
    }
    std::map<std::string, std::vector<Token>> rules;
    for (size_t i = 0; i + 1 < tokens.size(); ++i) {
        if (tokens[i].terminal || tokens[i + 1].terminal || tokens[i + 1].text != "=")
            continue;
        std::vector<Token>& body = rules[tokens[i].text];
        for (i += 2; i < tokens.size() && !(tokens[i].text == ";" && !tokens[i].terminal); ++i)
            body.push_back(tokens[i]);
    }
    return rules;
}

// The lexical rules describe characters, not words: their terminals ("e" of an
// exponent, "n" of a string escape) are not keywords.
const std::set<std::string> kLexicalRules = {"number", "exponent", "digits", "digit", "string",
                                             "identifier", "comment", "letter", "character", "newline"};

bool isWord(const std::string& text) {
    const size_t start = !text.empty() && text[0] == '#' ? 1 : 0;
    if (start >= text.size() || !(std::isalpha(static_cast<unsigned char>(text[start])) || text[start] == '_'))
        return false;
    return std::all_of(text.begin() + long(start), text.end(),
                       [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

Keywords extractKeywords(const std::string& ebnf) {
    Keywords keywords;
    auto classify = [&](const std::string& word, Kind kind) {
        auto [it, inserted] = keywords.emplace(word, kind);
        if (!inserted && kind < it->second)
            it->second = kind;
    };
    for (const auto& [rule, body] : parseRules(ebnf)) {
        if (kLexicalRules.count(rule))
            continue;
        for (size_t i = 0; i < body.size(); ++i) {
            const Token& t = body[i];
            if (!t.terminal || !isWord(t.text))
                continue;
            const Token* next = i + 1 < body.size() ? &body[i + 1] : nullptr;
            // A whole alternative on its own (| "pi" |), not part of a group or sequence.
            const bool afterBar = i == 0 || (!body[i - 1].terminal && body[i - 1].text == "|");
            const bool beforeBar = !next || (!next->terminal && next->text == "|");
            const bool standalone = afterBar && beforeBar;
            if (t.text[0] == '#')
                classify(t.text, Kind::Directive);
            else if (rule == "function")
                classify(t.text, Kind::Function);
            else if (rule == "boolean")
                classify(t.text, Kind::Boolean);
            else if (rule == "primary" && standalone)
                classify(t.text, Kind::Constant);
            else if (next && next->terminal && next->text == "{")
                classify(t.text, Kind::Block);
            else
                classify(t.text, Kind::Keyword);
        }
    }
    return keywords;
}

std::vector<std::string> wordsOf(const Keywords& keywords, Kind kind) {
    std::vector<std::string> words;
    for (const auto& [word, k] : keywords)
        if (k == kind)
            words.push_back(word[0] == '#' ? word.substr(1) : word);
    return words;
}

std::string joined(const std::vector<std::string>& words, const std::string& separator) {
    std::string out;
    for (const std::string& w : words)
        out += (out.empty() ? "" : separator) + w;
    return out;
}

const char* const kGenerated = "generated from grammar/drt.ebnf by tests/editor_grammar_test.cpp";

std::string textMateGrammar(const Keywords& keywords) {
    using nlohmann::ordered_json;
    auto words = [&](Kind kind) { return "\\b(?:" + joined(wordsOf(keywords, kind), "|") + ")\\b"; };
    ordered_json grammar = {
        {"comment", std::string("drt scene language (.drt), ") + kGenerated},
        {"name", "drt"},
        {"scopeName", "source.drt"},
        {"fileTypes", {"drt"}},
        {"patterns",
         {{{"include", "#comments"}},
          {{"include", "#strings"}},
          {{"include", "#directives"}},
          {{"include", "#numbers"}},
          {{"include", "#keywords"}}}},
        {"repository",
         {{"comments",
           {{"patterns",
             {{{"name", "comment.line.double-slash.drt"}, {"match", "//.*$"}},
              {{"include", "#block-comment"}}}}}},
          {"block-comment",
           {{"name", "comment.block.drt"},
            {"begin", "/\\*"},
            {"end", "\\*/"},
            {"patterns", {{{"include", "#block-comment"}}}}}}, // block comments nest
          {"strings",
           {{"name", "string.quoted.double.drt"},
            {"begin", "\""},
            {"end", "\""},
            {"patterns", {{{"name", "constant.character.escape.drt"}, {"match", "\\\\[\"\\\\nt]"}}}}}},
          {"directives",
           {{"name", "keyword.control.directive.drt"},
            {"match", "#\\s*(?:" + joined(wordsOf(keywords, Kind::Directive), "|") + ")\\b"}}},
          {"numbers",
           {{"name", "constant.numeric.drt"},
            {"match", "(?:\\b[0-9]+(?:\\.[0-9]*)?|\\.[0-9]+)(?:[eE][+-]?[0-9]+)?\\b"}}},
          {"keywords",
           {{"patterns",
             {{{"name", "support.function.drt"}, {"match", words(Kind::Function)}},
              {{"name", "constant.language.boolean.drt"}, {"match", words(Kind::Boolean)}},
              {{"name", "constant.language.drt"}, {"match", words(Kind::Constant)}},
              {{"name", "storage.type.drt"}, {"match", words(Kind::Block)}},
              {{"name", "keyword.other.drt"}, {"match", words(Kind::Keyword)}}}}}}}},
    };
    return grammar.dump(2) + "\n";
}

// Words Vim's :syn keyword takes as arguments rather than keywords.
const std::set<std::string> kVimReserved = {"contains", "oneline", "fold", "display", "extend", "concealends",
                                            "conceal", "cchar", "contained", "containedin", "nextgroup",
                                            "transparent", "skipwhite", "skipnl", "skipempty"};

std::string vimSyntax(const Keywords& keywords) {
    std::ostringstream out;
    out << "\" Vim syntax file for the drt scene language (.drt), " << kGenerated << ".\n"
        << "\" Install: copy grammar/vim/ into ~/.vim/ (or a plugin folder); see docs/editors.md.\n"
        << "if exists('b:current_syntax')\n  finish\nendif\n\n";
    const std::pair<Kind, const char*> groups[] = {{Kind::Function, "drtFunction"}, {Kind::Boolean, "drtBoolean"},
                                                   {Kind::Constant, "drtConstant"}, {Kind::Block, "drtBlock"},
                                                   {Kind::Keyword, "drtKeyword"}};
    for (const auto& [kind, group] : groups) {
        std::vector<std::string> plain, reserved;
        for (const std::string& w : wordsOf(keywords, kind))
            (kVimReserved.count(w) ? reserved : plain).push_back(w);
        for (size_t i = 0; i < plain.size(); i += 8) {
            const std::vector<std::string> line(plain.begin() + long(i),
                                                plain.begin() + long(std::min(plain.size(), i + 8)));
            out << "syn keyword " << group << " " << joined(line, " ") << "\n";
        }
        for (const std::string& w : reserved)
            out << "syn match " << group << " \"\\<" << w << "\\>\"\n";
    }
    out << "syn match drtDirective \"#\\s*\\%(" << joined(wordsOf(keywords, Kind::Directive), "\\|") << "\\)\\>\"\n"
        << "syn match drtNumber \"\\%(\\<\\d\\+\\%(\\.\\d*\\)\\=\\|\\.\\d\\+\\)\\%([eE][+-]\\=\\d\\+\\)\\=\\>\"\n"
        << "syn region drtString start=+\"+ skip=+\\\\[\"\\\\]+ end=+\"+ contains=drtEscape\n"
        << "syn match drtEscape contained +\\\\[\"\\\\nt]+\n"
        << "syn match drtComment \"//.*$\" contains=@Spell\n"
        << "syn region drtBlockComment start=\"/\\*\" end=\"\\*/\" contains=drtBlockComment,@Spell\n\n"
        << "hi def link drtFunction Function\n"
        << "hi def link drtBoolean Boolean\n"
        << "hi def link drtConstant Constant\n"
        << "hi def link drtBlock Structure\n"
        << "hi def link drtKeyword Keyword\n"
        << "hi def link drtDirective PreProc\n"
        << "hi def link drtNumber Number\n"
        << "hi def link drtString String\n"
        << "hi def link drtEscape SpecialChar\n"
        << "hi def link drtComment Comment\n"
        << "hi def link drtBlockComment Comment\n\n"
        << "let b:current_syntax = 'drt'\n";
    return out.str();
}

const char* const kTextMatePath = "grammar/vscode/syntaxes/drt.tmLanguage.json";
const char* const kVimPath = "grammar/vim/syntax/drt.vim";

Keywords grammarKeywords() { return extractKeywords(test::readFile(test::sourcePath("grammar/drt.ebnf"))); }

TEST(EditorGrammars, KeywordsAreReadFromTheGrammar) {
    const Keywords k = extractKeywords(R"ebnf((* a comment with "quoted" words *)
number = digits [ "e" digits ] ;
scene = { "#declare" identifier "=" thing ";" } ;
function = "sqrt" | "min" ;
boolean = "on" | "off" ;
primary = "pi" | ( "color" | "colour" ) colour | function "(" ")" ;
thing = "sphere" "{" "radius" float "}" | "<" ;
)ebnf");
    const Keywords expected = {{"#declare", Kind::Directive}, {"sqrt", Kind::Function}, {"min", Kind::Function},
                               {"on", Kind::Boolean},         {"off", Kind::Boolean},   {"pi", Kind::Constant},
                               {"color", Kind::Keyword},      {"colour", Kind::Keyword}, {"sphere", Kind::Block},
                               {"radius", Kind::Keyword}};
    EXPECT_EQ(k, expected);

    const Keywords real = grammarKeywords();
    EXPECT_GT(real.size(), 200u);
    EXPECT_EQ(real.at("#declare"), Kind::Directive);
    EXPECT_EQ(real.at("sphere"), Kind::Block);
    EXPECT_EQ(real.at("vcross"), Kind::Function);
    EXPECT_EQ(real.at("x"), Kind::Constant);
    EXPECT_EQ(real.at("phong_size"), Kind::Keyword);
}

// The first pattern (in order, as editors apply them) matching the whole word.
std::string textMateScopeOf(const nlohmann::json& grammar, const std::string& word) {
    std::vector<const nlohmann::json*> patterns;
    for (const auto& include : grammar.at("patterns")) {
        const nlohmann::json& entry = grammar.at("repository").at(include.at("include").get<std::string>().substr(1));
        if (entry.contains("patterns"))
            for (const auto& p : entry.at("patterns"))
                patterns.push_back(&p);
        else
            patterns.push_back(&entry);
    }
    for (const nlohmann::json* p : patterns) {
        if (!p->contains("match"))
            continue;
        std::smatch m;
        const std::string text = " " + word + " ";
        if (std::regex_search(text, m, std::regex(p->at("match").get<std::string>())) && m.position(0) == 1 &&
            m.length(0) == long(word.size()))
            return p->at("name").get<std::string>();
    }
    return "";
}

TEST(EditorGrammars, TextMateGrammarHighlightsEveryKeyword) {
    const auto grammar = nlohmann::json::parse(test::readFile(test::sourcePath(kTextMatePath)));
    EXPECT_EQ(grammar.at("scopeName"), "source.drt");
    for (const auto& [word, kind] : grammarKeywords()) {
        const std::string scope = textMateScopeOf(grammar, word);
        EXPECT_FALSE(scope.empty()) << word << " is not highlighted by " << kTextMatePath;
        if (kind == Kind::Directive) {
            EXPECT_EQ(scope, "keyword.control.directive.drt") << word;
        }
    }
    // Identifiers are not keywords.
    EXPECT_EQ(textMateScopeOf(grammar, "MyRedSphere"), "");
    EXPECT_EQ(textMateScopeOf(grammar, "spheres"), "");
}

TEST(EditorGrammars, VimSyntaxHighlightsEveryKeyword) {
    std::map<std::string, std::string> groupOf; // word -> syntax group
    std::istringstream in(test::readFile(test::sourcePath(kVimPath)));
    std::string line;
    std::string directives;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string command, type, group, word;
        words >> command >> type >> group;
        if (command == "syn" && type == "keyword")
            while (words >> word)
                groupOf[word] = group;
        static const std::regex wordMatch(R"re(^syn match (\w+) "\\<(\w+)\\>"$)re");
        std::smatch m;
        if (std::regex_match(line, m, wordMatch))
            groupOf[m[2]] = m[1];
        if (line.rfind("syn match drtDirective", 0) == 0)
            directives = line;
    }
    for (const auto& [word, kind] : grammarKeywords()) {
        if (kind == Kind::Directive)
            EXPECT_TRUE(std::regex_search(directives, std::regex("[(|]" + word.substr(1) + "\\\\[|)]")))
                << word << " is not highlighted by " << kVimPath;
        else
            EXPECT_TRUE(groupOf.count(word)) << word << " is not highlighted by " << kVimPath;
    }
    EXPECT_FALSE(groupOf.count("MyRedSphere"));
}

TEST(EditorGrammars, CommittedFilesAreGeneratedFromTheCurrentGrammar) {
    const Keywords keywords = grammarKeywords();
    const std::pair<const char*, std::string> files[] = {{kTextMatePath, textMateGrammar(keywords)},
                                                         {kVimPath, vimSyntax(keywords)}};
    const char* write = std::getenv("DRT_WRITE_EDITOR_GRAMMARS");
    for (const auto& [path, text] : files) {
        if (write && std::string(write) == "1")
            test::writeFile(test::sourcePath(path), text);
        EXPECT_EQ(test::readFile(test::sourcePath(path)), text)
            << path << " is out of date with grammar/drt.ebnf; regenerate it with\n"
            << "  DRT_WRITE_EDITOR_GRAMMARS=1 build/tests/drt_tests --gtest_filter='EditorGrammars.*'";
    }
}

} // namespace
} // namespace drt
