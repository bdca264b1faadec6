// cnt's odometer (see cnt.h).
#include "data/cnt.h"

#include <string>
#include <vector>

namespace rp::data {

void writeCounts(std::span<const int> counts, std::ostream& out) {
    std::vector<int> n;
    for (int c : counts) {
        if (c == 0) break;  // RADIANCE's list ends at a zero
        if (c < 0) return;  // its loop never runs
        n.push_back(c);
    }
    std::vector<int> i(n.size(), 0);
    std::string line;
    for (;;) {
        line.clear();
        for (int v : i) (line += '\t') += std::to_string(v);
        line += '\n';
        out.write(line.data(), static_cast<std::streamsize>(line.size()));
        std::size_t k = n.size();
        while (k > 0 && ++i[k - 1] == n[k - 1]) i[--k] = 0;
        if (k == 0) return;
    }
}

}  // namespace rp::data
