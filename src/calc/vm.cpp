// The dispatch loop of the .cal virtual machine (vm.h). Hot instructions are a switch
// case each with operands read through one select between the register window and the
// globals; errors build their message only when thrown.
#include "calc/vm.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "calc/builtins.h"

namespace rp::calc {
namespace {

static_assert(offsetof(RayContext, DA) + sizeof(Vec3) == kRayDoubles * sizeof(double),
              "ray variables must be the first kRayDoubles doubles of RayContext");

[[noreturn]] void runtimeError(const void* info, const std::string& msg) {
    if (info) throw InputError(static_cast<const NodeInfo*>(info)->loc, msg);
    throw InputError(msg);
}

[[noreturn]] void tooDeep(const SourceLoc* loc, const char* kind, const std::string& name) {
    std::string msg =
        std::string("recursion too deep in ") + kind + " '" + name + "' (missing base case?)";
    if (loc) throw InputError(*loc, msg);
    throw InputError(msg);
}

inline double finiteOrZero(double r, long& errors) {
    if (std::isfinite(r)) [[likely]]
        return r;
    ++errors;
    return 0;
}

inline int indexOf(double v) { return roundedIndex(v); }

double modArg(int n, const void* info, const RayContext& ray) {
    const auto& args = ray.args;
    if (n < 1) return static_cast<double>(args.size());
    if (static_cast<std::size_t>(n) > args.size())
        runtimeError(info, "missing real argument " + std::to_string(n) + " (modifier has " +
                               std::to_string(args.size()) + ")");
    return args[n - 1];
}

double param(int n, const void* info, const double* prm, int nprm) {
    if (n < 1) return nprm;
    if (n > nprm) runtimeError(info, "missing argument " + std::to_string(n) + " to function");
    return prm[n - 1];
}

}  // namespace

double powerInt(double x, int n, long& errors) {
    unsigned m = static_cast<unsigned>(n < 0 ? -n : n);
    double r = 1, b = x;
    while (m) {
        if (m & 1) r *= b;
        b *= b;
        m >>= 1;
    }
    return n < 0 ? finiteOrZero(1 / r, errors) : finiteOrZero(r, errors);
}

void Machine::attach(const CodeImage& image) {
    image_ = &image;
    int frame = 1;
    for (const Block& b : image.blocks) frame = std::max(frame, b.frameSize);
    const int nglobals = image.globalCount();
    mem_.assign(nglobals + frame, 0.0);
    r_ = mem_.data() + nglobals;
    for (std::size_t i = 0; i < image.constants.size(); ++i)
        r_[image.constOperand(static_cast<int>(i))] = image.constants[i];
    stamps_.assign(image.nvars + 1, 0);
    if (!saved_) saved_.reset(new double[kSavedCapacity]);
    setRay(ray_ ? *ray_ : defaultRay_);
}

void Machine::setRay(const RayContext& ray) {
    ray_ = &ray;
    ++clock_;
    std::memcpy(r_ + image_->rayOperand(0), &ray, kRayDoubles * sizeof(double));
    const std::size_t n = std::min(ray.args.size(), static_cast<std::size_t>(image_->maxArg));
    if (n) std::memcpy(r_ + image_->argOperand(1), ray.args.data(), n * sizeof(double));
}

double Machine::call(double id, const double* args, int nargs) {
    if (id >= 0) return run(image_->funcBlock[static_cast<int>(id)], args, nargs);
    const Builtin& b = builtins()[static_cast<int>(-id) - 1];
    if (nargs < b.minArgs || nargs > b.maxArgs)
        throw InputError("wrong number of arguments to '" + std::string(b.name) + "'");
    return finiteOrZero(b.f1 ? b.f1(args[0]) : b.fn(args, nargs), mathErrors);
}

double Machine::run(int blockId, const double* args, int nargs) {
    const CodeImage& img = *image_;
    const Instr* const code = img.code.data();
    double* const r = r_;
    if (nargs > static_cast<int>(kSavedCapacity)) runtimeError(nullptr, "too many arguments");
    std::copy(args, args + nargs, saved_.get());
    double* const saved = saved_.get();
    const std::size_t savedCap = kSavedCapacity;
    std::size_t savedTop = nargs;
    const double* prm = saved;
    int nprm = nargs;
    const double* const argv = ray_->args.data();
    const std::size_t argc = ray_->args.size();
    const Instr* pc = code + img.blocks[blockId].entry(argc);
    if (frames_.empty()) frames_.resize(64);
    Frame* frames = frames_.data();  // frames[0 .. depth) are the callers
    std::size_t depth = 0;
    std::size_t frameLimit = std::min(frames_.size(), std::size_t(kMaxCallDepth) + 1);
    const std::uint64_t clock = clock_;
    std::uint64_t* const stamps = stamps_.data();
    const Block* const blocks = img.blocks.data();

// Operand i: a register (i >= 0) or a global (i < 0); globals lie just below r.
#define V(i) r[i]
// Runs `block` in the same registers after saving the caller's first `live` ones (and
// the arguments among them); LOC, KIND and NAME describe the block in errors.
#define ENTER(block, live, loc, kind, name, dst)                                           \
    do {                                                                                   \
        if (depth >= frameLimit) [[unlikely]] {                                            \
            if (depth > static_cast<std::size_t>(kMaxCallDepth)) tooDeep(loc, kind, name); \
            frames_.resize(2 * depth);                                                     \
            frames = frames_.data();                                                       \
            frameLimit = std::min(frames_.size(), std::size_t(kMaxCallDepth) + 1);         \
        }                                                                                  \
        const std::size_t n_ = (live);                                                     \
        if (savedTop + n_ > savedCap) [[unlikely]]                                         \
            tooDeep(loc, kind, name);                                                      \
        std::copy(r, r + n_, saved + savedTop);                                            \
        frames[depth++] = Frame{pc, savedTop, n_, prm, nprm, dst};                         \
        savedTop += n_;                                                                    \
        pc = code + blocks[block].entry(argc);                                             \
    } while (0)
    const Instr* in;
#if defined(__GNUC__)
    // Threaded dispatch: each instruction jumps straight to the next one's handler, so
    // the branch predictor sees one indirect jump per kind of instruction.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"
    static const void* const kHandlers[] = {
        &&op_Mov,   &&op_Neg,      &&op_Add,     &&op_Sub,        &&op_Mul,      &&op_MulAdd,
        &&op_Div,   &&op_Pow,      &&op_PowI,    &&op_Math1,      &&op_BuiltinN, &&op_Jmp,
        &&op_JNP,   &&op_JNPSub,   &&op_Sel,     &&op_JCached,    &&op_StVar,    &&op_NeedVar,
        &&op_LdArg, &&op_LdArgDyn, &&op_LdParam, &&op_LdParamDyn, &&op_Call,     &&op_CallId,
        &&op_Ret,   &&op_RetVar,   &&op_Chan,    &&op_Error};
#define CASE(name) op_##name : case Code::name
#define NEXT                                       \
    do {                                           \
        in = pc++;                                 \
        goto* kHandlers[static_cast<int>(in->op)]; \
    } while (0)
#else
#define CASE(name) case Code::name
#define NEXT break
#endif
    for (;;) {
        in = pc++;
        switch (in->op) {
            CASE(Mov) : r[in->d] = V(in->a);
            NEXT;
            CASE(Neg) : r[in->d] = -V(in->a);
            NEXT;
            CASE(Add) : r[in->d] = V(in->a) + V(in->b);
            NEXT;
            CASE(Sub) : r[in->d] = V(in->a) - V(in->b);
            NEXT;
            CASE(Mul) : r[in->d] = V(in->a) * V(in->b);
            NEXT;
            CASE(MulAdd) : {
                double m = V(in->a) * V(in->b);
                r[in->d] = m + V(in->c);
                NEXT;
            }
            CASE(Div) : {
                double x = V(in->a), y = V(in->b);
                if (y == 0) [[unlikely]] {
                    ++mathErrors;
                    r[in->d] = 0;
                } else {
                    r[in->d] = x / y;
                }
                NEXT;
            }
            CASE(Pow) : r[in->d] = finiteOrZero(std::pow(V(in->a), V(in->b)), mathErrors);
            NEXT;
            CASE(PowI) : r[in->d] = powerInt(V(in->a), in->b, mathErrors);
            NEXT;
            CASE(Math1)
                : r[in->d] =
                      finiteOrZero(static_cast<const Builtin*>(in->p)->f1(V(in->a)), mathErrors);
            NEXT;
            CASE(BuiltinN)
                : r[in->d] = finiteOrZero(static_cast<const Builtin*>(in->p)->fn(r + in->a, in->c),
                                          mathErrors);
            NEXT;
            CASE(Jmp) : pc = code + in->c;
            NEXT;
            CASE(JNP) : if (!(V(in->a) > 0)) pc = code + in->c;
            NEXT;
            CASE(JNPSub) : if (!(V(in->a) - V(in->b) > 0)) pc = code + in->c;
            NEXT;
            CASE(Sel) : {
                int k = indexOf(V(in->a));
                if (k == 0) {
                    r[in->d] = in->b;
                    pc = code + in->c;
                } else if (k < 0 || k > in->b) {
                    runtimeError(in->p, "select index " + std::to_string(k) + " out of range 1.." +
                                            std::to_string(in->b));
                } else {
                    pc = code + pc[k - 1].c;
                }
                NEXT;
            }
            CASE(JCached) : if (stamps[in->b] == clock) pc = code + in->c;
            NEXT;
            CASE(StVar) : r[CodeImage::varOperand(in->b)] = V(in->a);
            stamps[in->b] = clock;
            NEXT;
            CASE(NeedVar) : if (stamps[in->b] != clock) {
                const auto* v = static_cast<const VarInfo*>(in->p);
                ENTER(img.varBlock[in->b], in->a, &v->loc, "variable", v->name, -1);
            }
            NEXT;
            CASE(LdArg)
                : if (in->b >= 1 && static_cast<std::size_t>(in->b) <= argc) [[likely]] r[in->d] =
                      argv[in->b - 1];
            else r[in->d] = modArg(in->b, in->p, *ray_);
            NEXT;
            CASE(LdArgDyn) : r[in->d] = modArg(indexOf(V(in->a)), in->p, *ray_);
            NEXT;
            CASE(LdParam) : r[in->d] = param(in->b, in->p, prm, nprm);
            NEXT;
            CASE(LdParamDyn) : r[in->d] = param(indexOf(V(in->a)), in->p, prm, nprm);
            NEXT;
            CASE(Call) : {
                const FunctionInfo& f = *img.functions[in->b];
                ENTER(img.funcBlock[in->b], in->a + in->c,
                      &static_cast<const NodeInfo*>(in->p)->loc, "function", f.name, in->d);
                prm = saved + savedTop - in->c;
                nprm = in->c;
                NEXT;
            }
            CASE(CallId) : {
                double id = param(in->b, in->p, prm, nprm);
                const double* base = r + in->a;
                if (id >= 0) {
                    int fi = static_cast<int>(id);
                    if (img.funcBlock[fi] < 0) runtimeError(in->p, "function not available yet");
                    ENTER(img.funcBlock[fi], in->a + in->c,
                          &static_cast<const NodeInfo*>(in->p)->loc, "function",
                          img.functions[fi]->name, in->d);
                    prm = saved + savedTop - in->c;
                    nprm = in->c;
                } else {
                    const Builtin& b = builtins()[static_cast<int>(-id) - 1];
                    if (in->c < b.minArgs || in->c > b.maxArgs)
                        runtimeError(in->p,
                                     "wrong number of arguments to '" + std::string(b.name) + "'");
                    r[in->d] = finiteOrZero(b.f1 ? b.f1(base[0]) : b.fn(base, in->c), mathErrors);
                }
                NEXT;
            }
            CASE(RetVar) : CASE(Ret) : {
                double v = V(in->a);
                if (in->op == Code::RetVar) {
                    r[CodeImage::varOperand(in->b)] = v;
                    stamps[in->b] = clock;
                }
                if (depth == 0) return v;
                const Frame& f = frames[--depth];
                pc = f.pc;
                std::copy(saved + f.saved, saved + f.saved + f.live, r);
                savedTop = f.saved;
                prm = f.prm;
                nprm = f.nprm;
                if (f.dst >= 0) r[f.dst] = v;
                NEXT;
            }
            CASE(Chan) : {
                const int n = indexOf(V(in->a));
                if (!channels_) runtimeError(in->p, "no input channels");
                r[in->d] = in->b == 1 && n == 0 ? channels_->channelCount() : channels_->channel(n);
                NEXT;
            }
            CASE(Error) : runtimeError(in->p, static_cast<const NodeInfo*>(in->p)->text);
            default:
                __builtin_unreachable();
        }
    }
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
#undef CASE
#undef NEXT
#undef V
#undef ENTER
}

}  // namespace rp::calc
