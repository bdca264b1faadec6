// xform: transform a RADIANCE scene description (see src/gen/xform_scene.h, xform(1)).
#include <iostream>

#include "gen/xform_scene.h"
#include "util/error.h"
#include "util/warnings.h"

int main(int argc, char** argv) {
    std::ios::sync_with_stdio(false);
    rp::setWarningSink([](const std::string& m) { std::cerr << "xform: warning: " << m << '\n'; });
    try {
        rp::XformOptions opts = rp::parseXformArgs(argc, argv, &std::cin);
        std::cout << rp::xformScene(opts, std::cin);
        std::cout.flush();
        return std::cout ? 0 : 1;
    } catch (const rp::InputError& e) {
        std::cout.flush();
        std::cerr << "xform: " << e.what() << '\n';
        return 1;
    }
}
