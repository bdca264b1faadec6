// rcalc's record loop (see rcalc.h), RADIANCE rcalc.c's execute, getinputrec, chanvalue,
// l_in, chanset and bchanset.
#include "calc/rcalc.h"

#include <cctype>
#include <cstdlib>
#include <cstring>
#include <optional>

#include "util/error.h"

namespace rp::calc {
namespace {

constexpr std::size_t kMaxRecord = 16384;  // RADIANCE INBSIZ: fgets buffer of a record

void swapBytes(char* p, std::size_t size, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i, p += size)
        for (std::size_t a = 0, b = size - 1; a < b; ++a, --b) std::swap(p[a], p[b]);
}

}  // namespace

class Rcalc::Impl final : public ChannelSource, public OutputValues {
public:
    Impl(const RcalcOptions& o, const std::vector<std::string>& searchPath) : o_(o) {
        Builder b(searchPath);
        b.enableChannels();
        b.loadString("PI : 3.14159265358979323846;", "rcalc");
        for (const auto& [isFile, text] : o_.sources) {
            if (isFile)
                b.loadFile(text);
            else
                b.loadString(text);
        }
        for (const std::string& p : o_.presets) {  // RADIANCE svpreset: no '=', no preset
            const auto eq = p.find('=');
            if (eq == std::string::npos) continue;
            StringVar& v = strings_[stringVarIndex(strings_, p.substr(0, eq))];
            v.preset = v.value = p.substr(eq + 1);
        }
        if (o_.hasInputFormat) {
            reader_.emplace(parseRecordFormat(o_.inputFormat, o_.inputFormatIgnoreEol),
                            o_.blanksEqual, o_.ignoreEol, o_.passive, strings_);
            for (const std::string& n : reader_->numberNames()) b.addExternal(n);
        }
        if (o_.hasOutputFormat) {
            outFields_ = parseRecordFormat(o_.outputFormat, o_.outputFormatIgnoreEol);
            for (FormatField& f : outFields_) {
                if (f.type == FormatField::Type::String)
                    f.var = stringVarIndex(strings_, f.text);
                else if (f.type == FormatField::Type::Number)
                    f.var = b.addExpression(f.text, SourceLoc{"output format", 0});
            }
        }
        b.addExternal("recno");
        b.addExternal("outno");
        prog_ = b.build();
        ev_.emplace(prog_);
        ev_->setChannels(this);
        cond_ = prog_->variable("cond");
        recno_ = prog_->variable("recno");
        outno_ = prog_->variable("outno");
        if (reader_)
            for (const std::string& n : reader_->numberNames())
                fieldVars_.push_back(*prog_->variable(n));
    }

    void run(std::istream& in, const std::string& name, std::ostream& out) {
        long nrecs = 0, nout = 0;  // RADIANCE compat: counted per file
        if (reader_) reader_->begin(in, out);
        while (readRecord(in)) {
            ++nrecs;
            try {
                ev_->setRay(ray_);
                ev_->set(*recno_, static_cast<double>(nrecs));
                ev_->set(*outno_, static_cast<double>(nout + 1));
                for (std::size_t i = 0; i < fieldVars_.size(); ++i)
                    ev_->set(fieldVars_[i], reader_->numberValue(static_cast<int>(i)));
                if (!cond_ || ev_->eval(*cond_) > 0.0) {
                    putOut(out);
                    ++nout;
                }
            } catch (const InputError& e) {
                throw InputError(SourceLoc{name, 0},
                                 "record " + std::to_string(nrecs) + ": " + e.what());
            }
            if (o_.inputLimit && nrecs >= o_.inputLimit) break;
            if (o_.outputLimit && nout >= o_.outputLimit) break;
        }
    }

    void runNoInput(std::ostream& out) {
        ev_->setRay(ray_);
        putOut(out);
    }

    long mathErrors() const { return ev_->mathErrors(); }

    // ChannelSource: RADIANCE chanvalue and l_in.
    double channel(int n) override {
        if (o_.noInput || reader_) throw InputError("no column input");
        if (n < 1) throw InputError("illegal channel number");
        if (o_.binaryColumns) {
            if (n > o_.binaryColumns) return 0.0;
            const char* p = record_.data();
            if (o_.inputType == 'd' || o_.inputType == 'D') {
                double v;
                std::memcpy(&v, p + (n - 1) * sizeof(double), sizeof v);
                return v;
            }
            float v;
            std::memcpy(&v, p + (n - 1) * sizeof(float), sizeof v);
            return v;
        }
        if (static_cast<std::size_t>(n) <= columns_.size() && columns_[n - 1])
            return *columns_[n - 1];
        const char* cp = record_.c_str();
        const bool spaces =
            o_.blanksEqual && std::isspace(static_cast<unsigned char>(o_.separator));
        for (int i = 1; i < n; ++i) {
            if (spaces) {
                while (std::isspace(static_cast<unsigned char>(*cp))) ++cp;
                while (*cp && !std::isspace(static_cast<unsigned char>(*cp))) ++cp;
            } else {
                while (*cp && *cp++ != o_.separator) {
                }
            }
        }
        while (std::isspace(static_cast<unsigned char>(*cp))) ++cp;  // some atof()s mind tabs
        const double v = std::atof(cp);  // RADIANCE compat: no number reads as 0
        if (static_cast<std::size_t>(n) > columns_.size()) columns_.resize(n);
        columns_[n - 1] = v;
        return v;
    }
    double channelCount() override {
        if (o_.noInput || reader_) return 0;
        if (o_.binaryColumns) return o_.binaryColumns;
        const char* cp = record_.c_str();
        int n = 0;
        const bool spaces =
            o_.blanksEqual && std::isspace(static_cast<unsigned char>(o_.separator));
        while (*cp) {
            if (spaces) {
                while (std::isspace(static_cast<unsigned char>(*cp))) ++cp;
                n += *cp != '\0';
                while (*cp && !std::isspace(static_cast<unsigned char>(*cp))) ++cp;
            } else {
                n += *cp != '\n';
                while (*cp && *cp++ != o_.separator) {
                }
            }
        }
        return n;
    }

