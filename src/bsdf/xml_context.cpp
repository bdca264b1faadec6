// XmlContext: line numbers for nodes of a parsed XML file (pugixml keeps byte offsets).
#include <strings.h>

#include <algorithm>
#include <cctype>

#include "bsdf/xml_detail.h"

namespace rp::bsdf::detail {

XmlContext::XmlContext(std::string path, const std::string& text) : path_(std::move(path)) {
    lineStarts_.push_back(0);
    for (std::size_t i = 0; i < text.size(); ++i)
        if (text[i] == '\n') lineStarts_.push_back(static_cast<std::ptrdiff_t>(i + 1));
}

SourceLoc XmlContext::locOfOffset(std::ptrdiff_t offset) const {
    const auto it = std::upper_bound(lineStarts_.begin(), lineStarts_.end(), offset);
    return {path_, static_cast<int>(it - lineStarts_.begin())};
}

SourceLoc XmlContext::loc(const pugi::xml_node& node) const {
    const std::ptrdiff_t off = node ? node.offset_debug() : -1;
    return off < 0 ? SourceLoc{path_, 0} : locOfOffset(off);
}

void XmlContext::fail(const pugi::xml_node& node, const std::string& message) const {
    throw InputError(loc(node), message);
}

std::string trimmedText(const pugi::xml_node& node) {
    std::string s = node.child_value();
    const auto notSpace = [](unsigned char c) { return !std::isspace(c); };
    s.erase(s.begin(), std::find_if(s.begin(), s.end(), notSpace));
    s.erase(std::find_if(s.rbegin(), s.rend(), notSpace).base(), s.end());
    return s;
}

bool textIs(const pugi::xml_node& node, const char* s) {
    return strcasecmp(trimmedText(node).c_str(), s) == 0;
}

}  // namespace rp::bsdf::detail
