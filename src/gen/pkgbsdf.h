// pkgBSDF(1): a RADIANCE scene that places an XML BSDF file: a "BSDF" material and a
// rectangle the size of the sample at its front (and, where the back reflects
// non-diffusely, its back), then the detailed geometry from the file's MGF block (as
// mgf2rad converts it) or, with -i, an instance of that geometry frozen as NAME.oct.
// Reading the XML is bsdf/bsdf.h; the MGF conversion is mgf2rad.h.
#pragma once

#include <string>
#include <vector>

#include "bsdf/bsdf.h"

namespace rp::gen {

// The scene text pkgBSDF prints for `bsdf`. `xmlArg` is the file as named on the command
// line (its folder is dropped in the "# Produced by" line). Without MGF there is one
// rectangle at z = 0; with it, one at the front (z = thickness) and one at the back where
// bsdf.rb is set, then the MGF geometry or, when `instance`, "void instance NAME_g"
// placing NAME.oct (which writeBsdfOctree makes). Zero width or height is an InputError.
std::string pkgBsdfScene(const bsdf::BsdfData& bsdf, bool instance, const std::string& xmlArg,
                         const std::string& program = "pkgBSDF");

// The BSDF's MGF geometry as RADIANCE text ("" without MGF): mgf2rad's output.
std::string pkgBsdfGeometry(const bsdf::BsdfData& bsdf, const std::string& xmlArg,
                            const std::string& program = "pkgBSDF");

// Freezes `geometry` (scene text) into a RADIANCE octree at `octPath`, written atomically
// (what RADIANCE's "mgf2rad ... | oconv -f - > NAME.oct" makes), `headerLine` its command.
void writeBsdfOctree(const std::string& geometry, const std::string& octPath,
                     const std::string& headerLine);

// The command: pkgBSDF [-i][-s] input.xml .. (args[0] its name). Each file is found along
// `searchPath` (RAYPATH, else "." only) as RADIANCE's getpath finds it. With -s (one file
// only) the scene is returned; without it, written to NAME.rad in folder `from` ("" = the
// current one) and "" returned. With -i, NAME.oct is written there too.
std::string pkgBSDF(const std::vector<std::string>& args, std::vector<std::string>& warnings,
                    const std::vector<std::string>& searchPath, const std::string& from = "");

}  // namespace rp::gen
