// The symbols of one reading of a scene (the Interpreter's symbol table):
// the scopes of #declare and #local (the global one, one per macro call
// and include file), what each variable holds and when it is declared, and
// the log that lets a side of a time split be read and then undone.
//
// The scopes follow POV-Ray 3.7's rules (its parser's symbol tables,
// source/backend/parser/tokenize.cpp): #local writes the innermost scope, #declare
// writes the global one unless the name is already local, and a name is
// looked up from the innermost scope out. Errors are ValueErrors for the
// caller to place.
#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "language/memory_budget.hpp"
#include "language/value.hpp"
#include "language/value_ops.hpp"
#include "runtime/time/lifetime.hpp"

namespace hexant::language {

class SymbolTable {
  public:
    // `memory` is the arrays' budget (Limits::array_memory): a variable's
    // string is charged to it too. The global scope is open.
    explicit SymbolTable(std::shared_ptr<MemoryBudget> memory);

    const std::shared_ptr<MemoryBudget>& memory() const { return memory_; }

    // The value `name` holds, from the innermost scope out; null when it is
    // not declared.
    const Value* lookup(const std::string& name) const;
    // When `name` is declared (always, or the pieces of time where one side
    // of a branch on clock declared it); null when it is not declared.
    const runtime::Lifetime* declared_when(const std::string& name) const;
    // #declare (`local` false) or #local. Throws ValueError past the memory
    // budget, changing nothing.
    void declare(const std::string& name, Value value, bool local);
    // The array `name` names, for an element to be set; throws ValueError
    // when it is undeclared or not an array, or when a side of a time split
    // is being read (the sides would share the array).
    Array& array_for_element(const std::string& name);
    // Sets `name` where it is declared, from the innermost scope out (an
    // output argument: trace()'s normal). Throws ValueError when it is not
    // declared.
    void assign(const std::string& name, Value value);
    // #undef: whether `name` was declared.
    bool undefine(const std::string& name);

    // A macro call's or include file's scope.
    void open_scope() { scopes_.emplace_back(); }
    void close_scope() { scopes_.pop_back(); }
    // A name in the innermost scope only (a macro's parameter); null when
    // that scope does not declare it.
    const Value* innermost(const std::string& name) const;
    // Sets `name` in the nearest scope outside the innermost that declares
    // it (a macro's reference parameter written back); none: nothing.
    void set_outer(const std::string& name, const Value& value);

    // ---- the sides of a time split (Interpreter::split_time)
    // A variable's place (its scope's depth, its name), and what it held
    // there: its value and when it is declared (none: not declared).
    using Key = std::pair<std::size_t, std::string>;
    struct Held {
        Value value;
        runtime::Lifetime defined;
    };
    using Changes = std::map<Key, std::optional<Held>>;
    // From now on, the variables of the scopes open now that change are
    // logged with what they held before.
    void begin_side();
    // Puts every variable the side changed back as it was at begin_side();
    // gives what the side left them holding.
    Changes end_side();
    // How many sides are being read, one inside the other.
    std::size_t sides_open() const { return logs_.size(); }
    std::optional<Held> held(const Key& key) const;
    // Sets (or, with none, removes) the variable at `key`, logged as any
    // change (the merge of two sides writes through it).
    void set_held(const Key& key, const std::optional<Held>& value);

  private:
    // A variable: its value, what its string's characters are charged to
    // the memory budget (an array charges itself), and when it is declared.
    struct Variable {
        Value value;
        MemoryCharge charge;
        runtime::Lifetime defined;
    };
    using Scope = std::unordered_map<std::string, Variable>;
    // Sets the scope's variable `name` to `value`, charging a string's
    // characters; throws ValueError past the budget, changing nothing.
    void set(Scope& scope, const std::string& name, Value value);
    void log_change(const Scope& scope, const std::string& name);

    std::vector<Scope> scopes_;
    struct Log {
        std::size_t scopes = 0;  // how many were open when the side began
        Changes before;
    };
    std::vector<Log> logs_;
    bool restoring_ = false;  // writing back a log: not itself logged
    std::shared_ptr<MemoryBudget> memory_;
};

}  // namespace hexant::language
