// The RADIANCE scene description reader: text -> Primitive records with SourceLocs,
// "!command" expansion, alias resolution and RADIANCE's modifier rule (the most recent
// definition before a use). Frozen scene files and octrees are loaded in scene_file.h.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "scene/primitive.h"

namespace rp {

// May intercept a "!command" before it goes to /bin/sh: given the command text (without
// the '!') and where it was written, returns the command's output as scene text, or
// nullopt to let the shell run it. Later issues plug built-in genbox/xform/gensky in here.
using CommandHook =
    std::function<std::optional<std::string>(const std::string& command, const SourceLoc& loc)>;

struct LoadOptions {
    CommandHook commandHook;   // default: none, every command goes to /bin/sh -c
    int maxCommandDepth = 32;  // commands whose output runs commands, and so on
    // Number objects and resolve modifier names exactly as RADIANCE does, as oconv must
    // for its octree: records the renderers skip (a polygon without area) are kept, and
    // a modifier redefined equal to the one its name stands for keeps the earlier one
    // (modifier_table.h).
    bool radianceNumbering = false;
    // Geometry only (getbbox): a modifier that is not defined reads as void, as RADIANCE's
    // readobj2 never looks modifiers up.
    bool geometryOnly = false;
};

// Accumulates primitives from any number of inputs, in order, into one Scene.
class SceneReader {
public:
    explicit SceneReader(LoadOptions options = {});

    // A scene description file; "-" reads standard input, "!cmd" runs a command as
    // RADIANCE's readobj() does. Records the input (path, mtime) in the scene.
    void readFile(const std::string& path);
    // The contents of file `path`, already read: records the input and parses it.
    void readContents(const std::string& path, std::string_view text);
    // Scene text from memory; `file` is the name SourceLocs carry. Records no input.
    void readText(std::string_view text, const std::string& file);
    // Appends already-resolved records (a frozen scene); later text may use its modifiers.
    void append(const Scene& other);

    // Records a file read by other means (a scene file or octree) for the stale check.
    void addInput(SceneInput input) { scene_.inputs.push_back(std::move(input)); }

    const Scene& scene() const { return scene_; }
    Scene take() { return std::move(scene_); }

private:
    struct Context;  // where the text being read came from
    void parse(std::string_view text, const Context& ctx);
    void parsePrimitive(class SceneLexer& lex, const Context& ctx);
    void runCommand(const std::string& command, const SourceLoc& loc, int depth);
    int32_t resolveModifier(const std::string& name, const SourceLoc& loc) const;
    void add(Primitive p);
    void index(int32_t i);  // enters record i in the name tables

    LoadOptions options_;
    Scene scene_;
    std::unordered_map<std::string, int32_t> modifiers_;  // name -> latest modifier
    std::unordered_map<std::string, int32_t> surfaces_;   // name -> latest surface
};

// Convenience for tools and tests: reads text as one file.
Scene parseScene(std::string_view text, const std::string& file = "", const LoadOptions& = {});

// Seconds since the epoch of the file's last modification, 0 if unknown.
int64_t fileMtime(const std::string& path);

}  // namespace rp
