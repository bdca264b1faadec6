// The MGF reader: lines, includes and the entity contexts (RADIANCE's mgf_parser.c,
// mgf_context.c, mgf_object.c and mgf_xf.c, rewritten). Prism, torus and face-with-holes
// expansions are in mgf_expand.cpp.
#include "gen/mgf_reader.h"

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <sstream>
#include <unordered_map>

namespace rp::gen {

const char* mgfErrorMessage(MgfError e) {
    static const char* const kMessages[] = {"No error",
                                            "Unknown entity",
                                            "Wrong number of arguments",
                                            "Wrong argument type",
                                            "Illegal argument value",
                                            "Undefined reference",
                                            "Cannot open input file",
                                            "Error in included file",
                                            "Out of memory",
                                            "Seek failure",
                                            "Illegal material specification",
                                            "Input line too long",
                                            "Unmatched context close"};
    return kMessages[int(e)];
}

namespace {

const char* skipInt(const char* s) {
    while (std::isspace(static_cast<unsigned char>(*s))) ++s;
    s += (*s == '-') | (*s == '+');
    if (!std::isdigit(static_cast<unsigned char>(*s))) return nullptr;
    while (std::isdigit(static_cast<unsigned char>(*s))) ++s;
    return s;
}

const char* skipFloat(const char* s) {
    while (std::isspace(static_cast<unsigned char>(*s))) ++s;
    s += (*s == '-') | (*s == '+');
    const char* cp = s;
    while (std::isdigit(static_cast<unsigned char>(*cp))) ++cp;
    if (*cp == '.') {
        ++cp;
        ++s;
        while (std::isdigit(static_cast<unsigned char>(*cp))) ++cp;
    }
    if (cp == s) return nullptr;  // no digit at all
    if (*cp == 'e' || *cp == 'E')
        return std::isspace(static_cast<unsigned char>(cp[1])) ? nullptr : skipInt(cp + 1);
    return cp;
}

}  // namespace

bool mgfIsInt(const std::string& s) {
    const char* e = skipInt(s.c_str());
    return e && !*e;
}

bool mgfIsFloat(const std::string& s) {
    const char* e = skipFloat(s.c_str());
    return e && !*e;
}

bool mgfIsName(const std::string& s) {
    size_t i = 0;
    while (i < s.size() && s[i] == '_') ++i;
    if (i >= s.size() || !std::isalpha(static_cast<unsigned char>(s[i]))) return false;
    for (++i; i < s.size(); ++i)
        if (!std::isgraph(static_cast<unsigned char>(s[i]))) return false;
    return true;
}

double mgfNormalize(Vec3& v) {
    double d = dot(v, v);
    if (d == 0) return 0;
    double len, f;
    if (d <= 1 + 1e-6 && d >= 1 - 1e-6) {  // RADIANCE compat: first-order near unit length
        len = 0.5 + 0.5 * d;
        f = 2 - len;
    } else {
        len = std::sqrt(d);
        f = 1 / len;
    }
    v *= f;
    return len;
}

MgfReader::MgfReader(MgfHandler& handler) : handler_(handler) {}
MgfReader::~MgfReader() = default;

namespace {

std::vector<std::string> splitWords(const std::string& line) {
    std::vector<std::string> words;
    std::istringstream in(line);
    for (std::string w; in >> w;) words.push_back(w);
    return words;
}

}  // namespace

std::unique_ptr<MgfReader::File> MgfReader::makeFile(std::string_view text,
                                                     const std::string& name) {
    auto file = std::make_unique<File>();
    file->name = name;
    file->id = ++nextFileId_;
    std::string pending;
    int physical = 0;
    size_t pos = 0;
    while (pos < text.size()) {
        size_t end = text.find('\n', pos);
        std::string_view line = text.substr(pos, end == std::string_view::npos ? end : end - pos);
        pos = end == std::string_view::npos ? text.size() : end + 1;
        ++physical;
        if (!line.empty() && line.back() == '\\') {  // continued on the next line
            pending.append(line.substr(0, line.size() - 1)).push_back(' ');
            continue;
        }
        pending.append(line);
        file->lines.push_back(std::move(pending));
        file->lineNumbers.push_back(physical);
        pending.clear();
    }
    if (!pending.empty()) {
        file->lines.push_back(std::move(pending));
        file->lineNumbers.push_back(physical);
    }
    return file;
}

void MgfReader::loadText(std::string_view text, const std::string& name) {
    readFile(makeFile(text, name));
}

void MgfReader::loadFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(SourceLoc{path, 0}, mgfErrorMessage(MgfError::NoFile));
    std::ostringstream all;
    all << in.rdbuf();
    loadText(all.str(), path);
}

