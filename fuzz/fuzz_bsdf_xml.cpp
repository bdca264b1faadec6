// LBNL XML BSDF files (Klems and tensor trees): parse, then query what loaded, and make
// the coefficient matrices of the matrix tools.
#include <cstddef>
#include <cstdint>
#include <string>

#include "bsdf/bsdf.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const auto sd = rp::bsdf::parseBsdfText(text, "fuzz.xml");
        const rp::Vec3 in{0.3, 0.2, 0.932}, out{-0.1, 0.4, -0.911};
        (void)sd->evaluate(in, out);
        (void)sd->nonDiffuseHemispherical(in, true);
        double psa[2];
        sd->size(in, &out, rp::bsdf::SizeQuery::MinMax, psa);
        for (const auto* set : {sd->reflection(true), sd->transmission(true)})
            if (set)
                for (const auto& c : set->components) {
                    rp::Vec3 o;
                    c->sample(in, 0.37, 0.61, o);
                }
        // rmtxop's and dctimestep's matrices of it (Klems data only; others throw).
        for (auto part : {rp::bsdf::MatrixPart::Transmission, rp::bsdf::MatrixPart::ReflectionFront,
                          rp::bsdf::MatrixPart::ReflectionBack})
            (void)rp::bsdf::klemsCoefficients(*sd, part);
    } catch (const rp::InputError&) {
    }
    return 0;
}
