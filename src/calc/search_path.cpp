// RAYPATH handling (see search_path.h).
#include "calc/search_path.h"

#include <cstdlib>
#include <fstream>
#include <iterator>

#include "util/error.h"

namespace rp::calc {

std::vector<std::string> splitSearchPath(std::string_view raypath) {
    std::vector<std::string> dirs;
    std::size_t start = 0;
    while (start <= raypath.size()) {
        std::size_t end = raypath.find(':', start);
        if (end == std::string_view::npos) end = raypath.size();
        if (end > start) dirs.emplace_back(raypath.substr(start, end - start));
        start = end + 1;
    }
    return dirs;
}

std::vector<std::string> defaultSearchPath(const std::string& projectLibDir) {
    if (const char* env = std::getenv("RAYPATH"); env && *env) return splitSearchPath(env);
    std::vector<std::string> dirs{"."};
    if (!projectLibDir.empty()) dirs.push_back(projectLibDir);
    return dirs;
}

static bool readable(const std::string& path) {
    std::ifstream f(path);
    return f.good();
}

std::string inDirectory(const std::string& from, const std::string& path) {
    if (from.empty() || path.empty() || path.front() == '/') return path;
    return from.ends_with('/') ? from + path : from + "/" + path;
}

std::optional<std::string> findFile(const std::string& name, std::span<const std::string> dirs,
                                    const std::string& from) {
    if (name.empty()) return std::nullopt;
    if (name.front() == '/' || name.starts_with("./") || name.starts_with("../")) {
        std::string path = inDirectory(from, name);
        return readable(path) ? std::optional<std::string>(path) : std::nullopt;
    }
    for (const std::string& dir : dirs) {
        std::string path = dir.empty() || dir == "." ? name : dir + "/" + name;
        if (dir.ends_with('/')) path = dir + name;
        path = inDirectory(from, path);
        if (readable(path)) return path;
    }
    return std::nullopt;
}

std::vector<std::string> readWordFile(const std::string& name, std::span<const std::string> dirs,
                                      const std::string& what) {
    const std::optional<std::string> path = findFile(name, dirs);
    std::ifstream in(path ? *path : name);
    if (!path || !in) throw InputError("cannot open " + what + " file \"" + name + "\"");
    return {std::istream_iterator<std::string>(in), std::istream_iterator<std::string>()};
}

}  // namespace rp::calc
