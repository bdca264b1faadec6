// Reading RADIANCE's portable binary values (common/portio.c) from bytes in memory:
// big-endian integers of 1 to 8 bytes, sign-extended from their first byte; reals as a
// 4-byte mantissa and a 1-byte exponent; NUL-terminated strings. Every read checks the
// bytes left, so a truncated file is an InputError naming the file, never a crash.
// Shared by the binary object records, the mesh reader and the octree reader.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "util/error.h"
#include "util/portable_io.h"

namespace rp {

class PortableReader {
public:
    // `kind` names what is read in messages ("mesh file", "octree").
    PortableReader(std::string_view bytes, size_t& pos, const std::string& what, const char* kind)
        : in_(bytes), pos_(pos), what_(what), kind_(kind) {}

    [[noreturn]] void fail(const std::string& why) const {
        throw InputError(SourceLoc{what_, 0}, "damaged " + std::string(kind_) + " (" + why + ")");
    }
    [[noreturn]] void truncated(const char* where) const {
        throw InputError(SourceLoc{what_, 0}, "truncated " + std::string(kind_) + " (ends inside " +
                                                  describe(where) + ")");
    }

    // What the values being read belong to ("patch 3", "object 12 'chair'"), named in
    // messages as "<where> of <context>"; null for nothing. Set once per record rather
    // than built for each value, so that reading allocates nothing.
    void setContext(const std::string* context) { context_ = context; }
    std::string describe(const char* where) const {
        return context_ ? std::string(where) + " of " + *context_ : std::string(where);
    }

    size_t left() const { return in_.size() - pos_; }
    size_t pos() const { return pos_; }

    // A `size`-byte integer, sign-extended as RADIANCE's getint() does.
    int64_t integer(int size, const char* where) {
        if (left() < static_cast<size_t>(size)) truncated(where);
        int64_t v = portable::getInt(here(), size);
        pos_ += size;
        return v;
    }
    // The same 4 bytes as an unsigned value (mesh vertex coordinates).
    uint32_t u32(const char* where) { return static_cast<uint32_t>(integer(4, where)); }
    int byte(const char* where) { return static_cast<int>(integer(1, where) & 0xff); }

    // portio.c's float (util/portable_io.h getFlt).
    double real(const char* where) {
        if (left() < size_t(portable::kPortableFloatSize)) truncated(where);
        double v = portable::getFlt(here());
        pos_ += portable::kPortableFloatSize;
        return v;
    }

    std::string str(const char* where) {
        size_t end = in_.find('\0', pos_);
        if (end == std::string_view::npos) truncated(where);
        std::string s(in_.substr(pos_, end - pos_));
        pos_ = end + 1;
        return s;
    }

    // A count read as `size` bytes, each counted element needing at least `minBytes`:
    // negative counts and counts the remaining bytes cannot hold are damage.
    size_t count(int size, size_t minBytes, const char* where) {
        int64_t n = integer(size, where);
        if (n < 0 || static_cast<uint64_t>(n) * minBytes > left())
            fail("impossible " + describe(where) + " " + std::to_string(n));
        return static_cast<size_t>(n);
    }

private:
    const unsigned char* here() const {
        return reinterpret_cast<const unsigned char*>(in_.data()) + pos_;
    }
    std::string_view in_;
    size_t& pos_;
    const std::string& what_;
    const char* kind_;
    const std::string* context_ = nullptr;
};

// The tree that precedes the objects of an octree and the patches of a mesh
// (readoct.c/readmesh.c skiptree): pre-order nodes, a byte each, empty (0), full (1,
// followed by an object set: a count, then that many `objsize`-byte references) or
// a tree (2, followed by its 8 children). Skips it while checking its structure:
// node kinds, set sizes (at most RADIANCE's MAXSET) and that every reference lies in
// [0, maxRef). Uses a stack of bounded depth rather than recursion.
void skipRadianceTree(PortableReader& r, int objsize, int64_t maxRef);

// The cube of an octree or mesh: origin x, y, z and side as four decimal strings (as
// oconv and obj2mesh print them). Returns the strings as stored; `origin` and `size`
// get their values. A string that is not a number is damage.
std::array<std::string, 4> readRadianceCube(PortableReader& r, std::array<double, 3>& origin,
                                            double& size);

}  // namespace rp
