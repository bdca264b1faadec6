// pkgBSDF: scene text placing an XML BSDF (RADIANCE's pkgBSDF.c, rewritten).
#include "gen/pkgbsdf.h"

#include <strings.h>

#include "calc/search_path.h"
#include "gen/gen_text.h"
#include "gen/mgf2rad.h"
#include "scene/reader.h"
#include "scene/scene_load.h"
#include "util/error.h"
#include "util/file_write.h"
#include "util/options.h"

namespace rp::gen {

namespace {

std::string baseName(const std::string& path) {
    size_t slash = path.rfind('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

// One BSDF material and its rectangle at z. RADIANCE compat (pkgBSDF.c): the material's
// thickness is z * 1.00004 and the rectangle sits at z * 0.00002 in front (so, almost at
// 0) or at z * 1.00002 behind, just outside the geometry the thickness spans.
std::string bsdfFace(const bsdf::BsdfData& b, double z) {
    const char* sfx = z > 1e-6 ? "_f" : z < -1e-6 ? "_b" : "";
    const char* name = b.name.c_str();
    std::string s =
        cformat("void BSDF m_%s%s\n6 %g %s.xml 0 1 0 .\n0\n0\n\n", name, sfx, z * 1.00004, name);
    z *= (z < 0) + 0.00002;
    s += cformat("m_%s%s polygon %s%s\n0\n0\n12\n", name, sfx, name, sfx);
    double w = .5 * b.width, h = .5 * b.height;
    s += cformat("\t%.6e\t%.6e\t%.6e\n", -w, -h, z);
    s += cformat("\t%.6e\t%.6e\t%.6e\n", w, -h, z);
    s += cformat("\t%.6e\t%.6e\t%.6e\n", w, h, z);
    s += cformat("\t%.6e\t%.6e\t%.6e\n\n", -w, h, z);
    return s;
}

}  // namespace

std::string pkgBsdfGeometry(const bsdf::BsdfData& b, const std::string& xmlArg,
                            const std::string& program) {
    if (b.mgf.empty()) return "";
    (void)program;
    // MGF messages name the XML file; includes are relative to its folder.
    std::string where = (b.path.empty() ? xmlArg : b.path) + " MGF block";
    unsigned unknown = 0;
    std::vector<std::string> warnings;
    std::string body = mgfToRad(b.mgf, where, {}, &warnings, &unknown);
    // RADIANCE runs "mgf2rad TEMPFILE"; its header lines name that file.
    std::string name = baseName(xmlArg) + ":MGFblock";
    std::string s = "## Translated from MGF Version 2.0\n## mgf2rad\n## mgf2rad " + name +
                    " ##############################\n" + body;
    if (unknown) s += cformat("## mgf2rad %s: %u unknown entities\n", name.c_str(), unknown);
    return s;
}

std::string pkgBsdfScene(const bsdf::BsdfData& b, bool instance, const std::string& xmlArg,
                         const std::string& program) {
    if (!(b.width > 1e-6 && b.height > 1e-6))
        throw InputError(SourceLoc{b.path.empty() ? xmlArg : b.path, 0}, "zero width or height");
    std::string s = "# Produced by: " + program + " " + baseName(xmlArg) + "\n";
    if (!b.materialName.empty() && !b.manufacturer.empty())
        s += "# Material '" + b.materialName + "' by '" + b.manufacturer + "'\n\n";
    if (b.mgf.empty()) return s + bsdfFace(b, 0);
    s += bsdfFace(b, b.thickness);
    if (b.rb) s += bsdfFace(b, -b.thickness);
    if (instance) return s + "void instance " + b.name + "_g\n1 " + b.name + ".oct\n0\n0\n\n";
    return s + pkgBsdfGeometry(b, xmlArg, program);
}

void writeBsdfOctree(const std::string& geometry, const std::string& octPath,
                     const std::string& headerLine) {
    // RADIANCE's pkgBSDF pipes the geometry into `oconv -f -`: a frozen RADIANCE octree.
    OconvRequest request;
    request.files = {"-"};
    request.standardInput = geometry;
    request.frozen = true;
    request.commandLine = headerLine;
    writeFileAtomically(octPath, oconvOutput(request));
}

namespace {

// TEMPORARY until bsdf/xml_load.cpp (the XML loader) is merged: src/CMakeLists.txt
// defines RP_HAVE_BSDF_LOADER when that file exists, and only then is the loader called.
std::shared_ptr<const bsdf::BsdfData> loadBsdf(const std::string& path) {
#ifdef RP_HAVE_BSDF_LOADER
    return bsdf::loadBsdfFile(path);
#else
    throw notSupportedYet(SourceLoc{path, 0}, "pkgBSDF before the XML BSDF loader is built");
#endif
}

}  // namespace

std::string pkgBSDF(const std::vector<std::string>& args, std::vector<std::string>& warnings,
                    const std::vector<std::string>& searchPath, const std::string& from) {
    (void)warnings;
    const std::string usage = "usage: pkgBSDF [-i][-s] input.xml ..";
    bool instance = false, toStdout = false;
    OptionTable table;
    table.defaultsStops = false;
    table.messages.unknown = [usage](const std::string& w) {
        return "unknown option '" + w + "'; " + usage;
    };
    table.add(customOption("-i", [&instance](OptionReader&) { instance = true; }));
    table.add(customOption("-s", [&toStdout](OptionReader&) { toStdout = true; }));
    std::vector<std::string> words = args;
    const size_t i0 = table.parse(words, 1).next;
    // RADIANCE compat (pkgBSDF): every word starting with '-' before the inputs is an
    // option, a lone "-" and -version among them.
    if (i0 < args.size() && !args[i0].empty() && args[i0][0] == '-')
        throw InputError(table.messages.unknown(args[i0]));
    size_t i = i0;
    if (i >= args.size()) throw InputError("missing XML input; " + usage);
    if (toStdout && i + 1 < args.size()) throw InputError("cannot send multiple BSDFs to stdout");
    std::string out;
    for (; i < args.size(); ++i) {
        const std::string& xml = args[i];
        if (xml.size() < 5 || strcasecmp(xml.c_str() + xml.size() - 4, ".xml") != 0)
            throw InputError(xml + ": input does not end in '.xml'");
        auto path = calc::findFile(xml, searchPath, from);
        if (!path) throw InputError(xml + ": cannot find BSDF file");
        auto b = loadBsdf(*path);
        std::string scene = pkgBsdfScene(*b, instance, xml, args[0]);
        if (instance && !b->mgf.empty())
            writeBsdfOctree(pkgBsdfGeometry(*b, xml, args[0]),
                            calc::inDirectory(from, b->name + ".oct"), "oconv -f -");
        if (toStdout)
            out += scene;
        else
            writeFileAtomically(calc::inDirectory(from, b->name + ".rad"), scene);
    }
    return out;
}

}  // namespace rp::gen
