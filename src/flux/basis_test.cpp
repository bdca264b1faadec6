// Hemisphere bases: bin counts, the stratifying curve, and the consistency rfluxmtx.1
// promises ("a receiver surface may be reused as a sender ... the matrices will
// concatenate properly"): every direction a sender draws for bin b falls in bin b of
// the receiver binning (lib/*.cal, our Shirley-Chiu definitions) of the same surface.
#include "flux/basis.h"

#include <gtest/gtest.h>

#include <set>

#include "calc/program.h"
#include "util/rng.h"

namespace rp::flux {
namespace {

TEST(Basis, BinCounts) {
    EXPECT_EQ(basisBins(BasisKind::Uniform, 1), 1);
    EXPECT_EQ(basisBins(BasisKind::ShirleyChiu, 5), 25);
    EXPECT_EQ(basisBins(BasisKind::Reinhart, 1), 145);
    EXPECT_EQ(basisBins(BasisKind::Reinhart, 2), 577);
    EXPECT_EQ(basisBins(BasisKind::Reinhart, 4), 2305);
    EXPECT_EQ(basisBins(BasisKind::KlemsFull, 1), 145);
    EXPECT_EQ(basisBins(BasisKind::KlemsHalf, 1), 73);
    EXPECT_EQ(basisBins(BasisKind::KlemsQuarter, 1), 41);
}

TEST(Basis, MultiSample3Stratifies) {
    // 512 numbers, one per 1/512 of [0,1), land one in each of the 8x8x8 cells.
    std::set<int> cells;
    const double jitter[3] = {.5, .5, .5};
    for (int n = 0; n < 512; ++n) {
        double t[3];
        multiSample3((n + .37) / 512, jitter, t);
        cells.insert(int(t[0] * 8) * 64 + int(t[1] * 8) * 8 + int(t[2] * 8));
    }
    EXPECT_EQ(cells.size(), 512u);
}

TEST(Basis, ReceiverArgumentsAsRadiance) {
    const ReceiverBins u = receiverBins(BasisKind::Uniform, 1, '+', {0, 0, 1}, {0, 1, 0});
    EXPECT_EQ(u.binExpr, "if(-Dx*0-Dy*0-Dz*1,0,-1)");
    const ReceiverBins r = receiverBins(BasisKind::Reinhart, 1, '+', {0, 0, -1}, {0, 1, 0});
    EXPECT_EQ(r.params, "MF=1,rNx=0,rNy=0,rNz=-1,Ux=0,Uy=1,Uz=0,RHS=+1");
    EXPECT_EQ(r.countExpr, "Nrbins");
    const ReceiverBins k = receiverBins(BasisKind::KlemsHalf, 1, '-', {0, -1, 0}, {0, 0, 1});
    EXPECT_EQ(k.calFile, "klems_half.cal");
    EXPECT_EQ(k.params, "RHS=-1");
    EXPECT_EQ(k.binExpr, "khbin(0,-1,0,0,0,1)");
}

// The receiver bin of a ray travelling `d`, as rcontrib evaluates it.
class ReceiverBinner {
public:
    ReceiverBinner(BasisKind kind, int size, char sign, const Vec3& n, const Vec3& up)
        : b_({std::string(RP_SOURCE_DIR) + "/lib"}) {
        const ReceiverBins r = receiverBins(kind, size, sign, n, up);
        b_.loadFile("rayinit.cal");
        if (!r.calFile.empty()) b_.loadFile(r.calFile);
        std::string params = r.params;
        for (char& c : params)
            if (c == ',') c = ';';
        if (!params.empty()) b_.loadString(params + ";");
        id_ = b_.addExpression(r.binExpr, {});
        program_ = b_.build();
        ev_ = std::make_unique<calc::Evaluator>(program_);
    }
    int bin(const Vec3& d) {
        ctx_.D = d;
        ev_->setRay(ctx_);
        return int(ev_->eval(program_->expression(id_)));
    }

private:
    calc::Builder b_;
    int id_ = 0;
    std::shared_ptr<const calc::Program> program_;
    std::unique_ptr<calc::Evaluator> ev_;
    calc::RayContext ctx_;
};

struct Case {
    BasisKind kind;
    int size;
    char sign;
};

TEST(Basis, SenderDirectionsFallInTheirReceiverBins) {
    const Vec3 n = normalize(Vec3{0.3, -1, 0.2}), up{0, 0, 1};
    Vec3 u = normalize(cross(up, n));
    const Vec3 v = cross(n, u);
    for (const Case c : {Case{BasisKind::KlemsFull, 1, '+'}, Case{BasisKind::KlemsHalf, 1, '-'},
                         Case{BasisKind::KlemsQuarter, 1, '+'}, Case{BasisKind::Reinhart, 1, '+'},
                         Case{BasisKind::Reinhart, 2, '-'}, Case{BasisKind::ShirleyChiu, 4, '+'},
                         Case{BasisKind::ShirleyChiu, 3, '-'}}) {
        const Vec3 uu = c.sign == '-' ? -u : u;
        ReceiverBinner binner(c.kind, c.size, c.sign, n, up);
        Rng rng(1, RngDomain::Test, uint64_t(c.kind));
        int wrong = 0;
        const int bins = basisBins(c.kind, c.size);
        for (int b = 0; b < bins; ++b)
            for (int k = 0; k < 8; ++k) {
                // Keep off the patch edges, where rounding may go either way.
                const double s1 = .02 + .96 * rng.uniform(), s2 = .02 + .96 * rng.uniform();
                const Vec3 d = senderDirection(c.kind, c.size, b, s1, s2);
                const Vec3 dir = uu * d.x + v * d.y + n * d.z;
                ASSERT_LT(dot(dir, n), 0);
                wrong += binner.bin(dir) != b;
            }
        EXPECT_EQ(wrong, 0) << "basis " << int(c.kind) << " size " << c.size;
    }
}

}  // namespace
}  // namespace rp::flux
