// mkillum's input, read as a stream in the order it is written (RADIANCE mkillum.c
// filter and xobject): comment lines (some of them `#@mkillum` settings), "!command"
// lines, aliases and primitives, whose words are kept as written, unresolved: mkillum
// copies what it does not convert. Scene loading for rendering is scene/reader.h.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "scene/primitive.h"
#include "util/error.h"

namespace rp::illum {

// One primitive or alias as written.
struct InputObject {
    std::string modifier;
    std::string typeName;  // as written; "alias" for an alias
    PrimType type = PrimType::Polygon;
    std::string name;
    std::string aliasOf;  // alias: the name it copies
    std::vector<std::string> sargs;
    std::vector<double> rargs;
    SourceLoc loc;
    bool isAlias() const { return type == PrimType::Alias; }
};

// What the reader found next.
struct InputItem {
    enum class Kind { kComment, kCommand, kObject, kEnd };
    Kind kind = Kind::kEnd;
    std::string text;  // comment: the line from '#' with its newline; command: without '!'
    InputObject object;
    SourceLoc loc;
};

// Reads items from scene text one at a time. `file` names the text in SourceLocs.
class InputReader {
public:
    InputReader(std::string_view text, std::string file) : text_(text), file_(std::move(file)) {}

    // The next item. Errors (InputError at the item's line): an unknown type, a count
    // that is not a non-negative integer, integer arguments (RADIANCE keeps none), a real
    // argument that is not a number, and text ending inside a primitive.
    InputItem next();

private:
    bool skipSpace();
    bool readWord(std::string& word);
    std::string readLine();
    std::string readCommand();
    InputObject readObject(const SourceLoc& loc);
    SourceLoc here() const { return {file_, line_}; }

    std::string_view text_;
    std::string file_;
    size_t pos_ = 0;
    int line_ = 1;
};

}  // namespace rp::illum
