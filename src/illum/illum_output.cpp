// mkillum's primitives and data files (see illum_output.h).
#include "illum/illum_output.h"

#include <unistd.h>

#include <functional>

#include "util/file_write.h"
#include "util/options.h"

namespace rp::illum {

namespace {

constexpr const char* kFunctionFile = "illum.cal";  // RADIANCE FNCFNM

std::string inDirectory(const std::string& directory, const std::string& name) {
    if (directory.empty() || name.empty() || name[0] == '/') return name;
    return directory + "/" + name;
}

void writeFile(const std::string& path, const std::string& text) {
    AtomicFile file(path);
    file.write(text.data(), text.size());
    file.commit();
}

std::string axisLine(const Vec3& a) { return formatLine("\t%f\t%f\t%f\n", a.x, a.y, a.z); }

// Twice the row's mean less each value: the row mirrored across the pole, so that
// interpolation toward the pole ends at the row's mean (RADIANCE compinv).
std::vector<Color> mirrored(const Color* row, int n) {
    Color mean;
    for (int j = 0; j < n; ++j) mean += row[j];
    mean = mean / double(n);
    std::vector<Color> out(static_cast<size_t>(n));
    for (int j = 0; j < n; ++j) out[size_t(j)] = mean * 2 - row[j];
    return out;
}

// The rows of a data file: the mirrored first row, every row, then (sphere) the mirrored
// last row, each value mapped by `value`.
std::vector<std::vector<double>> dataRows(const Distribution& d, bool sphere,
                                          const std::function<double(const Color&)>& value) {
    const int m = d.azimuths;
    std::vector<std::vector<Color>> colours;
    colours.push_back(mirrored(&d.sums[0], m));
    for (int i = 0; i < d.altitudes; ++i)
        colours.emplace_back(d.sums.begin() + i * m, d.sums.begin() + (i + 1) * m);
    if (sphere) colours.push_back(mirrored(&d.sums[size_t(d.altitudes - 1) * size_t(m)], m));
    std::vector<std::vector<double>> rows;
    for (const auto& row : colours) {
        rows.emplace_back();
        for (const Color& c : row) rows.back().push_back(value(c));
    }
    return rows;
}

// Writes the file(s) of distribution `d` and returns the pattern's first lines.
std::string writeDistribution(IllumSettings& s, const Distribution& d, const Color& average,
                              bool sphere, const std::string& directory) {
    const int n = d.altitudes;
    const double alt0 = sphere ? 1 + 1.0 / n : 1 + .5 / n;
    const double alt1 = sphere ? -1 - 1.0 / n : .5 / n;
    const double samples = d.samples;
    std::string out = "\nvoid ";
    if (s.colour == ColourMode::kDistribution) {
        out += "colordata " + s.material + ".dist\n9 red green blue";
        for (int p = 0; p < 3; ++p) {
            // A channel the average lacks has nothing to normalise: zeros (RADIANCE
            // would write infinities).
            const double mult = average[p] > 0 ? 1 / (samples * average[p]) : 0;
            const std::string name = nextDataFile(s, "RGB"[p], directory);
            writeFile(inDirectory(directory, name),
                      formatDataFile(alt0, alt1, dataRows(d, sphere, [&](const Color& c) {
                                         return c[p] * mult;
                                     })));
            out += " " + name;
        }
    } else {
        const double mult = 1 / (samples * illumBrightness(average));
        const std::string name = nextDataFile(s, 0, directory);
        writeFile(inDirectory(directory, name),
                  formatDataFile(alt0, alt1, dataRows(d, sphere, [&](const Color& c) {
                                     return illumBrightness(c) * mult;
                                 })));
        out += "brightdata " + s.material + ".dist\n5 noneg " + name;
    }
    ++s.dataFileNumber;
    return out;
}

}  // namespace

std::string formatObject(const std::string& modifier, const InputObject& o) {
    if (isSurface(o.type) && modifier == "void") return {};
    std::string out =
        "\n" + modifier + " " + o.typeName + " " + o.name + "\n" + std::to_string(o.sargs.size());
    for (const std::string& a : o.sargs) out += " " + a;
    out += "\n0\n" + std::to_string(o.rargs.size());
    for (size_t i = 0; i < o.rargs.size(); ++i) {
        if (i % 3 == 0) out += '\n';
        out += formatLine(" %18.12g", o.rargs[i]);
    }
    return out + '\n';
}

std::string formatAlias(const InputObject& o) {
    return "\n" + o.modifier + " alias " + o.name + "\t" + o.aliasOf + "\n";
}

std::string formatDataFile(double alt0, double alt1, const std::vector<std::vector<double>>& rows) {
    const size_t m = rows.empty() ? 0 : rows.front().size();
    std::string out = formatLine("2\n%f %f %d\n%f %f %d\n", alt0, alt1, int(rows.size()), 0.0,
                                 2 * kPi, int(m) + 1);
    size_t column = 0;
    auto put = [&](double v) {
        if (column++ % 5 == 0) out += '\n';
        out += formatLine(" %11e", v);
    };
    for (const auto& row : rows) {
        for (double v : row) put(v);
        put(row.front());  // azimuth 2 pi is azimuth 0
    }
    return out + '\n';
}

std::string nextDataFile(IllumSettings& s, char channel, const std::string& directory) {
    auto name = [&] {
        std::string n = s.dataFile;
        if (channel) n += channel;
        if (s.dataFileNumber > 0) n += std::to_string(s.dataFileNumber);
        return n + ".dat";
    };
    if (!s.clobber)
        while (::access(inDirectory(directory, name()).c_str(), F_OK) == 0) ++s.dataFileNumber;
    return name();
}

std::string writeFlatDistribution(IllumSettings& s, const Distribution& d, const Color& average,
                                  const FlatFrame& f, const std::string& directory) {
    std::string out = writeDistribution(s, d, average, false, directory);
    out += std::string("\n\t") + kFunctionFile + " il_alth il_azih\n0\n9\n";
    return out + axisLine(f.u) + axisLine(f.v) + axisLine(f.w);
}

std::string writeRoundDistribution(IllumSettings& s, const Distribution& d, const Color& average,
                                   const std::string& directory) {
    std::string out = writeDistribution(s, d, average, true, directory);
    return out + std::string("\n\t") + kFunctionFile + " il_alt il_azi\n0\n0\n";
}

std::string formatIllum(const IllumSettings& s, const std::string& alternate, const Color& average,
                        const InputObject& o) {
    std::string out = s.density <= 0 ? "\nvoid " : "\n" + s.material + ".dist ";
    out += (s.light ? "light " : "illum ") + s.material;
    out += s.light || alternate == "void" ? "\n0" : "\n1 " + alternate;
    const Color c = s.colour == ColourMode::kNone ? Color::grey(illumBrightness(average)) : average;
    out += formatLine("\n0\n3 %f %f %f\n", c.r, c.g, c.b);
    return out + formatObject(s.material, o);
}

}  // namespace rp::illum
