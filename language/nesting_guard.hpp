// How deep a scene may nest: parentheses, vectors, unary operators, nested
// comments, blocks, CSG, directives inside directives, bodies stepped over.
// The reader is recursive descent (PEGTL), so each level takes stack, and a
// generated scene could reach tens of thousands of levels (SIGSEGV at about
// 26,000 parentheses on an 8 MB stack). Rather than count each kind, the
// guard measures the resource itself: the stack used since the outermost
// parse began, checked when a nesting rule starts, against half the
// thread's stack limit (at most 8 MB counted). Past it the reader stops with
// an error at that place. It frees nothing and needs no unwinding: the
// measure is the stack pointer, so an exception caught and read on from
// cannot leave a count behind.
#pragma once

#include <cstddef>

#include <tao/pegtl.hpp>

namespace hexant::language {

class NestingGuard {
  public:
    // Marks the start of the outermost parse on this thread (nested
    // guards, for includes and --declare values, keep the outer mark).
    NestingGuard();
    ~NestingGuard();
    NestingGuard(const NestingGuard&) = delete;
    NestingGuard& operator=(const NestingGuard&) = delete;

    // Throws a parse_error at `in` when the stack used since the mark
    // exceeds the budget.
    template <typename ParseInput>
    static void check(const ParseInput& in) {
        const char probe = 0;
        if (base_ != nullptr && base_ - &probe > budget_)
            throw tao::pegtl::parse_error(
                "nested too deeply: the parentheses, blocks, directives or comments open here go "
                "deeper than the reader can follow (it would overflow its stack)",
                in);
    }

    // The budget in bytes (for tests).
    static std::ptrdiff_t budget() { return budget_; }

  private:
    static thread_local const char* base_;
    static thread_local std::ptrdiff_t budget_;
    bool outermost_ = false;
};

}  // namespace hexant::language
