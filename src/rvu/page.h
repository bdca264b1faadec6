#pragma once

#include <string_view>

namespace rp::rvu {

// The viewer's web page: one self-contained HTML document (style and script inline).
std::string_view pageHtml();

}  // namespace rp::rvu