void MgfReader::readFile(std::unique_ptr<File> file) {
    files_.push_back(file.get());
    struct Pop {
        std::vector<File*>& files;
        ~Pop() { files.pop_back(); }
    } pop{files_};
    runLines(*file);
}

void MgfReader::runLines(File& file) {
    while (file.next < file.lines.size()) {
        const std::string& line = file.lines[file.next];
        file.lineNo = file.lineNumbers[file.next];
        ++file.next;
        MgfArgs words = splitWords(line);
        if (words.empty()) continue;
        try {
            handle(words);
        } catch (const MgfFailure& f) {
            std::string text;
            for (const std::string& w : words) text += (text.empty() ? "" : " ") + w;
            throw InputError(SourceLoc{file.name, file.lineNo},
                             std::string(mgfErrorMessage(f.error)) + ": " + text);
        }
    }
}

void MgfReader::handle(const MgfArgs& args) {
    using Fn = void (MgfReader::*)(const MgfArgs&);
    static const std::unordered_map<std::string, Fn> kEntities = {
        {"c", &MgfReader::colorEntity},
        {"cxy", &MgfReader::colorEntity},
        {"cspec", &MgfReader::colorEntity},
        {"cct", &MgfReader::colorEntity},
        {"cmix", &MgfReader::mixEntity},
        {"m", &MgfReader::materialEntity},
        {"ed", &MgfReader::materialProperty},
        {"ir", &MgfReader::materialProperty},
        {"rd", &MgfReader::materialProperty},
        {"rs", &MgfReader::materialProperty},
        {"sides", &MgfReader::materialProperty},
        {"td", &MgfReader::materialProperty},
        {"ts", &MgfReader::materialProperty},
        {"v", &MgfReader::vertexEntity},
        {"p", &MgfReader::vertexProperty},
        {"n", &MgfReader::vertexProperty},
        {"o", &MgfReader::objectEntity},
        {"xf", &MgfReader::xfEntity},
        {"i", &MgfReader::include},
        {"fh", &MgfReader::faceWithHoles},
        {"prism", &MgfReader::prism},
        {"torus", &MgfReader::torus},
    };
    const std::string& e = args[0];
    if (auto it = kEntities.find(e); it != kEntities.end()) return (this->*(it->second))(args);
    if (e == "#") return handler_.comment(args);
    if (e == "f") return handler_.face(args);
    if (e == "cone") return handler_.cone(args);
    if (e == "cyl") return handler_.cylinder(args);
    if (e == "sph") return handler_.sphere(args);
    if (e == "ring") return handler_.ring(args);
    SourceLoc here =
        files_.empty() ? SourceLoc{} : SourceLoc{files_.back()->name, files_.back()->lineNo};
    if (e == "ies") throw notSupportedYet(here, "MGF 'ies' entities (ies2rad luminaires)");
    if (unknown_++ == 0) warnings_.push_back(here.str() + ": Unknown entity: " + e);
}

void MgfReader::include(const MgfArgs& args) {
    if (args.size() < 2) mgfFail(MgfError::ArgCount);
    std::string path = args[1];
    // Relative names are relative to the including file's folder.
    if (path[0] != '/' && !files_.empty()) {
        const std::string& cur = files_.back()->name;
        size_t slash = cur.rfind('/');
        if (slash != std::string::npos) path = cur.substr(0, slash + 1) + path;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) mgfFail(MgfError::NoFile);
    std::ostringstream all;
    all << in.rdbuf();
    std::unique_ptr<File> file = makeFile(all.str(), path);
    files_.push_back(file.get());
    struct Pop {
        std::vector<File*>& files;
        ~Pop() { files.pop_back(); }
    } pop{files_};
    // The include's own transform; an array in it repeats the whole file.
    size_t depth = xf_.size();
    bool withXf = args.size() > 2;
    if (withXf) {
        MgfArgs xfArgs{"xf"};
        xfArgs.insert(xfArgs.end(), args.begin() + 2, args.end());
        handle(xfArgs);
    }
    do {
        runLines(*file);
        if (withXf) handle({"xf"});
    } while (withXf && xf_.size() > depth);
}

}  // namespace rp::gen
