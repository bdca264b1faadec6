// loadBsdfFile: reads an LBNL WindowElement file (bsdf.c SDloadFile, SDloadGeometry) and
// hands its first optical layer to the Klems or tensor-tree reader.
#include <strings.h>

#include <fstream>
#include <sstream>

#include "bsdf/xml_detail.h"

namespace rp::bsdf {

namespace detail {

void finishSets(BsdfData& sd) {
    for (std::optional<ScatteringSet>* s : {&sd.rf, &sd.rb, &sd.tf, &sd.tb})
        if (*s && (*s)->maxHemi <= .001) s->reset();
}

}  // namespace detail

namespace {

using detail::XmlContext;

// Metres per unit (bsdf.c to_meters); no unit means metres.
double toMetres(const pugi::xml_node& node, const XmlContext& ctx) {
    const pugi::xml_attribute a = node.attribute("unit");
    if (!a) return 1;
    const char* u = a.value();
    if (!strcasecmp(u, "Meter")) return 1;
    if (!strcasecmp(u, "Foot")) return .3048;
    if (!strcasecmp(u, "Inch")) return .0254;
    if (!strcasecmp(u, "Centimeter")) return .01;
    if (!strcasecmp(u, "Millimeter")) return .001;
    ctx.fail(node, std::string("unknown unit '") + u + "'");
}

double dimension(const pugi::xml_node& matl, const char* tag, const XmlContext& ctx) {
    pugi::xml_node n = matl.child(tag);
    if (!n) return 0;
    const double v = std::atof(n.child_value()) * toMetres(n, ctx);
    if (v < 0) ctx.fail(n, std::string("negative ") + tag);
    return v;
}

void loadGeometry(const pugi::xml_node& layer, const XmlContext& ctx, BsdfData& sd) {
    if (pugi::xml_node matl = layer.child("Material")) {
        sd.materialName = detail::trimmedText(matl.child("Name"));
        sd.manufacturer = detail::trimmedText(matl.child("Manufacturer"));
        sd.width = dimension(matl, "Width", ctx);
        sd.height = dimension(matl, "Height", ctx);
        sd.thickness = dimension(matl, "Thickness", ctx);
    }
    pugi::xml_node geom = layer.child("Geometry");
    if (!geom) return;
    const pugi::xml_attribute fmt = geom.attribute("format");
    if (fmt && strcasecmp(fmt.value(), "MGF"))
        ctx.fail(geom, std::string("unrecognized geometry format '") + fmt.value() + "'");
    pugi::xml_node block = geom.child("MGFblock");
    const std::string mgf = detail::trimmedText(block);
    if (mgf.empty()) return;
    // RADIANCE wraps other units in a scaling transform (its ".5f" precision kept).
    const double f = toMetres(block, ctx);
    if (f < .99 || f > 1.01) {
        char head[64];
        std::snprintf(head, sizeof head, "xf -s %.5f\n", f);
        sd.mgf = head + mgf + "\nxf\n";
    } else {
        sd.mgf = mgf;
    }
}

std::string baseName(const std::string& path) {
    std::string n = path.substr(path.find_last_of('/') + 1);
    if (n.size() > 4 && !strcasecmp(n.c_str() + n.size() - 4, ".xml")) n.resize(n.size() - 4);
    return n;
}

}  // namespace

std::shared_ptr<const BsdfData> loadBsdfFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(SourceLoc{path, 0}, "cannot open BSDF file");
    std::ostringstream ss;
    ss << in.rdbuf();
    return parseBsdfText(ss.str(), path);
}

std::shared_ptr<const BsdfData> parseBsdfText(const std::string& text, const std::string& path) {
    const XmlContext ctx(path, text);
    pugi::xml_document doc;
    const pugi::xml_parse_result res = doc.load_buffer(text.data(), text.size());
    if (!res)
        throw InputError(ctx.locOfOffset(res.offset), std::string("bad XML: ") + res.description());
    pugi::xml_node top = doc.document_element();
    if (std::string(top.name()) != "WindowElement")
        ctx.fail(top, "not a BSDF file (top-level element is not 'WindowElement')");
    pugi::xml_node ft = top.child("FileType");
    if (ft && detail::trimmedText(ft) != "BSDF") ctx.fail(ft, "wrong FileType (must be 'BSDF')");
    pugi::xml_node layer = top.child("Optical").child("Layer");
    if (!layer) ctx.fail(top, "BSDF file has no optical layer");
    auto sd = std::make_shared<BsdfData>();
    sd->path = path;
    sd->name = baseName(path);
    loadGeometry(layer, ctx, *sd);
    const std::string ids =
        detail::trimmedText(layer.child("DataDefinition").child("IncidentDataStructure"));
    if (!strncasecmp(ids.c_str(), "TensorTree", 10))
        detail::loadTensorTree(layer, ctx, *sd);
    else
        detail::loadKlems(layer, ctx, *sd);
    detail::finishSets(*sd);
    return sd;
}

}  // namespace rp::bsdf
