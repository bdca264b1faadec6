// InputReader (see illum_input.h).
#include "illum/illum_input.h"

#include <cctype>

#include "scene/lexer.h"

namespace rp::illum {

namespace {

bool isSpace(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

std::string describe(const InputObject& o) { return o.typeName + " '" + o.name + "'"; }

}  // namespace

bool InputReader::skipSpace() {
    while (pos_ < text_.size() && isSpace(text_[pos_])) {
        if (text_[pos_] == '\n') ++line_;
        ++pos_;
    }
    return pos_ < text_.size();
}

// RADIANCE fgetword: white space separated, or between matching quotes.
bool InputReader::readWord(std::string& word) {
    word.clear();
    if (!skipSpace()) return false;
    char quote = 0;
    if (text_[pos_] == '"' || text_[pos_] == '\'') quote = text_[pos_++];
    while (pos_ < text_.size() && (quote ? text_[pos_] != quote : !isSpace(text_[pos_]))) {
        if (text_[pos_] == '\n') ++line_;
        word += text_[pos_++];
    }
    if (quote) {
        if (pos_ >= text_.size()) return !word.empty();  // unterminated: what was read
        ++pos_;
    }
    return true;
}

std::string InputReader::readLine() {
    const size_t end = text_.find('\n', pos_);
    const size_t stop = end == std::string_view::npos ? text_.size() : end + 1;
    std::string line(text_.substr(pos_, stop - pos_));
    pos_ = stop;
    if (end != std::string_view::npos) ++line_;
    return line;
}

// A command line; a backslash before the newline continues it (RADIANCE fgetline), and
// the pair goes, as the shell would remove it.
std::string InputReader::readCommand() {
    std::string command;
    while (pos_ < text_.size()) {
        const char c = text_[pos_++];
        if (c == '\n') {
            ++line_;
            if (command.empty() || command.back() != '\\') break;
            command.pop_back();
            continue;
        }
        command += c;
    }
    if (!command.empty() && command.back() == '\r') command.pop_back();
    return command;
}

InputObject InputReader::readObject(const SourceLoc& loc) {
    InputObject o;
    o.loc = loc;
    std::string word;
    auto need = [&](const char* what) -> std::string& {
        if (!readWord(word)) {
            const std::string in = o.name.empty() ? "a primitive" : describe(o);
            throw InputError(loc, "unexpected end of input in " + in + " (expected " + what + ")");
        }
        return word;
    };
    o.modifier = need("a modifier");
    o.typeName = need("a primitive type");
    if (!primTypeFromName(o.typeName, o.type))
        throw InputError(loc, "unknown type '" + o.typeName + "'");
    o.name = need("an identifier");
    if (o.isAlias()) {
        o.aliasOf = need("the name of the aliased modifier");
        return o;
    }
    auto count = [&](const char* kind) {
        const std::string what = std::string("the number of ") + kind + " arguments";
        long n = 0;
        if (!rp::parseInteger(need(what.c_str()), n) || n < 0)
            throw InputError(here(), describe(o) + ": expected " + what + ", got '" + word + "'");
        return size_t(n);
    };
    const size_t ns = count("string");
    for (size_t i = 0; i < ns; ++i) o.sargs.push_back(need("a string argument"));
    // RADIANCE compat: its primitives keep no integer arguments (readfargs without IARGS).
    if (count("integer") != 0)
        throw InputError(here(), describe(o) + ": integer arguments are not allowed");
    const size_t nr = count("real");
    for (size_t i = 0; i < nr; ++i) {
        double v = 0;
        if (!rp::parseReal(need("a real argument"), v))
            throw InputError(here(), describe(o) + ": bad real argument '" + word + "'");
        o.rargs.push_back(v);
    }
    return o;
}

InputItem InputReader::next() {
    InputItem item;
    if (!skipSpace()) return item;
    item.loc = here();
    switch (text_[pos_]) {
        case '#':
            item.kind = InputItem::Kind::kComment;
            item.text = readLine();
            break;
        case '!':
            ++pos_;
            item.kind = InputItem::Kind::kCommand;
            item.text = readCommand();
            break;
        default:
            item.kind = InputItem::Kind::kObject;
            item.object = readObject(item.loc);
    }
    return item;
}

}  // namespace rp::illum
