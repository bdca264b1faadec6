// RADIANCE N-dimensional data files (ray.html, "Data Files"; used by brightdata,
// colordata, texdata, mixdata, plasdata ...): the number of dimensions, per axis either
// "begin end count" (evenly spaced) or "begin end count v1 .. vcount" with begin == end
// (listed, monotonic), then the values with the last axis varying fastest. Lookup is
// multilinear. Pictures (colorpict) are not read here.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rp::calc {

class DataFile {
public:
    static constexpr int kMaxDimensions = 8;

    struct Axis {
        double begin = 0, end = 0;
        int count = 0;
        std::vector<double> points;  // listed coordinates; empty when evenly spaced
    };

    // Reads `path`; `name` defaults to the path in error messages. Throws InputError
    // with file:line for missing files, bad counts, non-numbers, short or long data.
    static DataFile load(const std::string& path);
    static DataFile parse(std::string_view text, const std::string& name);

    int dimensions() const { return static_cast<int>(axes_.size()); }
    const Axis& axis(int i) const { return axes_[i]; }
    const std::vector<double>& values() const { return values_; }

    // Interpolated value at `point` (one coordinate per dimension). RADIANCE compat
    // (data.c): outside an axis' range the value is extrapolated linearly for one more
    // division, then tapers off harmonically towards zero.
    double value(std::span<const double> point) const;

private:
    std::vector<Axis> axes_;
    std::vector<double> values_;
    std::vector<std::size_t> strides_;
};

}  // namespace rp::calc
