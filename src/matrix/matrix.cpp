// Matrix operations (see matrix.h), following RADIANCE rmatrix.c.
#include "matrix/matrix.h"

#include "util/error.h"

namespace rp::matrix {

namespace {

void mergeType(Matrix& into, DataType other) {
    const DataType t = combinedType(into.type, other);
    if (t == DataType::FromHeader)
        into.info += kTypeMismatchInfo;
    else
        into.type = t;
}

}  // namespace

std::string Matrix::sizeText() const {
    std::string s = std::to_string(rows) + "x" + std::to_string(cols);
    if (comps != 1) s += "x" + std::to_string(comps);
    return s;
}

Matrix transposed(const Matrix& m) {
    if (m.rows == 1 || m.cols == 1) {  // same order in memory
        Matrix v = m;
        std::swap(v.rows, v.cols);
        return v;
    }
    Matrix t(m.cols, m.rows, m.comps);
    t.type = m.type;
    if (!m.info.empty()) t.info = m.info + "Transposed rows and columns\n";
    for (int i = 0; i < t.rows; ++i)
        for (int j = 0; j < t.cols; ++j)
            for (int k = 0; k < t.comps; ++k) t.at(i, j, k) = m.at(j, i, k);
    return t;
}

Matrix product(const Matrix& a, const Matrix& b) {
    RP_CHECK(a.cols == b.rows && a.comps == b.comps);
    Matrix r(a.rows, b.cols, a.comps);  // a new matrix: type double, no info
    const DataType t = combinedType(a.type, b.type);
    if (t == DataType::FromHeader)
        r.info = kTypeMismatchInfo;
    else
        r.type = t;
    for (int i = 0; i < r.rows; ++i)
        for (int j = 0; j < r.cols; ++j)
            for (int k = 0; k < r.comps; ++k) {
                // RADIANCE compat (rmx_multiply): long double, last term first, so the
                // digits printed with %.15e are RADIANCE's.
                long double d = 0;
                for (int h = a.cols; h--;)
                    d += static_cast<long double>(a.at(i, h, k) * b.at(h, j, k));
                r.at(i, j, k) = static_cast<double>(d);
            }
    return r;
}

int multiplyElements(Matrix& a, const Matrix& b, bool divide) {
    RP_CHECK(a.rows == b.rows && a.cols == b.cols && (b.comps == 1 || b.comps == a.comps));
    mergeType(a, b.type);
    int zeroDivides = 0;
    for (int i = 0; i < a.rows; ++i)
        for (int j = 0; j < a.cols; ++j)
            for (int k = 0; k < a.comps; ++k) {
                const double d = b.at(i, j, b.comps == 1 ? 0 : k);
                double& v = a.at(i, j, k);
                if (!divide) {
                    v *= d;
                } else if (d == 0) {
                    // RADIANCE counts a one-component divisor once per element.
                    if (b.comps > 1 || k == 0) ++zeroDivides;
                    v = 0;
                } else if (b.comps == 1) {
                    v *= 1. / d;  // RADIANCE compat: the reciprocal, then products
                } else {
                    v /= d;
                }
            }
    if (zeroDivides) a.info += kZeroDivideInfo;
    return zeroDivides;
}

void addTo(Matrix& sum, const Matrix& add) {
    RP_CHECK(sum.rows == add.rows && sum.cols == add.cols && sum.comps == add.comps);
    mergeType(sum, add.type);
    for (size_t i = 0; i < sum.values.size(); ++i) sum.values[i] += 1.0 * add.values[i];
}

void scale(Matrix& m, const std::vector<double>& perComponent) {
    RP_CHECK(static_cast<int>(perComponent.size()) >= m.comps);
    for (size_t i = 0; i < m.values.size(); ++i)
        m.values[i] *= perComponent[i % static_cast<size_t>(m.comps)];
    if (!m.info.empty()) m.info += "Applied scalar\n";
}

Matrix transformComponents(const Matrix& m, const std::vector<double>& coef) {
    RP_CHECK(m.comps > 0 && !coef.empty() && coef.size() % static_cast<size_t>(m.comps) == 0);
    const int n = static_cast<int>(coef.size()) / m.comps;
    Matrix t(m.rows, m.cols, n);
    t.type = m.type;
    if (!m.info.empty())
        t.info = m.info + "Applied " + std::to_string(n) + "x" + std::to_string(m.comps) +
                 " component transform\n";
    for (int i = 0; i < m.rows; ++i)
        for (int j = 0; j < m.cols; ++j)
            for (int kd = 0; kd < n; ++kd) {
                double d = 0;  // RADIANCE compat: last source component first
                for (int ks = m.comps; ks--;) d += coef[kd * m.comps + ks] * m.at(i, j, ks);
                t.at(i, j, kd) = d;
            }
    return t;
}

}  // namespace rp::matrix
