// .rad scene text: the reader with every "!command" refused (a fuzzer must never reach
// the shell) and the argument rules.
#include <cstddef>
#include <cstdint>
#include <string>

#include "scene/reader.h"
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
    } catch (const rp::InputError&) {
    }
    return 0;
}
