// The symbol table (language/symbol_table.hpp).
#include "language/symbol_table.hpp"

namespace hexant::language {

SymbolTable::SymbolTable(std::shared_ptr<MemoryBudget> memory) : memory_(std::move(memory)) {
    scopes_.emplace_back();  // the global scope
}

const Value* SymbolTable::lookup(const std::string& name) const {
    for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it) {
        auto found = it->find(name);
        if (found != it->end()) return &found->second.value;
    }
    return nullptr;
}

const runtime::Lifetime* SymbolTable::declared_when(const std::string& name) const {
    for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it) {
        auto found = it->find(name);
        if (found != it->end()) return &found->second.defined;
    }
    return nullptr;
}

void SymbolTable::declare(const std::string& name, Value value, bool local) {
    // #declare of a name local to the current macro or file changes that
    // local (a macro's parameter, say); otherwise it is global.
    if (!local && scopes_.size() > 1 && scopes_.back().count(name)) local = true;
    set(local ? scopes_.back() : scopes_.front(), name, std::move(value));
}

Array& SymbolTable::array_for_element(const std::string& name) {
    Value* target = nullptr;
    for (auto it = scopes_.rbegin(); it != scopes_.rend() && !target; ++it) {
        auto found = it->find(name);
        if (found != it->end()) target = &found->second.value;
    }
    if (!target) throw ValueError("undeclared array '" + name + "'");
    // (An array is shared, not copied, by the sides of a time split: an
    // element set on one side would be seen on the other.)
    if (!logs_.empty())
        throw PiecewiseError(
            "an array element set under a branch whose condition depends on clock; "
            "hexant cannot yet make an array piecewise in time (declare a float or "
            "vector under the branch instead)");
    if (!target->is<std::shared_ptr<Array>>()) throw ValueError("'" + name + "' is not an array");
    return *target->as<std::shared_ptr<Array>>();
}

bool SymbolTable::undefine(const std::string& name) {
    for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it)
        if (it->count(name)) {
            log_change(*it, name);
            it->erase(name);
            return true;
        }
    return false;
}

const Value* SymbolTable::innermost(const std::string& name) const {
    const auto found = scopes_.back().find(name);
    return found == scopes_.back().end() ? nullptr : &found->second.value;
}

void SymbolTable::assign(const std::string& name, Value value) {
    for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it)
        if (it->count(name)) {
            set(*it, name, std::move(value));
            return;
        }
    throw ValueError("'" + name + "' is not declared");
}

void SymbolTable::set_outer(const std::string& name, const Value& value) {
    for (std::size_t level = scopes_.size() - 1; level-- > 0;)
        if (scopes_[level].count(name)) {
            set(scopes_[level], name, value);
            return;
        }
}

void SymbolTable::set(Scope& scope, const std::string& name, Value value) {
    log_change(scope, name);
    const std::size_t bytes = string_bytes(value);
    auto [slot, added] = scope.try_emplace(name);
    Variable& variable = slot->second;
    variable.charge.attach(memory_);
    try {
        variable.charge.set(bytes);
    } catch (const ValueError&) {
        if (added) scope.erase(slot);  // past the budget: no variable made
        throw;
    }
    variable.value = std::move(value);
    variable.defined = runtime::Lifetime::always();  // declared now
}

void SymbolTable::log_change(const Scope& scope, const std::string& name) {
    if (logs_.empty() || restoring_) return;
    Log& log = logs_.back();
    const std::size_t index = static_cast<std::size_t>(&scope - scopes_.data());
    if (index >= log.scopes) return;  // a scope of this side's own (a macro's)
    Key key{index, name};
    if (log.before.count(key)) return;
    log.before.emplace(key, held(key));
}

void SymbolTable::begin_side() {
    logs_.push_back({scopes_.size(), {}});
}

SymbolTable::Changes SymbolTable::end_side() {
    Log log = std::move(logs_.back());
    logs_.pop_back();
    Changes after;
    restoring_ = true;
    for (auto& [key, before] : log.before) {
        after[key] = held(key);
        set_held(key, before);
    }
    restoring_ = false;
    return after;
}

std::optional<SymbolTable::Held> SymbolTable::held(const Key& key) const {
    if (key.first >= scopes_.size()) return std::nullopt;
    const Scope& scope = scopes_[key.first];
    const auto found = scope.find(key.second);
    if (found == scope.end()) return std::nullopt;
    return Held{found->second.value, found->second.defined};
}

void SymbolTable::set_held(const Key& key, const std::optional<Held>& value) {
    Scope& scope = scopes_[key.first];
    if (value) {
        set(scope, key.second, value->value);
        scope[key.second].defined = value->defined;
    } else {
        log_change(scope, key.second);
        scope.erase(key.second);
    }
}

}  // namespace hexant::language
