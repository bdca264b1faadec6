// .rad scene text: the reader with every "!command" refused (a fuzzer must never reach
// the shell) and the argument rules; then, for text that reads, oconv's octree builder
// and writer over it (as `oconv -f -`).
#include <cstddef>
#include <cstdint>
#include <string>

#include "scene/reader.h"
#include "scene/scene_load.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    rp::LoadOptions opt;
    opt.commandHook = [](const std::string&,
                         const rp::SourceLoc& loc) -> std::optional<std::string> {
        throw rp::InputError(loc, "commands are off while fuzzing");
    };
    try {
        (void)rp::parseScene(text, "fuzz.rad", opt);
        rp::OconvRequest request;
        request.files = {"-"};
        request.standardInput = text;
        request.frozen = true;
        // RADIANCE's -r 16384 lets a few coincident surfaces split a plane's cells down to
        // 1/16384 of the cube (RADIANCE's oconv runs out of octree space on them too, and
        // ours gives its one-line out-of-memory error): keep the fuzzer's memory bounded.
        request.maxres = 256;
        (void)rp::oconvOutput(request, opt);
    } catch (const rp::InputError&) {
    }
    return 0;
}
