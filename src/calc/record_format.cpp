// rcalc's record formats (see record_format.h), following RADIANCE rcalc.c field by
// field so that records match, and print, as they do there.
#include "calc/record_format.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>

#include "util/error.h"

namespace rp::calc {
namespace {

constexpr std::size_t kMaxRecord = 16384;  // RADIANCE INBSIZ: longest record
constexpr std::size_t kMaxWord = 127;      // RADIANCE RMAXWORD: longest field value

bool isNumberChar(int c) {
    return std::isdigit(c) || c == '-' || c == '.' || c == '+' || c == 'e' || c == 'E';
}

}  // namespace

std::string recordFormatText(const std::string& arg) {
    if (arg.find('$') != std::string::npos) return arg;
    std::ifstream in(arg, std::ios::binary);
    if (!in) throw InputError(arg + ": cannot open");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (text.empty()) throw InputError(arg + ": empty file");
    if (text.size() >= kMaxRecord - 3) throw InputError(arg + ": format too long");
    return text;
}

std::vector<FormatField> parseRecordFormat(std::string_view spec, bool ignoreEol) {
    std::vector<FormatField> fields;
    std::string_view src = spec;
    std::size_t p = 0;
    for (;;) {  // RADIANCE readfield
        FormatField f;
        bool typed = false;
        int width = 0;
        while (f.text.size() < kMaxRecord - 1 && p < src.size()) {
            ++width;
            const char c = src[p];
            if (!typed) {
                typed = true;
                if (c == '$') {
                    ++p;
                    ++width;
                    const char n = p < src.size() ? src[p] : '\0';
                    if (n == '{' || n == '(') {
                        f.type = n == '{' ? FormatField::Type::Number : FormatField::Type::String;
                        ++p;
                        continue;
                    }
                    if (n != '$') throw InputError("format error");
                    --width;
                }
                f.type = FormatField::Type::Literal;
                f.text += src[p++];
                continue;
            }
            if (f.type == FormatField::Type::Literal) {
                if (c == '$') {
                    --width;
                    break;
                }
                f.text += c;
                ++p;
                continue;
            }
            const char close = f.type == FormatField::Type::Number ? '}' : ')';
            if (c == close) {
                ++p;
                break;
            }
            if (!std::isspace(static_cast<unsigned char>(c))) f.text += c;
            ++p;
        }
        if (!typed) break;
        f.width = width;
        fields.push_back(std::move(f));
        // RADIANCE compat: a format that does not end in a newline gets one.
        if (!ignoreEol && p == src.size() && src[p - 1] != '\n') {
            src = "\n";
            p = 0;
        }
    }
    return fields;
}

int stringVarIndex(std::vector<StringVar>& vars, const std::string& name) {
    for (std::size_t i = 0; i < vars.size(); ++i)
        if (vars[i].name == name) return static_cast<int>(i);
    vars.push_back(StringVar{name, std::nullopt, std::nullopt});
    return static_cast<int>(vars.size()) - 1;
}

RecordReader::RecordReader(std::vector<FormatField> fields, bool blanksEqual, bool ignoreEol,
                           bool passive, std::vector<StringVar>& strings)
    : fields_(std::move(fields)),
      blanksEqual_(blanksEqual),
      ignoreEol_(ignoreEol),
      passive_(passive),
      strings_(strings) {
    for (FormatField& f : fields_) {
        if (f.type == FormatField::Type::String) {
            f.var = stringVarIndex(strings_, f.text);
        } else if (f.type == FormatField::Type::Number) {
            f.var = -1;
            for (std::size_t i = 0; i < numbers_.size(); ++i)
                if (numbers_[i] == f.text) f.var = static_cast<int>(i);
            if (f.var < 0) {
                numbers_.push_back(f.text);
                f.var = static_cast<int>(numbers_.size()) - 1;
            }
        }
    }
    values_.assign(numbers_.size(), std::nullopt);
    // RADIANCE nbsynch: with blanks equal, leading blanks of the format match nothing.
    if (blanksEqual_ && !fields_.empty() && fields_[0].type == FormatField::Type::Literal) {
        std::string& t = fields_[0].text;
        std::size_t k = 0;
        while (k < t.size() && blank(static_cast<unsigned char>(t[k]))) ++k;
        t.erase(0, k);
        if (t.empty()) fields_.erase(fields_.begin());
    }
}

void RecordReader::begin(std::istream& in, std::ostream& passiveOut) {
    in_ = &in;
    out_ = &passiveOut;
    buf_.clear();
    beg_ = 0;
    pos_ = static_cast<std::size_t>(-1);  // before the beginning
    chr_ = 0;
    scan();
}

void RecordReader::scan() {
    if (chr_ == EOF) return;
    ++pos_;
    if (pos_ == buf_.size()) {
        chr_ = in_->rdbuf()->sbumpc();
        if (chr_ != EOF) buf_ += static_cast<char>(chr_);
    } else {
        chr_ = static_cast<unsigned char>(buf_[pos_]);
    }
}

void RecordReader::home() {
    beg_ = pos_;
    if (beg_ > 65536) {  // drop what no reset can return to
        buf_.erase(0, beg_);
        pos_ -= beg_;
        beg_ = 0;
    }
}

void RecordReader::reset() {
    pos_ = beg_;
    chr_ = static_cast<unsigned char>(buf_[pos_]);
    if (passive_) out_->put(static_cast<char>(chr_));  // transmit the unmatched character
    ++beg_;
    scan();
}

void RecordReader::clearRecord() {
    for (auto& v : values_) v.reset();
    for (StringVar& s : strings_) s.value = s.preset;
}

bool RecordReader::next() {
    while (chr_ != EOF) {
        if (blanksEqual_) {
            while (blank(chr_)) reset();
            if (chr_ == EOF) return false;
        }
        const bool eatLine = !ignoreEol_ && chr_ != '\n';
        clearRecord();
        std::size_t k = 0;
        while (k < fields_.size() && field(k)) ++k;
        if (k == fields_.size()) {
            home();
            return true;
        }
        reset();  // a false start
        if (eatLine) {
            while (chr_ != '\n') {
                if (chr_ == EOF) return false;
                reset();
            }
            reset();
        }
    }
    return false;
}

bool RecordReader::field(std::size_t k) {
    const FormatField& f = fields_[k];
    if (f.type == FormatField::Type::Literal) {
        const std::string& s = f.text;
        std::size_t c = 0;
        do {
            const int want = c < s.size() ? static_cast<unsigned char>(s[c]) : 0;
            if (blanksEqual_ && blank(want)) {
                if (!blank(chr_)) return false;
                do ++c;
                while (c < s.size() && blank(static_cast<unsigned char>(s[c])));
                do scan();
                while (blank(chr_));
            } else if (want == chr_) {
                ++c;
                scan();
            } else {
                return false;
            }
        } while (c < s.size());
        return true;
    }
    const bool nextLiteral =
        k + 1 < fields_.size() && fields_[k + 1].type == FormatField::Type::Literal;
    const int delim = nextLiteral && !fields_[k + 1].text.empty()
                          ? static_cast<unsigned char>(fields_[k + 1].text[0])
                      : nextLiteral ? 0
                                    : EOF;
    std::string word;
    bool inword;
    if (f.type == FormatField::Type::String) {
        do {
            if (chr_ == EOF || chr_ == '\n')
                inword = false;
            else if (blanksEqual_ && delim != EOF)
                inword = blank(delim) ? !blank(chr_) : chr_ != delim;
            else
                inword = static_cast<int>(word.size()) < f.width;
            if (inword) {
                word += static_cast<char>(chr_);
                scan();
            }
        } while (inword && word.size() < kMaxWord);
        StringVar& v = strings_[f.var];
        if (!v.value)
            v.value = word;  // first setting
        else if (*v.value != word)
            return false;  // does not match
        return true;
    }
    std::size_t start = std::string::npos;  // first non-blank
    do {
        if (!((start == std::string::npos && blank(chr_)) || isNumberChar(chr_)))
            inword = false;
        else if (blanksEqual_ && delim != EOF)
            inword = blank(delim) ? !blank(chr_) : chr_ != delim;
        else
            inword = static_cast<int>(word.size()) < f.width;
        if (inword) {
            if (start == std::string::npos && !blank(chr_)) start = word.size();
            word += static_cast<char>(chr_);
            scan();
        }
    } while (inword && word.size() < kMaxWord);
    double d = start == std::string::npos ? 0.0 : std::atof(word.c_str() + start);
    std::optional<double>& v = values_[f.var];
    if (!v) {
        v = d;  // first setting
    } else {
        // RADIANCE compat: a repeated numeric field matches within 0.1 %.
        d = (*v - d) / (d == 0. ? 1. : d);
        if (d > .001 || d < -.001) return false;
    }
    return true;
}

void writeRecord(const std::vector<FormatField>& fields, const std::vector<StringVar>& strings,
                 bool blanksEqual, OutputValues& values, std::string& out) {
    bool adLast = false;
    char buf[512];
    for (std::size_t k = 0; k < fields.size(); ++k) {
        const FormatField& f = fields[k];
        const bool adNext = blanksEqual && k + 1 < fields.size() &&
                            !(fields[k + 1].type == FormatField::Type::Literal &&
                              !fields[k + 1].text.empty() && fields[k + 1].text[0] == ' ');
        switch (f.type) {
            case FormatField::Type::Literal:
                out += f.text;
                adLast = f.width > 0 && static_cast<std::size_t>(f.width) <= f.text.size() &&
                         f.text[f.width - 1] != ' ';
                break;
            case FormatField::Type::String: {
                const StringVar& v = strings[f.var];
                if (!v.value) throw InputError(v.name + ": undefined string");
                int n = f.width - static_cast<int>(v.value->size());
                if (adLast) out += *v.value;
                if (!(adLast && adNext))
                    while (n-- > 0) out += ' ';
                if (!adLast) out += *v.value;
                adLast = true;
                break;
            }
            case FormatField::Type::Number: {
                const int n = f.width;
                const double dv = values.value(static_cast<int>(k));
                const double av = std::fabs(dv);
                std::string typ = n <= 9 ? "g" : "." + std::to_string(n - 5) + "e";
                if (av < 2147483648.0) {
                    const long iv = static_cast<long>(av + .5);
                    if (iv && std::fabs(av - static_cast<double>(iv)) <= av * 1e-14) typ = ".0f";
                }
                std::string fmt;
                if (adLast && adNext)
                    fmt = "%" + typ;
                else if (adLast)
                    fmt = "%-" + std::to_string(n) + typ;
                else
                    fmt = "%" + std::to_string(n) + typ;
                const int len = std::snprintf(buf, sizeof buf, fmt.c_str(), dv);
                if (len >= static_cast<int>(sizeof buf)) {
                    std::string big(static_cast<std::size_t>(len) + 1, '\0');
                    std::snprintf(big.data(), big.size(), fmt.c_str(), dv);
                    big.resize(static_cast<std::size_t>(len));
                    out += big;
                } else if (len > 0) {
                    out.append(buf, static_cast<std::size_t>(len));
                }
                adLast = true;
                break;
            }
        }
    }
}

}  // namespace rp::calc
