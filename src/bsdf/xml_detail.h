// Internals shared by the XML loader (xml_load.cpp) and the two data formats it hands
// a <Layer> to: Klems matrices (klems.cpp) and tensor trees (tensor_tree.cpp).
#pragma once

#include <pugixml.hpp>
#include <string>

#include "bsdf/bsdf.h"
#include "util/error.h"

namespace rp::bsdf::detail {

// The file being loaded: its name and a map from a node to its line, for messages.
class XmlContext {
public:
    XmlContext(std::string path, const std::string& text);
    const std::string& path() const { return path_; }
    SourceLoc loc(const pugi::xml_node& node) const;
    SourceLoc locOfOffset(std::ptrdiff_t offset) const;
    [[noreturn]] void fail(const pugi::xml_node& node, const std::string& message) const;

private:
    std::string path_;
    std::vector<std::ptrdiff_t> lineStarts_;
};

// Case-insensitive comparison of an element's text (trimmed) with `s`, as RADIANCE does.
bool textIs(const pugi::xml_node& node, const char* s);
std::string trimmedText(const pugi::xml_node& node);

// The non-diffuse sets of a Klems layer (IncidentDataStructure Rows or Columns), with the
// Lambertian parts extracted as bsdf_m.c extracts them.
void loadKlems(const pugi::xml_node& layer, const XmlContext& ctx, BsdfData& sd);

// The same for a TensorTree3 / TensorTree4 layer (bsdf_t.c).
void loadTensorTree(const pugi::xml_node& layer, const XmlContext& ctx, BsdfData& sd);

// Fills minProjSA and maxHemi of a set from its components, and drops sets whose
// maxHemi is insignificant (<= .001, as SDloadFile).
void finishSets(BsdfData& sd);

}  // namespace rp::bsdf::detail
