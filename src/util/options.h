// The one option mechanism of every tool: a table of option descriptors (which words an
// option matches, how its values are read and checked, its -defaults text) drives
// parsing, error messages, -defaults and -version. RADIANCE's conventions live here:
// boolean suffixes (check_bool), k/m/g counts (parseMultiplier), @file/$EVAR expansion
// (expandarg, util/command_args.h). What each option means lives with its tool.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "util/bool_option.h"
#include "util/color.h"

namespace rp {

// What a value should have been, for "bad value" messages that name it.
enum class ValueKind { kWord, kReal, kInteger, kCount };

// The texts of the errors a table reports. Tools keep the wording they have always had,
// so each table may replace these; the defaults are rtrace's.
struct OptionMessages {
    std::function<std::string(const std::string& opt)> missing = [](const std::string& opt) {
        return "missing value for option '" + opt + "'";
    };
    std::function<std::string(const std::string& opt, const std::string& value, ValueKind)> bad =
        [](const std::string& opt, const std::string& value, ValueKind) {
            return "bad value '" + value + "' for option '" + opt + "'";
        };
    // A value out of range: `what` says the rule ("must be >= 0").
    std::function<std::string(const std::string& opt, const std::string& what)> range =
        [](const std::string& opt, const std::string& what) {
            return "option '" + opt + "': " + what;
        };
    std::function<std::string(const std::string& opt)> unknown = [](const std::string& opt) {
        return "unknown option '" + opt + "'";
    };
};

// "500k" -> 500000, "1m" -> 1e6, "2.5M" -> 2500000, "1g" -> 1e9 (RADIANCE
// parseMultiplier); nullopt for anything else or a value that is not a positive count.
std::optional<uint64_t> parseCount(const std::string& s);
// A whole word as an integer (no trailing characters, no overflow of long).
std::optional<long> parseInteger(const std::string& s);
// A whole word as a finite real.
std::optional<double> parseReal(const std::string& s);

// Reads the values that follow one option word; every error goes through the table's
// messages and is an InputError (util/error.h) without a location.
class OptionReader {
public:
    OptionReader(const std::vector<std::string>& args, size_t at, const OptionMessages& m)
        : args_(args), messages_(m), opt_(args[at]), at_(at + 1) {}

    const std::string& option() const { return opt_; }
    const std::vector<std::string>& args() const { return args_; }
    void skipTo(size_t next) { at_ = next; }  // for handlers that read args() themselves
    bool hasNext() const { return at_ < args_.size(); }
    const std::string& word();
    double real();
    // An integer in [lo, hi]; outside it is a bad value (the reader's range, not a rule).
    long integer(long lo = -2147483647L, long hi = 2147483647L);
    uint64_t count();  // k/m/g suffixes
    Color color();     // three reals
    // True if the next word exists and is an integer (RADIANCE isint), without reading it.
    bool nextIsInteger() const;
    [[noreturn]] void bad(const std::string& value, ValueKind kind) const;
    // Throws the table's range message for this option unless `ok`.
    void require(bool ok, const std::string& what) const;
    size_t next() const { return at_; }  // the index after the values read

private:
    const std::vector<std::string>& args_;
    const OptionMessages& messages_;
    std::string opt_;
    size_t at_;
};

// One option: its name (for -defaults order and for finding it), which words it takes,
// how it reads them, and its -defaults text (empty function: no line).
struct OptionSpec {
    std::string name;
    std::function<bool(const std::string& word)> matches;
    std::function<void(OptionReader&)> read;
    std::function<std::string()> defaults;
    const OptionMessages* messages = nullptr;  // null: the table's
};

// Matching rules, as RADIANCE's tools compare words: exactly, or as a prefix (the rest of
// the word is the option's own business: "-ovw", "-bv+") up to a length.
std::function<bool(const std::string&)> exactly(std::string name);
std::function<bool(const std::string&)> prefix(std::string name, size_t maxLength = SIZE_MAX);

// A RADIANCE boolean: "-bv" toggles, "-bv+", "-bvy", "-bv1" set, "-bv-", "-bvn", "-bv0"
// clear (boolSuffix). maxLength limits the words it claims (rtrace's -i: 3); SIZE_MAX
// claims every word that starts with the name, and rejects a bad suffix as unknown.
OptionSpec flagOption(const std::string& name, bool& value, size_t maxLength = SIZE_MAX);

// A value of the field's type: word, real, integer (int range), count (k/m/g) or colour
// (three reals), accepted only when `ok` (if given) holds, else the range message `what`.
OptionSpec valueOption(const std::string& name, std::string& v);
OptionSpec valueOption(const std::string& name, double& v, std::function<bool(double)> ok = {},
                       std::string what = {});
OptionSpec valueOption(const std::string& name, int& v, std::function<bool(long)> ok = {},
                       std::string what = {});
OptionSpec countOption(const std::string& name, uint64_t& v);
OptionSpec valueOption(const std::string& name, Color& v);
// Anything else: the handler reads what it needs through the reader.
OptionSpec customOption(const std::string& name, std::function<void(OptionReader&)> read);
OptionSpec customOption(std::function<bool(const std::string&)> matches, const std::string& name,
                        std::function<void(OptionReader&)> read);

// printf into a string, for -defaults lines in RADIANCE's formats.
std::string formatLine(const char* fmt, ...) __attribute__((format(printf, 1, 2)));

// Why parsing stopped.
enum class OptionStop { kEnd, kVersion, kDefaults };
struct OptionParse {
    size_t next = 0;  // the first word that is not an option (or the -version word)
    OptionStop stop = OptionStop::kEnd;
};

class OptionTable {
public:
    OptionMessages messages;
    bool expandArgs = false;      // @file and $EVAR at option positions (rtrace, rpict, ...)
    bool helpIsDefaults = false;  // -help prints the defaults too (RADIANCE's renderers)
    bool defaultsStops = true;    // -defaults stops parsing (else it is an unknown option)
    bool plusWords = false;       // "+x" words are options too (gensky +s, pvalue +d, ...)
    bool unknownEnds = false;     // an unknown option ends the options (xform: the transform)

    // Adds `spec` after the others (earlier ones are tried first); when its name is taken
    // the earlier option stays, so a tool adds its own options before shared ones.
    void add(OptionSpec spec, std::function<std::string()> defaults = {});
    // Replaces the -defaults text of option `name` (which must exist).
    void setDefaults(const std::string& name, std::function<std::string()> defaults);
    // The options whose -defaults text is listed, in this order (default: table order).
    void setDefaultsOrder(std::vector<std::string> names) { defaultsOrder_ = std::move(names); }

    const OptionSpec* find(const std::string& word) const;
    // Parses options from args[first]: stops at the first word that is not an option
    // (shorter than 2 or not starting with '-', or '+' with plusWords), at -version and at
    // -defaults (and -help if helpIsDefaults), which may stand at any option position. Throws
    // InputError with the table's messages.
    OptionParse parse(std::vector<std::string>& args, size_t first) const;
    std::string formatDefaults() const;
    // For tools whose options follow positional arguments (the generators): parses from
    // args[first] to the end, where a word that is not an option (or -version, which
    // the tool's main has answered) is the table's unknown option.
    void parseAll(std::vector<std::string>& args, size_t first) const;

private:
    std::vector<OptionSpec> specs_;
    std::vector<std::string> defaultsOrder_;
};

}  // namespace rp
