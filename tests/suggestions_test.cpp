// "Did you mean": drt::nearestWord picks the known word closest to a misspelt
// one, within a third of its length in edits, then a swap of two neighbours,
// then a keyword the word starts. Checked against the textbook full-table
// Levenshtein distance on random words, and for words far too long to be any
// keyword.
#include "core/diagnostics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

namespace {

size_t levenshtein(const std::string& a, const std::string& b) {
    std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
    for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (size_t i = 1; i <= a.size(); ++i)
        for (size_t j = 1; j <= b.size(); ++j)
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
    return d[a.size()][b.size()];
}

// The rule nearestWord documents, written out the slow way.
std::string expectedNearest(const std::string& word, const std::vector<std::string>& known) {
    const size_t allowed = std::max<size_t>(1, word.size() / 3);
    const std::string* best = nullptr;
    size_t bestDistance = allowed + 1;
    for (const std::string& k : known) {
        const size_t d = levenshtein(word, k);
        if (d < bestDistance) bestDistance = d, best = &k;
    }
    if (best && !best->empty()) return *best;
    for (const std::string& k : known)
        for (size_t i = 0; k.size() == word.size() && i + 1 < word.size(); ++i) {
            std::string swapped = word;
            std::swap(swapped[i], swapped[i + 1]);
            if (swapped == k) return k;
        }
    if (word.size() >= 4)
        for (const std::string& k : known)
            if (k.compare(0, word.size(), word) == 0) return k;
    return "";
}

const std::vector<std::string> keywords = {"sphere", "box", "cylinder", "cone", "plane", "torus", "pigment",
                                           "finish", "normal", "interior", "ior", "reflection", "width", "height",
                                           "max_trace_level", "area_light", "rgb", "rgbf", "translate", "rotate"};

} // namespace

TEST(Suggestions, TypicalTypos) {
    EXPECT_EQ(drt::nearestWord("sphre", keywords), "sphere");
    EXPECT_EQ(drt::nearestWord("pigmnet", keywords), "pigment");
    EXPECT_EQ(drt::nearestWord("widht", keywords), "width"); // two swapped neighbours
    EXPECT_EQ(drt::nearestWord("max_trace", keywords), "max_trace_level"); // cut short
    EXPECT_EQ(drt::nearestWord("banana", keywords), "");
    EXPECT_EQ(drt::nearestWord("", keywords), "");
}

TEST(Suggestions, AgreeWithTheFullTableOnRandomWords) {
    std::mt19937 random(20261203);
    std::vector<std::string> known = keywords;
    const std::string letters = "abcdeiorstx_";
    for (int n = 0; n < 30; ++n) { // short random keywords make close calls and ties likely
        std::string k(1 + random() % 6, 'a');
        for (char& c : k) c = letters[random() % letters.size()];
        known.push_back(k);
    }
    for (int trial = 0; trial < 3000; ++trial) {
        std::string word = known[random() % known.size()];
        const int edits = random() % 4;
        for (int e = 0; e < edits; ++e) {
            const size_t at = word.empty() ? 0 : random() % (word.size() + 1);
            const char c = letters[random() % letters.size()];
            switch (random() % 4) {
            case 0: word.insert(word.begin() + at, c); break;
            case 1: if (at < word.size()) word.erase(at, 1); break;
            case 2: if (at < word.size()) word[at] = c; break;
            default: if (at + 1 < word.size()) std::swap(word[at], word[at + 1]);
            }
        }
        ASSERT_EQ(drt::nearestWord(word, known), expectedNearest(word, known)) << "word '" << word << "'";
    }
}

TEST(Suggestions, AWordFarLongerThanAnyKeywordIsNotCompared) {
    // 100,000 characters against the keywords: the lengths alone rule every one
    // out (the full table would be 10^5 x 15 entries per keyword).
    const std::string garbage(100'000, 'q');
    EXPECT_EQ(drt::nearestWord(garbage, keywords), "");
    std::string almost = "max_trace_level";
    almost.insert(7, "zz");
    EXPECT_EQ(drt::nearestWord(almost, keywords), "max_trace_level");
}
