// The values the actions work on while a scene is read (the Interpreter's
// value stack): the values rules leave for the rule around them, frames
// marking where a variable-length list (a call's arguments, a vector)
// begins, and the words (names, keywords) rules remember for the rule
// around them. Underflow is hexant's own fault: std::logic_error.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "language/value.hpp"

namespace hexant::language {

class ValueStack {
  public:
    void push(Value v) { values_.push_back(std::move(v)); }
    Value pop();
    Value& top();
    std::size_t depth() const { return values_.size(); }

    // A list begins here; close_frame() takes the values pushed since.
    void open_frame() { frames_.push_back(values_.size()); }
    std::vector<Value> close_frame();

    void push_name(std::string name) { names_.push_back(std::move(name)); }
    std::string pop_name();
    // The last name pushed and not yet popped ("" when none).
    const std::string& top_name() const {
        static const std::string none;
        return names_.empty() ? none : names_.back();
    }

    // Where all three stand, to go back to when a reading is abandoned (a
    // declaration kept as source).
    struct Mark {
        std::size_t values, frames, names;
    };
    Mark mark() const { return {values_.size(), frames_.size(), names_.size()}; }
    void rewind(const Mark& m);

    // The values above `depth`, taken off (none when fewer are left): what
    // one side of a time split pushed.
    std::vector<Value> take_above(std::size_t depth);

  private:
    std::vector<Value> values_;
    std::vector<std::size_t> frames_;
    std::vector<std::string> names_;
};

}  // namespace hexant::language
