// Where .cal and data files are found: RADIANCE's RAYPATH, a colon-separated list of
// directories searched in order. Without RAYPATH the default is "." then the directory
// the caller names (tools pass the project's lib/ folder, e.g. from their own
// RP_SOURCE_DIR or install prefix; the library has no compiled-in path).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rp::calc {

// Splits "a:b::c" into {"a", "b", "c"} (empty entries dropped).
std::vector<std::string> splitSearchPath(std::string_view raypath);

// RAYPATH from the environment when set and not empty, else {".", projectLibDir}
// (projectLibDir omitted when empty).
std::vector<std::string> defaultSearchPath(const std::string& projectLibDir);

// RADIANCE getpath(): names that are absolute or start with "./" or "../" are used as
// given; others are tried in each directory in turn. Nothing if no readable file exists.
// `from`: the directory the search runs in ("" = the current one), where RADIANCE's
// xform has changed to (relative names and directories are seen from there).
std::optional<std::string> findFile(const std::string& name, std::span<const std::string> dirs,
                                    const std::string& from = "");

// RADIANCE's wordfile() on getpath(): the whitespace-separated words of file `name`,
// found on `dirs` as findFile finds it (the modifier lists of -aI/-aE, -tI/-tE and
// mkpmap's -apO/-apS/-aI/-aE). InputError `cannot open <what> file "<name>"` when it is
// nowhere or unreadable.
std::vector<std::string> readWordFile(const std::string& name, std::span<const std::string> dirs,
                                      const std::string& what);

// `path` as seen from directory `from` ("" = the current one): relative paths are joined
// to it, absolute ones kept.
std::string inDirectory(const std::string& from, const std::string& path);

}  // namespace rp::calc
