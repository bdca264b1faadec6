// .cal text: compile it, then evaluate every variable it defines at a sample ray.
#include <cstddef>
#include <cstdint>
#include <string>

#include "calc/program.h"
#include "calc/ray_context.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        rp::calc::Builder b({});
        b.loadString(text, "fuzz.cal");
        const int e = b.addExpression("a + b(1, 2) + c", rp::SourceLoc{"fuzz", 1});
        auto prog = b.build();
        rp::calc::Evaluator ev(prog);
        rp::calc::RayContext ray;
        ev.setRay(ray);
        (void)ev.eval(prog->expression(e));
    } catch (const rp::InputError&) {
    }
    return 0;
}
