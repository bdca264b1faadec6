// Reinhart sky patches and the table cosine (see gendaymtx_patches.h).
#include "gen/gendaymtx_patches.h"

#include <array>
#include <cmath>

#include "util/error.h"

namespace rp::gen {

namespace {
constexpr int kTregenzaRows = 7;
constexpr int kTregenzaRowCount[kTregenzaRows] = {30, 30, 24, 24, 18, 12, 6};
constexpr int kCosEntries = 1024;  // per quarter turn
}  // namespace

Vec3 skyVector(double altitude, double azimuth) {
    double c = std::cos(altitude);
    return {c * std::sin(azimuth), c * std::cos(azimuth), std::sin(altitude)};
}

Vec3 ReinhartSky::direction(int patch) const { return skyVector(altitude[patch], azimuth[patch]); }

ReinhartSky makeReinhartSky(int m) {
    RP_CHECK(m >= 0);
    ReinhartSky sky;
    sky.subdivisions = m;
    int count = 2;
    for (int n : kTregenzaRowCount) count += n * m * m;
    sky.altitude.assign(count, 0);
    sky.azimuth.assign(count, 0);
    sky.solidAngle.assign(count, 0);
    const double alpha = (kPi / 2) / (kTregenzaRows * m + 0.5);
    sky.altitude[0] = static_cast<float>(-kPi / 2);
    sky.solidAngle[0] = static_cast<float>(2 * kPi);
    sky.altitude[count - 1] = static_cast<float>(kPi / 2);
    sky.solidAngle[count - 1] = static_cast<float>(2 * kPi * (1 - std::cos(alpha * 0.5)));
    int p = 1;
    for (int row = 0; row < kTregenzaRows * m; ++row) {
        const float altitude = static_cast<float>(alpha * (row + 0.5));
        const int inRow = kTregenzaRowCount[row / m] * m;
        const float dom = static_cast<float>(
            2 * kPi * (std::sin(alpha * (row + 1)) - std::sin(alpha * row)) / double(inRow));
        for (int j = 0; j < inRow; ++j, ++p) {
            sky.altitude[p] = altitude;
            sky.azimuth[p] = static_cast<float>(2 * kPi * j / double(inRow));
            sky.solidAngle[p] = dom;
        }
    }
    return sky;
}

double tableCos(double x) {
    static const std::array<double, kCosEntries + 1> table = [] {
        std::array<double, kCosEntries + 1> t{};
        for (int i = 0; i <= kCosEntries; ++i) t[i] = std::cos((kPi / 2 / kCosEntries) * i);
        return t;
    }();
    if (x < 0) x = -x;
    int i = static_cast<int>((kCosEntries * 2 / kPi) * x + 0.5);
    i %= 4 * kCosEntries;
    switch (i / kCosEntries) {
        case 0:
            return table[i];
        case 1:
            return -table[2 * kCosEntries - i];
        case 2:
            return -table[i - 2 * kCosEntries];
        default:
            return table[4 * kCosEntries - i];
    }
}

double tableSin(double x) { return tableCos(x - kPi / 2); }

}  // namespace rp::gen
