#include "lang/symbols.h"

#include <atomic>

namespace drt::lang {

Scopes::Scopes() {
    static std::atomic<uint32_t> tables{0};
    id_ = ++tables;
}

void Scopes::pop() {
    const size_t scope = names_.size() - 1;
    for (Slot* slot : names_.back()) {
        Bindings& b = slot->second;
        // The innermost scope's binding is the last of its name's.
        if (!b.empty() && b.back().scope == scope) b.pop_back();
    }
    names_.pop_back();
}

Cell* Scopes::findBelow(size_t open, const std::string& name) {
    const auto it = table_.find(name);
    if (it == table_.end()) return nullptr;
    Bindings& b = it->second;
    for (auto r = b.rbegin(); r != b.rend(); ++r)
        if (r->scope < open) return &r->cell;
    return nullptr;
}

Cell* Scopes::findIn(size_t scope, const std::string& name) {
    const auto it = table_.find(name);
    if (it == table_.end()) return nullptr;
    for (Binding& b : it->second)
        if (b.scope == scope) return &b.cell;
    return nullptr;
}

void Scopes::set(size_t scope, const std::string& name, Cell cell) {
    auto it = table_.try_emplace(name).first;
    Bindings& b = it->second;
    auto at = b.end();
    while (at != b.begin() && std::prev(at)->scope >= scope) --at;
    if (at != b.end() && at->scope == scope) {
        at->cell = std::move(cell);
        return;
    }
    b.insert(at, Binding{scope, std::move(cell)});
    names_[scope].push_back(&*it);
}

bool Scopes::eraseInnermost(const std::string& name) {
    const auto it = table_.find(name);
    if (it == table_.end() || it->second.empty()) return false;
    const size_t scope = it->second.back().scope;
    it->second.pop_back();
    std::vector<Slot*>& names = names_[scope];
    // Usually declared lately: search from the end.
    for (size_t i = names.size(); i-- > 0;)
        if (names[i] == &*it) {
            names[i] = names.back();
            names.pop_back();
            break;
        }
    return true;
}

} // namespace drt::lang
