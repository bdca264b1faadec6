// rmtxop's evaluation (rmtxop.h runRmtxop), after RADIANCE rmtxop.c loadop, binaryop,
// op_left2right, op_right2left and prefer_right2left.
#include <cstdio>
#include <optional>

#include "matrix/matrix_io.h"
#include "matrix/rmtxop.h"
#include "util/error.h"

namespace rp::matrix {

namespace {

std::string fixed(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, " %f", v);
    return buf;
}

class Evaluator {
public:
    Evaluator(RmtxopCommand& cmd, std::ostream& log) : cmd_(cmd), log_(log) {
        loaded_.resize(cmd.operands.size());
    }

    Matrix run() {
        Matrix m = preferRightToLeft() ? rightToLeft() : leftToRight();
        return applyOps(std::move(m), cmd_.trailing, "trailing_ops");
    }

private:
    const Matrix& load(size_t i) {
        if (!loaded_[i]) loaded_[i] = loadMatrix(cmd_.operands[i].spec, cmd_.operands[i].part);
        return *loaded_[i];
    }
    // The operand's matrix after its unary operations (loaded once, then handed over).
    Matrix take(size_t i) {
        load(i);
        Matrix m = std::move(*loaded_[i]);
        loaded_[i].reset();
        const Operand& o = cmd_.operands[i];
        return applyOps(std::move(m), o.ops, nameOf(i));
    }
    std::string nameOf(size_t i) const {
        const std::string& s = cmd_.operands[i].spec;
        return s == "-" ? kStdinName : s;
    }
    Matrix applyOps(Matrix m, const UnaryOps& ops, const std::string& name);
    Matrix combine(const std::string& name, Matrix left, char op, Matrix right);
    Matrix leftToRight();
    Matrix rightToLeft();
    bool preferRightToLeft();

    RmtxopCommand& cmd_;
    std::ostream& log_;
    std::vector<std::optional<Matrix>> loaded_;
};

Matrix Evaluator::applyOps(Matrix m, const UnaryOps& ops, const std::string& name) {
    const SourceLoc at{name, 0};
    if (!ops.scalars.empty()) {
        if (!ops.coefficients.empty()) throw InputError("options -s and -c are exclusive");
        std::vector<double> f = ops.scalars;
        if (f.size() == 1)
            f.assign(static_cast<size_t>(m.comps), f[0]);
        else if (static_cast<int>(f.size()) != m.comps)
            throw InputError(at, "-s must have one or " + std::to_string(m.comps) + " factors");
        scale(m, f);
        if (cmd_.verbose) {
            log_ << name << ": applied scalar (";
            for (double v : ops.scalars) log_ << fixed(v);
            log_ << " )\n";
        }
    }
    if (!ops.coefficients.empty()) {
        if (ops.coefficients.size() % static_cast<size_t>(m.comps))
            throw InputError(at, "-c must have N x " + std::to_string(m.comps) + " coefficients");
        const int from = m.comps;
        m = transformComponents(m, ops.coefficients);
        if (cmd_.verbose)
            log_ << name << ": applied " << m.comps << " x " << from << " transform\n";
    }
    if (ops.transpose) {
        m = transposed(m);
        if (cmd_.verbose) log_ << name << ": transposed rows and columns\n";
    }
    return m;
}

Matrix Evaluator::combine(const std::string& name, Matrix left, char op, Matrix right) {
    const SourceLoc at{name, 0};
    switch (op) {
        case '.': {
            if (left.comps != right.comps)
                throw InputError(at, "# components do not match (" + std::to_string(left.comps) +
                                         " and " + std::to_string(right.comps) + ")");
            if (left.cols != right.rows)
                throw InputError(at, "mismatched dimensions for product (" + left.sizeText() +
                                         " times " + right.sizeText() + ")");
            Matrix r = product(left, right);
            if (cmd_.verbose) log_ << name << ": concatenated matrix\n";
            return r;
        }
        case '+':
            if (left.rows != right.rows || left.cols != right.cols || left.comps != right.comps)
                throw InputError(at, "matrix sum failed: sizes differ (" + left.sizeText() +
                                         " plus " + right.sizeText() + ")");
            addTo(left, right);
            if (cmd_.verbose) log_ << name << ": added in matrix\n";
            return left;
        default: {
            const char* what = op == '/' ? "division" : "multiplication";
            if (left.rows != right.rows || left.cols != right.cols ||
                (right.comps > 1 && right.comps != left.comps))
                throw InputError(at, std::string("element-wise ") + what +
                                         " failed: sizes differ (" + left.sizeText() + " and " +
                                         right.sizeText() + ")");
            if (multiplyElements(left, right, op == '/'))
                log_ << name << ": warning - error during element-wise " << what << "\n";
            else if (cmd_.verbose)
                log_ << name << ": element-wise " << what << "\n";
            return left;
        }
    }
}

Matrix Evaluator::leftToRight() {
    Matrix m = take(0);
    for (size_t i = 0; cmd_.operands[i].nextOp; ++i)
        m = combine(nameOf(i + 1), std::move(m), cmd_.operands[i].nextOp, take(i + 1));
    return m;
}

Matrix Evaluator::rightToLeft() {
    size_t last = cmd_.operands.size() - 1;
    Matrix m = take(last);
    for (size_t i = last; i-- > 0;)
        m = combine(nameOf(i), take(i), cmd_.operands[i].nextOp, std::move(m));
    return m;
}

bool Evaluator::preferRightToLeft() {
    // RADIANCE compat (prefer_right2left): only for a chain of two or more products,
    // judged on the sizes after -t (the -s/-c transforms do not change them).
    const auto& ops = cmd_.operands;
    for (size_t i = 0; i + 1 < ops.size(); ++i)
        if (ops[i].nextOp != '.') return false;
    const size_t last = ops.size() - 1;
    if (last <= 1) return false;
    auto rows = [&](size_t i) { return ops[i].ops.transpose ? load(i).cols : load(i).rows; };
    auto cols = [&](size_t i) { return ops[i].ops.transpose ? load(i).rows : load(i).cols; };
    if (cols(last) == 1) return true;
    if (cols(last) >= rows(last)) return false;
    return cols(last) < rows(0);
}

}  // namespace

Matrix runRmtxop(RmtxopCommand& cmd, std::ostream& log) { return Evaluator(cmd, log).run(); }

}  // namespace rp::matrix
