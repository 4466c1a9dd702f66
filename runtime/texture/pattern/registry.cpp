// Every pattern hexant has, made once from the registered kinds
// (kinds.hpp): the texture evaluator's Kind of each, sorted by name.
#include <algorithm>

#include "runtime/texture/pattern/kinds.hpp"

namespace hexant::runtime::pattern {

namespace {

template <class... K>
std::vector<Kind> make_kinds(PatternKindList<K...>) {
    std::vector<Kind> all = {make_kind<K>()...};
    std::sort(all.begin(), all.end(), [](const Kind& a, const Kind& b) { return a.name < b.name; });
    return all;
}

const std::vector<Kind>& kind_table() {
    static const std::vector<Kind> all = make_kinds(PatternKinds{});
    return all;
}

}  // namespace

const Kind* find_kind(std::string_view name) {
    const auto& all = kind_table();
    const auto it = std::lower_bound(all.begin(), all.end(), name,
                                     [](const Kind& k, std::string_view n) { return k.name < n; });
    return it != all.end() && it->name == name ? &*it : nullptr;
}

const Setting* find_setting(const Kind& kind, std::string_view name) {
    for (const Setting& s : kind.settings)
        if (s.name == name) return &s;
    return nullptr;
}

const std::vector<const Kind*>& all_kinds() {
    static const std::vector<const Kind*> list = [] {
        std::vector<const Kind*> out;
        for (const Kind& k : kind_table()) out.push_back(&k);
        return out;
    }();
    return list;
}

}  // namespace hexant::runtime::pattern
