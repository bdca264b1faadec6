#include "util/file_read.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>

#include "util/error.h"

namespace rp {

std::string readFileBytes(const std::string& path, size_t limit) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError(SourceLoc{path, 0},
                         std::string("cannot open file (") + std::strerror(errno) + ")");
    if (limit == 0) return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    std::string s(limit, '\0');
    in.read(s.data(), std::streamsize(limit));
    s.resize(size_t(in.gcount()));
    return s;
}

}  // namespace rp
