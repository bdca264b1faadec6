// getinfo: header printing, dimensions, header stripping and appending (see getinfo.h).
// Output formats match RADIANCE's getinfo.c byte for byte.
#include "image/getinfo.h"

#include <fstream>
#include <istream>
#include <ostream>

#include "util/error.h"
#include "util/header.h"

namespace rp {

namespace {

constexpr const char* kStdinName = "standard input";

void copyRest(std::istream& in, std::ostream& out) {
    char buf[8192];
    while (in.read(buf, sizeof buf) || in.gcount() > 0) out.write(buf, in.gcount());
}

// RADIANCE compat: getdim() in getinfo.c. After the header a picture has its resolution
// line, an octree a 2-byte magic number starting with byte 1 and then its bounding cube
// as four NUL-terminated strings (xmin ymin zmin size).
std::string dimensions(std::istream& in) {
    int c = in.get();
    std::string s;
    if (c == '+' || c == '-') {
        do s.push_back(static_cast<char>(c));
        while ((c = in.get()) != EOF && c != '\n' && s.size() < 256);
    } else if (c == 1) {
        in.get();
        int nul = 0;
        while ((c = in.get()) != EOF && s.size() < 256) {
            if (c == 0) {
                if (++nul >= 4) break;
                s.push_back(' ');
            } else {
                s.push_back(static_cast<char>(c));
            }
        }
    } else {
        s = "unknown file type";
    }
    return s + "\n";
}

// Our oconv's scene file (scene/scene_file.h kSceneFileFormat; image/ does not depend on
// scene/) holds records only: its cube comes from GetinfoOptions::sceneCube.
constexpr const char* kSceneFileFormat = "radphoton_scene";

// The dimensions line of a file whose header has been read (and its name for errors);
// false after an error line.
bool dimensionsOf(const GetinfoOptions& opt, const Header& h, const std::string& name,
                  bool fromStdin, std::istream& in, std::string& line, std::ostream& err) {
    if (h.format() != kSceneFileFormat) {
        line = dimensions(in);
        return true;
    }
    if (!opt.sceneCube || fromStdin) {
        err << "getinfo: " << name << ": a radphoton scene file has no bounding cube"
            << (fromStdin ? " (give the file's name)" : "") << "\n";
        return false;
    }
    try {
        line = opt.sceneCube(name) + "\n";
        return true;
    } catch (const InputError& e) {
        err << "getinfo: " << e.what() << "\n";
        return false;
    }
}

void printTabbedHeader(std::ostream& out, const std::string& name, const Header& h) {
    out << name << ":\n\t" << kHeaderMagic << '\n';
    for (const auto& l : h.lines) out << '\t' << l << '\n';
    out << "\t\n";
}

}  // namespace

GetinfoOptions parseGetinfoArgs(int argc, const char* const* argv) {
    GetinfoOptions opt;
    int i = 1;
    bool dim = false;
    if (i < argc && (argv[i][0] == '-' || argv[i][0] == '+') && argv[i][1] == 'd' &&
        argv[i][2] == '\0') {
        dim = true;
        opt.mode =
            argv[i][0] == '-' ? GetinfoOptions::Mode::kDimensions : GetinfoOptions::Mode::kBoth;
        ++i;
    }
    if (i < argc && std::string(argv[i]) == "-a") {
        if (dim) throw InputError("-a cannot be combined with -d");
        opt.mode = GetinfoOptions::Mode::kAppend;
        for (++i; i < argc; ++i) opt.addLines.push_back(argv[i]);
        return opt;
    }
    if (i == argc - 1 && std::string(argv[i]) == "-") {
        // RADIANCE compat: -d also skips the resolution line; +d keeps it.
        opt.skipResolution = opt.mode == GetinfoOptions::Mode::kDimensions;
        opt.mode = GetinfoOptions::Mode::kStrip;
        return opt;
    }
    for (; i < argc; ++i) {
        std::string a = argv[i];
        if (a.size() > 1 && a[0] == '-' && (a == "-c" || a == "-a" || a == "-d" || a == "+d"))
            throw InputError("option " + a +
                             " not supported here (usage: getinfo [-d|+d] "
                             "[file ..] | getinfo [-d] - | getinfo -a line ..)");
        opt.files.push_back(a);
    }
    return opt;
}

int runGetinfo(const GetinfoOptions& opt, std::istream& in, std::ostream& out, std::ostream& err) {
    using Mode = GetinfoOptions::Mode;
    Header h;
    if (opt.mode == Mode::kStrip || opt.mode == Mode::kAppend) {
        if (!tryReadHeader(in, h)) {
            err << "getinfo: " << kStdinName << ": not a RADIANCE file\n";
            return 1;
        }
        if (opt.mode == Mode::kAppend) {
            // RADIANCE compat: checkheader() drops FORMAT= lines and getinfo -a writes the
            // last one's value after the added lines.
            const std::string fmt = h.format();
            std::erase_if(h.lines, [](const std::string& l) { return l.rfind("FORMAT=", 0) == 0; });
            for (const auto& l : opt.addLines) {
                if (l.empty()) continue;
                h.lines.push_back(l.back() == '\n' ? l.substr(0, l.size() - 1) : l);
            }
            if (!fmt.empty()) h.lines.push_back("FORMAT=" + fmt);
            writeHeader(out, h);
        } else if (opt.skipResolution) {
            std::string line;
            std::getline(in, line);
            if (line.empty() || (line[0] != '+' && line[0] != '-')) {
                err << "getinfo: " << kStdinName << ": no resolution string\n";
                return 1;
            }
        }
        copyRest(in, out);
        return 0;
    }

    if (opt.files.empty()) {
        if (!tryReadHeader(in, h)) {
            err << "getinfo: " << kStdinName << ": not a RADIANCE file\n";
            return 1;
        }
        // RADIANCE compat: from standard input the header is printed untabbed, then an
        // empty line.
        if (opt.mode != Mode::kDimensions) writeHeader(out, h);
        if (opt.mode == Mode::kHeader) return 0;
        std::string line;
        if (!dimensionsOf(opt, h, kStdinName, true, in, line, err)) return 1;
        out << line;
        return 0;
    }

    int status = 0;
    for (const auto& name : opt.files) {
        std::ifstream f(name, std::ios::binary);
        if (!f) {
            err << "getinfo: cannot open " << name << '\n';
            status = 1;
            continue;
        }
        if (!tryReadHeader(f, h)) {
            err << "getinfo: " << name << ": not a RADIANCE file\n";
            status = 1;
            continue;
        }
        if (opt.mode != Mode::kDimensions) printTabbedHeader(out, name, h);
        if (opt.mode == Mode::kHeader) continue;
        out.flush();
        std::string line;
        if (!dimensionsOf(opt, h, name, false, f, line, err)) {
            status = 1;
            continue;
        }
        out << (opt.mode == Mode::kDimensions ? name + ": " : std::string("\t")) << line;
    }
    out.flush();
    return status;
}

}  // namespace rp
