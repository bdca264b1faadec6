// A small coloured Klems BSDF for tests (bsdf and material): front reflection only ("Reflection
// Back" in WINDOW's terms), on the Klems Quarter basis, with CIE-X and CIE-Z matrices at a
// constant ratio X : Y : Z = 1.2 : 1 : 0.5 to the visible one, whose values vary over the
// matrix between 0.05 and 0.15. Test code only.
#pragma once

#include <string>

namespace rp::bsdf {

inline std::string colouredKlemsXml() {
    auto block = [](const char* wl, double scale) {
        std::string vals;
        for (int k = 0; k < 41 * 41; ++k)
            vals += std::to_string(scale * (0.05 + 0.001 * ((k * 37) % 101))) + " ";
        return std::string("<WavelengthData><Wavelength>") + wl +
               "</Wavelength><WavelengthDataBlock>"
               "<WavelengthDataDirection>Reflection Back</WavelengthDataDirection>"
               "<ColumnAngleBasis>LBNL/Klems Quarter</ColumnAngleBasis>"
               "<RowAngleBasis>LBNL/Klems Quarter</RowAngleBasis><ScatteringData>" +
               vals + "</ScatteringData></WavelengthDataBlock></WavelengthData>";
    };
    return "<?xml version=\"1.0\"?>\n<WindowElement><FileType>BSDF</FileType><Optical><Layer>"
           "<DataDefinition><IncidentDataStructure>Columns</IncidentDataStructure>"
           "</DataDefinition>" +
           block("Visible", 1) + block("CIE-X", 1.2) + block("CIE-Z", .5) +
           "</Layer></Optical></WindowElement>\n";
}

}  // namespace rp::bsdf
