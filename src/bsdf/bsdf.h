// Measured and simulated BSDFs from LBNL's XML "WindowElement" files (WINDOW, genBSDF,
// pab-opto): Klems matrices (klems.cpp) and variable-resolution tensor trees
// (tensor_tree.cpp), loaded once per file (xml_load.cpp) into an immutable BsdfData that
// the BSDF/aBSDF materials read from any thread without locks or allocation.
//
// Conventions are RADIANCE's (bsdf.h of its BSDF library): local coordinates with +Z the
// surface normal on the "front" side (the room side for genBSDF output: WINDOW's front
// and back are swapped), +Y the material's up vector, +X = Y x Z; both vectors of a pair
// point away from the surface. Values are BSDFs per steradian. Each of the four
// scattering sets (front/back reflection, transmission entering from the front/back)
// is split as RADIANCE splits it: a Lambertian part (the minimum of the data, as a
// hemispherical reflectance or transmittance) and the rest, the "non-diffuse" part,
// which is evaluated, sized and importance-sampled here.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "util/color.h"
#include "util/vec.h"

namespace rp::bsdf {

// Projected solid angle queries (RADIANCE SDqueryMin / SDqueryMax).
enum class SizeQuery : uint8_t { Min = 1, Max = 2, MinMax = 3 };

// One non-diffuse scattering distribution (RADIANCE's SDComponent with its methods).
// Implementations precompute or cache what they need so that every call is lock-free
// and allocation-free after the first use of an incident direction.
class Distribution {
public:
    virtual ~Distribution() = default;

    // The BSDF value for the pair (either order; reciprocity is used where the data
    // has only one), black where this distribution has nothing for the pair.
    virtual Color value(const Vec3& in, const Vec3& out) const = 0;

    // RADIANCE queryProjSA: the projected solid angle of the data's cells at v1 (and at
    // v2 where given), folded into psa[0] (smallest, for Min and MinMax) and psa[1]
    // (largest, MinMax) or psa[0] (largest, Max). The caller initialises psa.
    virtual void projectedSolidAngle(const Vec3& v1, const Vec3* v2, SizeQuery q,
                                     double psa[2]) const = 0;

    // The directional-hemispherical scattering for light arriving from `in` (RADIANCE's
    // cTotal of the cumulative distribution), Y channel.
    virtual double hemispherical(const Vec3& in) const = 0;

    // An outgoing direction for `in` drawn with probability proportional to
    // value * |cos| (x uniform in [0,1); y a second uniform that a distribution may use
    // for the position inside the chosen cell: Klems data take it from x, as RADIANCE
    // does); false where there is nothing to sample (hemispherical <= 1e-6).
    virtual bool sample(const Vec3& in, double x, double y, Vec3& out) const = 0;

    // Whether the values have colour (CIE-X/Z matrices, CIE-u/v trees), not only Y.
    virtual bool coloured() const = 0;
};

// RADIANCE's SDSpectralDF: the non-diffuse part of one scattering set.
struct ScatteringSet {
    double minProjSA = kPi;  // smallest projected solid angle of any cell
    double maxHemi = 0;      // largest directional-hemispherical value over incidence
    std::vector<std::unique_ptr<Distribution>> components;
};

// Which side a scattering set belongs to.
enum class Set : uint8_t { ReflectFront, ReflectBack, TransmitFront, TransmitBack };

struct BsdfData {
    std::string path;          // as loaded, for messages
    std::string name;          // file name without folder and .xml (pkgBSDF's name)
    std::string materialName;  // <Material><Name>
    std::string manufacturer;  // <Material><Manufacturer>
    std::string mgf;           // <Geometry format="MGF"><MGFblock>, in metres, or empty
    double width = 0, height = 0, thickness = 0;  // metres

    // Lambertian parts as hemispherical values (RADIANCE rLambFront ... tLambBack: the
    // BSDF is value / pi).
    Color rLambFront, rLambBack, tLambFront, tLambBack;
    // Non-diffuse parts; rf: reflection at the front (+Z) side; tf: transmission of light
    // arriving from the front side (in.z > 0, out.z < 0); tb the reverse.
    std::optional<ScatteringSet> rf, rb, tf, tb;
    std::shared_ptr<const void> keepAlive;  // tables the components refer to (angle bases)

    // The set for a reflection (both vectors on one side) or transmission, as RADIANCE
    // picks it: transmission falls back to the other direction's data (reciprocity).
    const ScatteringSet* reflection(bool front) const { return front ? ptr(rf) : ptr(rb); }
    const ScatteringSet* transmission(bool inFront) const {
        const ScatteringSet* s = inFront ? ptr(tf) : ptr(tb);
        return s ? s : (inFront ? ptr(tb) : ptr(tf));
    }
    bool hasTransmission() const { return tf || tb; }
    // Whether any part has colour: a Lambertian part that is not grey, or a coloured
    // distribution.
    bool coloured() const;

    // The whole BSDF (Lambertian plus non-diffuse) for the pair (RADIANCE SDevalBSDF).
    Color evaluate(const Vec3& in, const Vec3& out) const;
    // RADIANCE SDsizeBSDF: psa[0] (and psa[1] for MinMax) for v1 (and v2), pi where the
    // sets concerned are all diffuse.
    void size(const Vec3& v1, const Vec3* v2, SizeQuery q, double psa[2]) const;
    // RADIANCE SDdirectHemi with SDsampSp{R,T} (non-diffuse reflection or transmission
    // for light from `in`), Y.
    double nonDiffuseHemispherical(const Vec3& in, bool transmission) const;

private:
    static const ScatteringSet* ptr(const std::optional<ScatteringSet>& s) {
        return s ? &*s : nullptr;
    }
};

// A Klems BSDF as a matrix of coefficients, RADIANCE's for rmtxop and dctimestep (cmbsdf.c
// cm_loadBTDF, cm_loadBRDF): rows are outgoing patches and columns incident ones, each
// entry the BSDF (Lambertian part included) times the incident patch's projected solid
// angle, so that the matrix maps incident radiance per patch to outgoing radiance.
// Transmission is for light arriving from the back (+Z is the room side), from the
// front's data by reciprocity where that is all there is; a set with no non-diffuse data
// is its Lambertian part on the Klems Full basis (145 x 145).
enum class MatrixPart : uint8_t { Transmission, ReflectionFront, ReflectionBack };
struct CoefficientMatrix {
    int rows = 0, cols = 0;
    std::vector<Color> values;  // row by row
};
// Throws InputError for data that are not one Klems matrix (a tensor tree).
CoefficientMatrix klemsCoefficients(const BsdfData& d, MatrixPart part);

// Loads and checks an XML BSDF file. Throws InputError "file:line: message" for a file
// that cannot be read, broken XML, a file that is not a BSDF, an unknown basis, or
// scattering data of the wrong size; notSupportedYet for data RADIANCE cannot read either.
std::shared_ptr<const BsdfData> loadBsdfFile(const std::string& path);
// The same for the file's text; `path` names it in messages and gives the BSDF's name.
std::shared_ptr<const BsdfData> parseBsdfText(const std::string& text, const std::string& path);

}  // namespace rp::bsdf
