// getinfo: print the information header of RADIANCE files (see src/image/getinfo.h).
#include "image/getinfo.h"

#include <iostream>

#include "util/error.h"

int main(int argc, char** argv) {
    std::ios::sync_with_stdio(false);
    try {
        rp::GetinfoOptions opt = rp::parseGetinfoArgs(argc, argv);
        int status = rp::runGetinfo(opt, std::cin, std::cout, std::cerr);
        std::cout.flush();
        return status;
    } catch (const rp::InputError& e) {
        std::cout.flush();
        std::cerr << "getinfo: " << e.what() << '\n';
        return 1;
    }
}
