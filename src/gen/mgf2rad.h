// mgf2rad(1): MGF (Materials and Geometry Format) to RADIANCE scene text, as RADIANCE's
// mgf2rad writes it: materials as plastic, metal, trans, glass, dielectric, light or glow
// (chosen from the MGF reflectances as mgf2rad chooses), faces as polygons (or smoothed
// triangles with a T-nor texture where vertex normals bend them), spheres, cylinders,
// cones and rings as themselves. The MGF reading itself is mgf_reader.h.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace rp::gen {

struct Mgf2radOptions {
    double glowDistance = 1e10;    // -g: emitters become glow with this radius (metres)
    double emitterMultiplier = 1;  // -e: emission scale
};

// Converts MGF text standing for the file `name` (includes are relative to its folder)
// into RADIANCE scene text: the entities' output only, no "##" header lines. Bad MGF is an
// InputError at the MGF file and line ("a.mgf:7: Undefined reference: f v1 v2 v3").
// `warnings` receives the first unknown entity's line ("a.mgf:3: Unknown entity: foo");
// `unknownEntities` their count, when given.
std::string mgfToRad(std::string_view mgf, const std::string& name, const Mgf2radOptions& opt,
                     std::vector<std::string>* warnings = nullptr,
                     unsigned* unknownEntities = nullptr);

// The command: mgf2rad [-g dist][-e mult] [file.mgf ..] (args[0] its name), reading
// `input` when no file is named, with RADIANCE's "##" header and per-file lines. Files
// are opened as named, relative to folder `from` ("" = the current one, where the shell
// would run it). -m (a separate materials file) is not supported.
std::string mgf2rad(const std::vector<std::string>& args, const std::string& input,
                    std::vector<std::string>& warnings, const std::string& from = "");

}  // namespace rp::gen
