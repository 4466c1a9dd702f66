#include "language/value_stack.hpp"

#include <algorithm>
#include <iterator>
#include <stdexcept>

namespace hexant::language {

Value ValueStack::pop() {
    if (values_.empty()) throw std::logic_error("hexant: value stack underflow");
    Value v = std::move(values_.back());
    values_.pop_back();
    return v;
}

Value& ValueStack::top() {
    if (values_.empty()) throw std::logic_error("hexant: value stack underflow");
    return values_.back();
}

std::vector<Value> ValueStack::close_frame() {
    if (frames_.empty()) throw std::logic_error("hexant: frame stack underflow");
    const std::size_t begin = frames_.back();
    frames_.pop_back();
    return take_above(begin);
}

std::string ValueStack::pop_name() {
    if (names_.empty()) throw std::logic_error("hexant: name stack underflow");
    std::string n = std::move(names_.back());
    names_.pop_back();
    return n;
}

void ValueStack::rewind(const Mark& m) {
    values_.resize(std::min(values_.size(), m.values));
    frames_.resize(m.frames);
    names_.resize(m.names);
}

std::vector<Value> ValueStack::take_above(std::size_t depth) {
    if (values_.size() < depth) return {};
    std::vector<Value> out(
        std::make_move_iterator(values_.begin() + static_cast<std::ptrdiff_t>(depth)),
        std::make_move_iterator(values_.end()));
    values_.resize(depth);
    return out;
}

}  // namespace hexant::language
