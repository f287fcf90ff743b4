// The identifiers of a read (private to src/lang): a stack of scopes, one per
// open file and macro call (the main file shares the global scope, the first),
// each binding names to cells. A name bound in several scopes means its
// binding in the innermost one.
//
// One hash table holds every name with its bindings, innermost last, so a
// lookup costs one hash whatever the number of scopes and names (POV-Ray's
// include files declare thousands); each scope lists the names it binds, so
// closing it removes just those.
#pragma once

#include "lang/lexer.h"
#include "lang/value.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace drt::lang {

class Scopes {
    struct Binding;
    using Bindings = std::vector<Binding>; // by scope, innermost last
    using Slot = std::pair<const std::string, Bindings>;

public:
    Scopes();
    size_t size() const { return names_.size(); }
    void push() { names_.emplace_back(); }
    // Closes the innermost scope: its names' bindings go.
    void pop();

    // The value of the innermost binding of `name`, or null (find() without a copy of the cell).
    const Value* get(const std::string& name) const {
        const auto it = table_.find(name);
        return it == table_.end() || it->second.empty() ? nullptr : it->second.back().cell.get();
    }
    // The cell of the innermost binding of `name`, or null.
    Cell find(const std::string& name) const {
        const auto it = table_.find(name);
        return it == table_.end() || it->second.empty() ? nullptr : it->second.back().cell;
    }
    // The binding of `name` in the innermost of scopes [0, open) that binds it, or null.
    Cell* findBelow(size_t open, const std::string& name);
    // The binding of `name` in scope `scope`, or null.
    Cell* findIn(size_t scope, const std::string& name);
    // Binds `name` to `cell` in scope `scope` (replacing its binding there).
    void set(size_t scope, const std::string& name, Cell cell);
    // Removes the innermost binding of `name` (#undef); false if it has none.
    bool eraseInnermost(const std::string& name);

    // Calls f(name, cell) for every binding: scope by scope from the global one,
    // each scope's names in sorted order.
    template <class F>
    void forEach(F&& f) const {
        for (size_t s = 0; s < names_.size(); ++s) {
            std::vector<const Slot*> slots(names_[s].begin(), names_[s].end());
            std::sort(slots.begin(), slots.end(), [](const Slot* a, const Slot* b) { return a->first < b->first; });
            for (const Slot* slot : slots)
                for (const Binding& b : slot->second)
                    if (b.scope == s) f(slot->first, b.cell);
        }
    }

    // find() and get() for a word token: its name's place in the table is
    // kept in the token (Token::symbol), checked against the name, so a
    // token replayed by a loop or a macro is looked up without a hash.
    Cell find(const Token& word) const {
        const Bindings& b = slotOf(word).second;
        return b.empty() ? nullptr : b.back().cell;
    }
    const Value* get(const Token& word) const {
        const Bindings& b = slotOf(word).second;
        return b.empty() ? nullptr : b.back().cell.get();
    }

    // Finds a word token's place in the table now, if it has none: a token of
    // a file's stream, before the reader copies it.
    void remember(const Token& word) const {
        if (word.symbolTable != id_ || !word.symbol) slotOf(word);
    }

private:
    struct Binding {
        size_t scope;
        Cell cell;
    };
    Slot& slotOf(const Token& word) const {
        if (word.symbolTable == id_ && word.symbol) {
            Slot* slot = static_cast<Slot*>(const_cast<void*>(word.symbol));
            if (slot->first == word.text) return *slot;
        }
        Slot& slot = *table_.try_emplace(word.text).first; // an entry without bindings for a name never bound
        word.symbol = &slot;
        word.symbolTable = id_;
        return slot;
    }
    uint32_t id_; // this table's number, for Token::symbolTable

    mutable std::unordered_map<std::string, Bindings> table_; // mutable: slotOf() adds names never bound
    std::vector<std::vector<Slot*>> names_; // per scope: the names it binds
};

// A set of names that answers "certainly not in it" from a name's length and
// its first and last characters, without hashing it: false positives, never
// false negatives.
class NameFilter {
public:
    void add(const std::string& name) { bits_[slot(name) >> 6] |= uint64_t(1) << (slot(name) & 63); }
    bool mayHold(const std::string& name) const {
        return (bits_[slot(name) >> 6] >> (slot(name) & 63) & 1) != 0;
    }

private:
    static size_t slot(const std::string& name) {
        if (name.empty()) return 0;
        const size_t h = size_t(uint8_t(name.front())) * 131 + size_t(uint8_t(name.back())) * 31 + name.size() * 7919;
        return h & (kBits - 1);
    }
    static constexpr size_t kBits = 4096;
    uint64_t bits_[kBits / 64] = {};
};

} // namespace drt::lang
