// Context qualification of .cal names (see names.h).
#include "calc/names.h"

namespace rp::calc {

std::string contextString(std::string_view context) {
    if (context.empty() || context.front() == kContextMark) return std::string(context);
    return std::string(1, kContextMark) + std::string(context);
}

std::optional<std::string> qualifiedName(std::string_view name, std::string_view context,
                                         int level) {
    if (name.empty()) return std::nullopt;
    if (name.front() == kContextMark) {  // explicit local: never search outward
        if (level > 0) return std::nullopt;
        name.remove_prefix(1);
    } else if (name.back() == kContextMark) {  // explicit global
        if (level > 0) return std::nullopt;
        return std::string(name.substr(0, name.size() - 1));
    }
    // Skip `level` context components ("`a", "`b", ...) from the innermost end.
    std::size_t pos = 0;
    for (int i = 0; i < level; ++i) {
        if (pos >= context.size()) return std::nullopt;
        std::size_t next = context.find(kContextMark, pos + 1);
        pos = next == std::string_view::npos ? context.size() : next;
    }
    if (level > 0 && pos > context.size()) return std::nullopt;
    return std::string(name) + std::string(context.substr(pos));
}

}  // namespace rp::calc
