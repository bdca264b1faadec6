// rcalc's record formats (rcalc(1), "-i format", "-o format"): literal text with numeric
// fields ${name} (${expr} on output) and string fields $(name), "$$" for a dollar sign.
// This file parses a specification into fields, matches input records against one
// through a lookahead buffer (RADIANCE's getrec/getfield, passive mode included) and
// writes output records (putrec). The record loop and the .cal side are in rcalc.h.
#pragma once

#include <istream>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace rp::calc {

struct FormatField {
    enum class Type { Literal, String, Number };
    Type type = Type::Literal;
    int width = 0;     // characters the field occupies in the specification ("${x}" is 4)
    std::string text;  // literal text, variable name, or output expression (blanks removed)
    int var = -1;      // String/Number: index of the variable (RecordFormat::strings/numbers)
};

// A string variable $(name): its value in the current record, and its -s preset.
struct StringVar {
    std::string name;
    std::optional<std::string> value;
    std::optional<std::string> preset;
};

// The text of a -i/-o argument: the argument itself when it holds a '$', else the
// contents of the file it names. InputError: "name: cannot open", "name: empty file".
std::string recordFormatText(const std::string& arg);

// Parses `spec` into fields. `ignoreEol` (-l) keeps a specification that does not end in
// a newline as it is; otherwise a newline is appended. InputError on "$" followed by
// anything but '{', '(' or '$' ("format error").
std::vector<FormatField> parseRecordFormat(std::string_view spec, bool ignoreEol);

// Matching input records against a format (RADIANCE rcalc.c getrec and getfield).
class RecordReader {
public:
    // `fields` from parseRecordFormat; string variables are looked up and added in
    // `strings` and numeric ones in `numbers` (their names) by index.
    RecordReader(std::vector<FormatField> fields, bool blanksEqual, bool ignoreEol, bool passive,
                 std::vector<StringVar>& strings);

    const std::vector<std::string>& numberNames() const { return numbers_; }
    // Starts reading `in`; characters that match nothing go to `passiveOut` in passive mode.
    void begin(std::istream& in, std::ostream& passiveOut);
    // Reads the next matching record; false at end of input. Numeric fields' values are
    // then in numberValue().
    bool next();
    double numberValue(int i) const { return *values_[i]; }

private:
    bool blank(int c) const { return ignoreEol_ ? std::isspace(c) != 0 : c == ' ' || c == '\t'; }
    void scan();   // scaninp
    void home();   // advinp
    void reset();  // resetinp
    bool field(std::size_t k);
    void clearRecord();

    std::vector<FormatField> fields_;
    bool blanksEqual_, ignoreEol_, passive_;
    std::vector<StringVar>& strings_;
    std::vector<std::string> numbers_;
    std::vector<std::optional<double>> values_;
    std::istream* in_ = nullptr;
    std::ostream* out_ = nullptr;
    std::string buf_;  // characters read and not yet passed: buf_[beg_ .. end)
    std::size_t beg_ = 0, pos_ = 0;
    int chr_ = 0;  // character at pos_, or EOF
};

// Where output fields get their numbers: the expression of field `expr` evaluated.
class OutputValues {
public:
    virtual ~OutputValues() = default;
    virtual double value(int field) = 0;
};

// Writes one output record for `fields` (RADIANCE putrec): numbers fill their field's
// width ("%g", or "%.Ne" for wide fields, integers as "%.0f"), string variables padded.
// InputError "name: undefined string" for a string variable without a value.
void writeRecord(const std::vector<FormatField>& fields, const std::vector<StringVar>& strings,
                 bool blanksEqual, OutputValues& values, std::string& out);

// The index of string variable `name` in `vars`, added if new.
int stringVarIndex(std::vector<StringVar>& vars, const std::string& name);

}  // namespace rp::calc
