// Lexer and recursive-descent parser for the RADIANCE .cal language (calc(1), ray.html
// "Function Files"). Produces Definitions and expression trees; syntax errors are
// InputErrors naming file:line. Context qualification of names lives in names.h.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "calc/ast.h"

namespace rp::calc {

// Parses a sequence of statements. `file` names the source in errors ("" for inline -e
// text); `firstLine` is the line number of the text's first line. Each definition's name
// is qualified with `context` (see names.h). A final ';' before end of text is optional.
std::vector<std::shared_ptr<const Definition>> parseDefinitions(std::string_view text,
                                                                const std::string& file,
                                                                const std::string& context,
                                                                int firstLine = 1);

// Parses one bare expression (a modifier's coordinate argument, a test input).
std::unique_ptr<Expr> parseExpression(std::string_view text, const SourceLoc& loc);

}  // namespace rp::calc
