// RADIANCE name contexts (calc(1), "CONTEXTS"): a context is a string "`a`b" (innermost
// first); a name written in it is stored as "name`a`b" and looked up at "name`a`b", then
// "name`b", then "name". A leading '`' ("`x") means "this context only"; a trailing '`'
// ("x`") means the global name. Shared by the parser (definitions) and the linker.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace rp::calc {

constexpr char kContextMark = '`';

// Normalises a user-supplied context: "" stays global, "sky" becomes "`sky",
// "`a`b" is kept.
std::string contextString(std::string_view context);

// The name to try at search level `level` (0 = innermost), or nothing past the global
// level or when the name's marks forbid searching.
std::optional<std::string> qualifiedName(std::string_view name, std::string_view context,
                                         int level);

}  // namespace rp::calc
