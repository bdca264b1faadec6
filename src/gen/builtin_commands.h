// Runs the generator commands that scene files embed (`!genbox ...`, `!genblinds ...`,
// `!xform ...`, `!gensky ... | xform ...`) with radphoton's own generators, in-process,
// so scenes load on machines without RADIANCE. Anything else (other programs,
// redirections, variables) is left to /bin/sh by the scene reader.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gen/xform_scene.h"
#include "scene/reader.h"
#include "util/error.h"

namespace rp::gen {

// Environment switch: when RADPHOTON_SHELL_COMMANDS is set to anything but "" or "0",
// every command goes to the shell, so a user's own PATH (e.g. RADIANCE's generators)
// wins.
constexpr const char* kShellCommandsEnv = "RADPHOTON_SHELL_COMMANDS";

// Splits a command line as /bin/sh would for the simple forms scene files use: words,
// '...' and "..." quoting, backslash escapes, and '|' between commands. nullopt when the
// line needs a real shell (redirection, ';', '&', variables, command substitution,
// globbing, comments, subshells).
std::optional<std::vector<std::vector<std::string>>> splitPipeline(std::string_view command);

// For LoadOptions::commandHook: the output of `command` if every stage of its pipeline
// is one of our generators (genblinds, genbox, genprism, gensky, gendaylit, genrev,
// gensurf, genworm, mgf2rad, pkgBSDF, xform), else nullopt. Generator errors are
// InputErrors at `loc` ("genbox: ..."), generator warnings are reported at `loc`.
std::optional<std::string> runBuiltinCommand(const std::string& command, const SourceLoc& loc);

// For xform's options: runs our generators in the folder and include chain of the file
// whose command it is (nullopt for anything else, which the shell runs there).
ContextCommandHook builtinCommandHook();

// LoadOptions with runBuiltinCommand installed: what every tool passes to loadScene.
LoadOptions builtinLoadOptions();

}  // namespace rp::gen
