// Where matrix tools read from, and how they walk what they read. An input spec is a
// file name, "-" (standard input) or "!command" (the command's standard output, read
// through a pipe), as in RADIANCE's rmx_load and cm_load; it is read whole into memory,
// since every tool here needs all of it. DataReader then walks the bytes: RADIANCE's
// information header (getheader), the resolution string of pictures, ASCII numbers and
// binary values, naming the input and line (or record) in every error.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace rp::matrix {

// "<stdin>": RADIANCE's stdin_name, how messages name standard input.
constexpr const char* kStdinName = "<stdin>";

struct InputData {
    std::string name;   // the spec as given ("<stdin>" for "-" or empty)
    std::string bytes;  // everything the source held
};

// Reads the whole input. Throws InputError "name: cannot open file (...)", "cannot run
// command" or "command failed (exit status N)".
InputData readInput(const std::string& spec);

class DataReader {
public:
    explicit DataReader(const InputData& in) : in_(in) {}

    // RADIANCE compat (header.c getheader): the lines up to the first empty one, whatever
    // they hold (no "#?" line is required); each line keeps its '\n'. False when the data
    // does not start with a printable character or ends before the empty line.
    bool readHeader(std::vector<std::string>& lines);
    // A picture resolution string ("-Y 3 +X 5" or another orientation), as fscnresolu:
    // `scanLength` pixels per scanline, `scanCount` scanlines. False when there is none.
    bool readResolution(int& scanLength, int& scanCount);

    // The next white-space separated number (fscanf "%lf"). False at the end of the data;
    // throws InputError "name:line: bad number 'word'" for a word that is not one.
    bool nextDouble(double& v);
    // The same as a float (fscanf "%f").
    bool nextFloat(float& v);
    // True when only white space is left.
    bool atEndIgnoringSpace() const;

    // Copies `n` bytes; false (nothing consumed) when fewer are left.
    bool readBytes(void* dst, size_t n);
    size_t remaining() const { return in_.bytes.size() - pos_; }
    size_t position() const { return pos_; }
    void seek(size_t pos) { pos_ = pos; }
    const char* cursor() const { return in_.bytes.data() + pos_; }
    const std::string& name() const { return in_.name; }
    // The 1-based line the reader is at, for messages about text data.
    int line() const { return lineAt(pos_); }
    // The line of the last number read (where data that ends too soon ended).
    int lastNumberLine() const { return lineAt(lastWord_); }
    int lineAt(size_t pos) const;

private:
    bool skipSpaceToWord(size_t& start, size_t& end);
    template <class T>
    bool nextNumber(T& v, T (*convert)(const char*, char**));
    const InputData& in_;
    size_t pos_ = 0;
    size_t lastWord_ = 0;
};

// Refuses a size from a header that the data left cannot possibly hold, before anything
// of that size is allocated: more than 2048 values a byte (RADIANCE's run-length pictures
// compress no further), or 2^31 values. Data merely short are left to the readers, whose
// messages say where they end. InputError naming the input.
void checkDeclaredSize(const DataReader& r, int64_t rows, int64_t cols, int64_t comps);

// Reverses the byte order of `count` values of `size` bytes each (4 or 8).
void swapBytes(void* data, size_t size, size_t count);

}  // namespace rp::matrix
