// RADIANCE information headers: the "#?RADIANCE" text block that opens pictures,
// octrees, scene files and photon maps, ended by an empty line. Shared by every
// file format we read or write; getinfo prints them.
#pragma once

#include <istream>
#include <ostream>
#include <string>
#include <vector>

namespace rp {

constexpr const char* kHeaderMagic = "#?RADIANCE";

struct Header {
    std::vector<std::string> lines;  // lines between the magic line and the blank line

    // Value of the last "FORMAT=" line, or "" if none.
    std::string format() const;
    // Value of the last line starting with "NAME=" (e.g. "VERSION", "EXPOSURE").
    std::string value(const std::string& name) const;
};

// Reads a header from the stream's current position, leaving the stream just after the
// terminating empty line. Throws InputError naming `what` (usually the file name) if
// the magic line is missing or the stream ends before the empty line.
Header readHeader(std::istream& in, const std::string& what);

// Like readHeader but returns false (stream position unspecified) instead of throwing
// when the data does not start with the magic line. Used to detect file kinds.
bool tryReadHeader(std::istream& in, Header& out);

// Writes the magic line, each line, and the empty line.
void writeHeader(std::ostream& out, const Header& h);

// "CAPDATE= 2024:01:02 03:04:05\nGMT= ...\n": the current local time and GMT, as
// RADIANCE's fputnow writes them into the headers of pictures and matrices.
std::string captureTimeLines();

// "prog arg1 arg2 ..." as RADIANCE's printargs writes a command line (fputword): a word
// with white space goes in double quotes, or in single quotes when it holds a double
// quote (not first or last), and in double quotes when it holds a single one.
std::string commandLine(int argc, const char* const* argv);

}  // namespace rp