    // OutputValues: the -o format's numeric field `field`.
    double value(int field) override { return ev_->eval(prog_->expression(outFields_[field].var)); }

private:
    bool readRecord(std::istream& in) {
        columns_.clear();
        if (reader_) return reader_->next();
        auto* sb = in.rdbuf();
        if (o_.inputType != 'a' && o_.binaryColumns > 0) {
            const bool dbl = o_.inputType == 'd' || o_.inputType == 'D';
            const std::size_t size = dbl ? sizeof(double) : sizeof(float);
            const std::size_t bytes = size * static_cast<std::size_t>(o_.binaryColumns);
            record_.resize(bytes);
            if (static_cast<std::size_t>(
                    sb->sgetn(record_.data(), static_cast<std::streamsize>(bytes))) != bytes)
                return false;
            if (o_.inputType == 'D' || o_.inputType == 'F')
                swapBytes(record_.data(), size, static_cast<std::size_t>(o_.binaryColumns));
            return true;
        }
        // RADIANCE compat (fgets into INBSIZ): a longer line is read as several records.
        record_.clear();
        for (int c; record_.size() < kMaxRecord - 1 && (c = sb->sbumpc()) != EOF;) {
            record_ += static_cast<char>(c);
            if (c == '\n') break;
        }
        return !record_.empty();
    }

    void putOut(std::ostream& out) {
        out_.clear();
        int colpos = 0;
        if (!outFields_.empty()) {
            writeRecord(outFields_, strings_, o_.blanksEqual, *this, out_);
        } else if (o_.outputType == 'a') {
            char buf[64];
            for (const OutputChannel& c : prog_->outputChannels()) {
                const double v = ev_->eval(c.entry);
                if (colpos == 0) colpos = 1;  // no leading separator
                for (; colpos < c.channel; ++colpos) out_ += o_.separator;
                out_.append(buf,
                            static_cast<std::size_t>(std::snprintf(buf, sizeof buf, "%.9g", v)));
            }
        } else {
            const bool dbl = o_.outputType == 'd' || o_.outputType == 'D';
            const bool swap = o_.outputType == 'D' || o_.outputType == 'F';
            const std::size_t size = dbl ? sizeof(double) : sizeof(float);
            for (const OutputChannel& c : prog_->outputChannels()) {
                const double v = ev_->eval(c.entry);
                while (++colpos < c.channel) out_.append(size, '\0');  // unset channels: 0
                char bytes[sizeof(double)];
                if (dbl) {
                    std::memcpy(bytes, &v, size);
                } else {
                    const float f = static_cast<float>(v);
                    std::memcpy(bytes, &f, size);
                }
                if (swap) swapBytes(bytes, size, 1);
                out_.append(bytes, size);
            }
        }
        if (colpos && o_.outputType == 'a') out_ += '\n';
        out.write(out_.data(), static_cast<std::streamsize>(out_.size()));
        if (o_.flush) out.flush();
    }

    RcalcOptions o_;
    std::shared_ptr<const Program> prog_;
    std::optional<Evaluator> ev_;
    RayContext ray_;
    std::optional<Entry> cond_, recno_, outno_;
    std::vector<Entry> fieldVars_;
    std::vector<StringVar> strings_;
    std::optional<RecordReader> reader_;
    std::vector<FormatField> outFields_;
    std::string record_;                          // the current input record
    std::vector<std::optional<double>> columns_;  // its columns read so far
    std::string out_;
};

Rcalc::Rcalc(const RcalcOptions& options, const std::vector<std::string>& searchPath)
    : impl_(std::make_unique<Impl>(options, searchPath)) {}
Rcalc::~Rcalc() = default;
void Rcalc::run(std::istream& in, const std::string& name, std::ostream& out) {
    impl_->run(in, name, out);
}
void Rcalc::runNoInput(std::ostream& out) { impl_->runNoInput(out); }
long Rcalc::mathErrors() const { return impl_->mathErrors(); }

}  // namespace rp::calc
