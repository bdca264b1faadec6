// Internal to surface_chain*.cpp: the compiled form of each pattern, texture, mixture
// and material record that SurfaceChains holds, shared by the builder
// (surface_chain.cpp) and the evaluator (surface_chain_eval.cpp). Not a public API.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "calc/data_file.h"
#include "calc/program.h"
#include "material/chain_pict.h"
#include "material/chain_text.h"
#include "material/surface_chain.h"
#include "scene/xform.h"
#include "util/spectrum.h"

namespace rp::material {

enum class ChainKind : uint8_t {
    NotModifier,  // a surface: cannot be in a chain
    Unsupported,  // a modifier type this module does not evaluate (an alias)
    Material,
    Spectrum,  // spectrum, specfile: a constant colour
    SpecFunc,
    SpecData,
    SpecPict,
    Func,  // colorfunc, brightfunc
    Data,  // colordata, brightdata
    Pict,  // colorpict
    Text,  // colortext, brighttext
    TexFunc,
    TexData,
    MixFunc,
    MixData,
    MixPict,
    MixText,
};

inline bool isMixtureKind(ChainKind k) {
    return k == ChainKind::MixFunc || k == ChainKind::MixData || k == ChainKind::MixPict ||
           k == ChainKind::MixText;
}

// A .cal function named by a record (rfunc, xfunc, mixing func ...), called with one or
// three values. RADIANCE compat (p_data.c): colordata/colorpict functions declared with
// fewer than three parameters get their own channel only.
struct NamedFunction {
    calc::Function fn;
    bool threeArgs = false;
};

struct ChainRecord {
    ChainKind kind = ChainKind::NotModifier;
    bool colour = false;  // three channels (colorfunc, colordata, colorpict, colortext)

    // Expressions: function components (colorfunc 3, brightfunc 1, texfunc 3), the
    // mixfunc coefficient, or the coordinates of data and picture lookups (pict: u, v).
    std::vector<int> exprIds;  // builder ids, until the program is built
    std::vector<calc::Entry> exprs;
    std::vector<std::string> funcNames;  // data/pict/texdata/mixdata/mixpict functions
    std::vector<NamedFunction> funcs;

    std::array<std::shared_ptr<const calc::DataFile>, 3> data{};  // one or three tables
    std::shared_ptr<const PictTable> pict;
    std::shared_ptr<const TextBlock> text;
    Color textFore{1, 1, 1}, textBack{1, 1, 1};  // colortext / brighttext
    Color constant{1, 1, 1};                     // spectrum, specfile
    double wlMin = 0, wlMax = 0;                 // specfunc: its range within -cw

    int32_t foreMod = kVoid, backMod = kVoid;  // mixtures ("void" is kVoid)

    Transform toObject;  // world -> the record's function space
    Transform forward;   // its transform arguments as written (object -> world)
    bool hasTransform = false;
    // Func and Data records: the value depends on D alone (no function file, and no
    // expression names P, N, T, Ts, Rdot, Lu or Lv). What lets the sources of a sky
    // share one emission direction table.
    bool directional = false;
};

struct SurfaceChains::Impl {
    Impl(const Scene& s, const spectral::Pass& p) : scene(&s), materials(s, false, p), pass(p) {}
    const Scene* scene = nullptr;
    MaterialTable materials;
    std::vector<ChainRecord> records;    // one per scene primitive
    std::vector<int32_t> plainMaterial;  // per primitive: the material if plain, else -2
    // The bands this chain renders: colours and spectra are converted to them.
    spectral::Pass pass;
    std::shared_ptr<const calc::Program> program;
};

}  // namespace rp::material
