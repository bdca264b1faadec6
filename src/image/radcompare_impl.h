// Internals of radcompare shared by radcompare.cpp (headers, pictures, binary and
// float data, the driver) and radcompare_text.cpp (text and ASCII data word by word).
// Not for use outside them.
#pragma once

#include <cctype>
#include <cstdio>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "image/picture.h"
#include "image/radcompare.h"
#include "image/rgbe.h"

namespace rp::radcompare_detail {

enum class DataKind {
    kUnknown,
    kText,
    kAscii,
    kRgbe,
    kXyze,
    kDepth,
    kNormal,
    kFloat,
    kDouble,
    kRbfMesh,
    kOctree,
    kTmesh,
    kId8,
    kId16,
    kId24,
    kBinary
};

inline const char* kindName(DataKind k) {
    static const char* names[] = {"Unrecognized",
                                  "TEXT_generic",
                                  "ascii",
                                  kRgbeFormat,
                                  kXyzeFormat,
                                  "16-bit_encoded_depth",
                                  "32-bit_encoded_normal",
                                  "float",
                                  "double",
                                  "BSDF_RBFmesh",
                                  "Radiance_octree",
                                  "Radiance_tmesh",
                                  "8-bit_indexed_name",
                                  "16-bit_indexed_name",
                                  "24-bit_indexed_name",
                                  "BINARY_unknown"};
    return names[static_cast<int>(k)];
}

inline DataKind kindOfFormat(const std::string& f) {
    for (int i = 1; i <= static_cast<int>(DataKind::kBinary); ++i)
        if (f == kindName(static_cast<DataKind>(i))) return static_cast<DataKind>(i);
    return DataKind::kUnknown;
}

inline bool isSpace(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }
inline bool isDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// One input: its bytes, where the data start, its header settings and line count.
struct Input {
    std::string name;
    const std::string* bytes = nullptr;
    size_t dataStart = 0;
    bool hasHeader = false;
    std::vector<std::pair<std::string, std::string>> settings;  // in first-set order
    int lines = 0;  // header lines read, the magic and empty lines included
    bool swapped = false;
    DataKind kind = DataKind::kUnknown;

    std::string* find(const std::string& key) {
        for (auto& [k, v] : settings)
            if (k == key) return &v;
        return nullptr;
    }
};

inline std::string formatted(const char* fmt, double a) {
    char buf[64];
    std::snprintf(buf, sizeof buf, fmt, a);
    return buf;
}

class Comparer {
public:
    Comparer(const RadcompareOptions& o, std::ostream& out, std::string program)
        : opt_(o), out_(out), prog_(std::move(program)) {}

    int run(Input& a, Input& b);

private:
    bool reports() const { return opt_.report != CompareReport::kQuiet; }
    bool warns() const { return opt_.report >= CompareReport::kWarnings; }
    bool verbose() const { return opt_.report == CompareReport::kVerbose; }

    void identify(Input& in);
    void setVariable(Input& in, const std::string& line);
    bool headersMatch(Input& a, Input& b);
    bool realCheck(double r1, double r2);
    bool goodRms(const Input& a, const Input& b);
    bool equivalent(const char* s1, const char* s2);
    bool compareBinary(const Input& a, const Input& b);
    bool compareText(Input& a, Input& b);
    bool comparePictures(const Input& a, const Input& b);
    template <class T>
    bool compareReals(const Input& a, const Input& b, const char* what);

    const RadcompareOptions& opt_;
    std::ostream& out_;
    std::string prog_;
    double diff2Sum_ = 0;
    long nSum_ = 0;
};

}  // namespace rp::radcompare_detail
