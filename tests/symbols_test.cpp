// The reader's identifiers (lang/symbols.h): one hash table of names with
// their bindings per scope, checked against the stack of per-scope maps it
// replaced, and through scenes whose #local, #declare, #undef and macro
// parameters shadow each other.
#include "lang/symbols.h"
#include "pov/load.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <map>
#include <random>

namespace drt::lang {
namespace {

// The reader's scopes before the hash table: a map per scope, searched from the innermost.
struct MapScopes {
    std::vector<std::map<std::string, Cell>> scopes;
    Cell find(const std::string& name) const {
        for (auto it = scopes.rbegin(); it != scopes.rend(); ++it)
            if (auto found = it->find(name); found != it->end()) return found->second;
        return nullptr;
    }
    Cell* findBelow(size_t open, const std::string& name) {
        for (size_t i = open; i-- > 0;)
            if (auto found = scopes[i].find(name); found != scopes[i].end()) return &found->second;
        return nullptr;
    }
    Cell* findIn(size_t scope, const std::string& name) {
        auto found = scopes[scope].find(name);
        return found == scopes[scope].end() ? nullptr : &found->second;
    }
    bool eraseInnermost(const std::string& name) {
        for (auto it = scopes.rbegin(); it != scopes.rend(); ++it)
            if (it->erase(name)) return true;
        return false;
    }
    std::vector<std::pair<std::string, Cell>> all() const {
        std::vector<std::pair<std::string, Cell>> out;
        for (const auto& scope : scopes)
            for (const auto& [name, cell] : scope) out.emplace_back(name, cell);
        return out;
    }
};

std::vector<std::pair<std::string, Cell>> all(const Scopes& s) {
    std::vector<std::pair<std::string, Cell>> out;
    s.forEach([&](const std::string& name, const Cell& cell) { out.emplace_back(name, cell); });
    return out;
}

TEST(ReaderSymbols, HashTableAnswersAsTheMapsPerScopeDid) {
    std::mt19937 random(7);
    const auto pick = [&](size_t n) { return size_t(random() % n); };
    const std::vector<std::string> names{"A", "B", "Ab", "ba", "row_count", "col_count", "X1", "x1", "N", "Counter"};
    for (int run = 0; run < 20; ++run) {
        Scopes fast;
        MapScopes slow;
        fast.push();
        slow.scopes.emplace_back();
        for (int step = 0; step < 2000; ++step) {
            const std::string& name = names[pick(names.size())];
            const size_t size = slow.scopes.size();
            switch (pick(8)) {
            case 0: // an include or a macro call opens a scope
                if (size < 6) fast.push(), slow.scopes.emplace_back();
                break;
            case 1: // and ends it
                if (size > 1) fast.pop(), slow.scopes.pop_back();
                break;
            case 2: { // #local, or a macro parameter: a scope's own binding
                const size_t scope = pick(size);
                auto cell = std::make_shared<Value>(Value::makeFloat(step));
                fast.set(scope, name, cell);
                slow.scopes[scope][name] = cell;
                break;
            }
            case 3: { // #declare: the nearest existing binding below `open`, else a new global one
                const size_t open = 1 + pick(size);
                Cell* a = fast.findBelow(open, name);
                Cell* b = slow.findBelow(open, name);
                ASSERT_EQ(a == nullptr, b == nullptr);
                if (a) {
                    ASSERT_EQ(*a, *b);
                } else {
                    auto cell = std::make_shared<Value>(Value::makeFloat(-step));
                    fast.set(0, name, cell);
                    slow.scopes[0][name] = cell;
                }
                break;
            }
            case 4: { // #local over an existing binding of the scope
                const size_t scope = pick(size);
                Cell* a = fast.findIn(scope, name);
                Cell* b = slow.findIn(scope, name);
                ASSERT_EQ(a == nullptr, b == nullptr);
                if (a) {
                    ASSERT_EQ(*a, *b);
                }
                break;
            }
            case 5: // #undef
                ASSERT_EQ(fast.eraseInnermost(name), slow.eraseInnermost(name));
                break;
            default: // a use
                ASSERT_EQ(fast.find(name), slow.find(name)) << name;
                ASSERT_EQ(fast.get(name), slow.find(name).get()) << name;
                break;
            }
            ASSERT_EQ(fast.size(), slow.scopes.size());
        }
        // Every name, for suggestions: scope by scope, each scope's names sorted.
        EXPECT_EQ(all(fast), slow.all());
    }
}

TEST(ReaderSymbols, NameFilterNeverMissesANameItHolds) {
    NameFilter filter;
    std::vector<std::string> held;
    for (int i = 0; i < 500; ++i) {
        held.push_back("Macro_" + std::to_string(i * 7919));
        filter.add(held.back());
    }
    for (const std::string& name : held) EXPECT_TRUE(filter.mayHold(name)) << name;
    NameFilter empty;
    EXPECT_FALSE(empty.mayHold("Anything"));
}

std::vector<std::string> warnings(const std::string& text) {
    auto r = test::readSceneText(text, true, {});
    EXPECT_FALSE(r->diags.hasErrors()) << r->diags.formatAll();
    return r->messages;
}

TEST(ReaderSymbols, LocalsDeclaresUndefsAndParametersShadowAsBefore) {
    // A macro's #local shadows the global; its #declare of a name bound only
    // globally updates the global; a parameter shadows a global of its name
    // and, passed a lone identifier, writes through to it.
    EXPECT_EQ(warnings("#declare V = 1;\n"
                       "#macro M(V, W) #local V = V + 10; #declare G = V; #declare W = W * 2; #end\n"
                       "#declare G = 0; #declare Out = 3;\n"
                       "M(5, Out)\n"
                       "#warning concat(str(V, 0, 0), \" \", str(G, 0, 0), \" \", str(Out, 0, 0))\n"),
              (std::vector<std::string>{"1 15 6"}));
    // Nested calls with the same parameter name: each sees its own; after
    // them the global is the one left.
    EXPECT_EQ(warnings("#declare N = 100;\n"
                       "#macro Inner(N) #warning str(N, 0, 0) #end\n"
                       "#macro Outer(N) Inner(N + 1) #warning str(N, 0, 0) #end\n"
                       "Outer(1)\n#warning str(N, 0, 0)\n"),
              (std::vector<std::string>{"2", "1", "100"}));
    // #undef removes the innermost binding only: the global shows again.
    EXPECT_EQ(warnings("#declare A = 1;\n"
                       "#macro M() #local A = 2; #undef A #warning str(A, 0, 0) #undef A "
                       "#ifndef (A) #warning \"gone\" #end #end\n"
                       "M()\n#ifndef (A) #warning \"still gone\" #end\n"),
              (std::vector<std::string>{"1", "gone", "still gone"}));
    // A name that was a macro and is then a number (and the other way round)
    // is expanded only while it is a macro.
    EXPECT_EQ(warnings("#macro F() 7 #end\n"
                       "#warning str(F(), 0, 0)\n"
                       "#undef F\n#declare F = 3;\n#warning str(F, 0, 0)\n"
                       "#undef F\n#macro F() 8 #end\n#warning str(F(), 0, 0)\n"),
              (std::vector<std::string>{"7", "3", "8"}));
    // A #local in a loop body inside a macro stays in the macro's scope across passes.
    EXPECT_EQ(warnings("#macro Sum(K) #local S = 0; #local I = 1; #while (I <= K) #local S = S + I; "
                       "#local I = I + 1; #end S #end\n"
                       "#declare I = 50;\n#warning concat(str(Sum(4), 0, 0), \" \", str(I, 0, 0))\n"),
              (std::vector<std::string>{"10 50"}));
}

} // namespace
} // namespace drt::lang
