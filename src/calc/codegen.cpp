// Node trees to VM code (see codegen.h).
#include "calc/codegen.h"

#include <algorithm>
#include <bit>

#include "calc/builtins.h"

namespace rp::calc {

int CodeGen::emitBlock(const Node* body, int varSlot) {
    if (cyclic_.size() != static_cast<std::size_t>(img_.nvars)) cyclic_.assign(img_.nvars, -1);
    Block b;
    for (int version = 0; version < 2; ++version) {
        argGlobals_ = version == 1;
        maxArg_ = 0;
        top_ = maxTop_ = 0;
        blockStart_ = b.start[version] = here();
        ensured_.assign(img_.nvars, 0);
        ensuredList_.clear();
        int v = gen(body, -1);
        if (varSlot >= 0)
            emit(Code::RetVar, 0, v, varSlot);
        else
            emit(Code::Ret, 0, v);
        b.frameSize = std::max(b.frameSize, maxTop_);
    }
    b.maxArg = maxArg_;
    img_.maxArg = std::max(img_.maxArg, maxArg_);
    img_.blocks.push_back(b);
    return static_cast<int>(img_.blocks.size()) - 1;
}

int CodeGen::alloc() {
    int r = top_++;
    if (top_ > maxTop_) maxTop_ = top_;
    return r;
}

int CodeGen::constant(double v) {
    auto [it, added] = constIndex_.try_emplace(std::bit_cast<std::uint64_t>(v),
                                               static_cast<int>(img_.constants.size()));
    if (added) img_.constants.push_back(v);
    return img_.constOperand(it->second);
}

int CodeGen::emit(Code op, int d, int a, int b, int c, const void* p) {
    img_.code.push_back(Instr{op, d, a, b, c, p});
    return here() - 1;
}

int CodeGen::place(int operand, int dst) {
    if (dst < 0 || operand == dst) return operand;
    emit(Code::Mov, dst, operand);
    return dst;
}

void CodeGen::forgetVarsAfter(std::size_t n) {
    while (ensuredList_.size() > n) {
        ensured_[ensuredList_.back()] = 0;
        ensuredList_.pop_back();
    }
}

int CodeGen::args(const Node* n) {
    const int base = top_;
    for (int i = 0; i < n->nkids; ++i) gen(n->kids[i], alloc());
    top_ = base;
    return base;
}

int CodeGen::binary(Code op, const Node* x, const Node* y, int dst) {
    const int mark = top_;
    int a = gen(x, -1);
    int b = gen(y, -1);
    top_ = mark;
    int d = target(dst);
    emit(op, d, a, b);
    return d;
}

// x*y + z and z + x*y (IEEE addition commutes exactly); operands are evaluated in the
// order written.
int CodeGen::mulAdd(const Node* n, int dst) {
    const int mark = top_;
    auto factors = [&](const Node* m, int& a, int& b) {
        a = gen(m->a, -1);
        b = m->op() == Op::MulC ? constant(m->num) : gen(m->b, -1);
    };
    int a, b, c;
    const Node* l = n->a;
    const Node* r = n->op() == Op::AddC ? nullptr : n->b;
    if (l->op() == Op::Mul || l->op() == Op::MulC) {
        factors(l, a, b);
        c = r ? gen(r, -1) : constant(n->num);
    } else {
        c = gen(l, -1);
        factors(r, a, b);
    }
    top_ = mark;
    int d = target(dst);
    emit(Code::MulAdd, d, a, b, c);
    return d;
}

// Does `n` (through variable bodies, not function bodies) refer to variable `slot`?
bool CodeGen::reaches(const Node* n, int slot, std::vector<char>& seen) const {
    if (!n) return true;  // body not compiled yet: assume the worst
    if (n->op() == Op::Var) {
        if (n->index == slot) return true;
        if (seen[n->index]) return false;
        seen[n->index] = 1;
        return reaches(static_cast<const VarInfo*>(n->ptr)->body, slot, seen);
    }
    for (const Node* k : {n->a, n->b, n->c})
        if (k && reaches(k, slot, seen)) return true;
    for (int i = 0; i < n->nkids; ++i)
        if (reaches(n->kids[i], slot, seen)) return true;
    return false;
}

bool CodeGen::inlinable(const VarInfo& v) {
    if (!v.body || here() - blockStart_ > kMaxInlineCode) return false;
    if (cyclic_[v.slot] < 0) {
        std::vector<char> seen(img_.nvars, 0);
        cyclic_[v.slot] = reaches(v.body, v.slot, seen) ? 1 : 0;
    }
    return cyclic_[v.slot] == 0;
}

// A variable: computed where first needed on this path, then read from its cache slot.
int CodeGen::var(const Node* n, int dst) {
    const int slot = n->index;
    if (!ensured_[slot]) {
        const auto& v = *static_cast<const VarInfo*>(n->ptr);
        if (inlinable(v)) {
            const int mark = top_;
            const std::size_t known = ensuredList_.size();
            int skip = emit(Code::JCached, 0, 0, slot);
            int value = gen(v.body, -1);
            top_ = mark;
            emit(Code::StVar, 0, value, slot);
            img_.code[skip].c = here();
            forgetVarsAfter(known);  // skipped when cached: nothing else is known
        } else {
            emit(Code::NeedVar, 0, top_, slot, 0, n->ptr);
        }
        ensured_[slot] = 1;
        ensuredList_.push_back(slot);
    }
    return place(CodeImage::varOperand(slot), dst);
}

int CodeGen::gen(const Node* n, int dst) {
    auto isMul = [](const Node* k) { return k && (k->op() == Op::Mul || k->op() == Op::MulC); };
    const int mark = top_;
    switch (n->op()) {
        case Op::Const:
            return place(constant(n->num), dst);
        case Op::Ray:
            return place(img_.rayOperand(n->index), dst);
        case Op::Var:
            return var(n, dst);
        case Op::ModArg: {
            if (argGlobals_ && n->index >= 1 && n->index <= kArgGlobals) {
                maxArg_ = std::max(maxArg_, n->index);
                return place(img_.argOperand(n->index), dst);
            }
            int d = target(dst);
            emit(Code::LdArg, d, 0, n->index, 0, n->info);
            return d;
        }
        case Op::Param: {
            int d = target(dst);
            emit(Code::LdParam, d, 0, n->index, 0, n->info);
            return d;
        }
        case Op::ModArgDyn:
        case Op::ParamDyn: {
            int a = gen(n->a, -1);
            top_ = mark;
            int d = target(dst);
            emit(n->op() == Op::ModArgDyn ? Code::LdArgDyn : Code::LdParamDyn, d, a, 0, 0, n->info);
            return d;
        }
        case Op::Neg: {
            int a = gen(n->a, -1);
            top_ = mark;
            int d = target(dst);
            emit(Code::Neg, d, a);
            return d;
        }
        case Op::Add:
            if (isMul(n->a) || isMul(n->b)) return mulAdd(n, dst);
            return binary(Code::Add, n->a, n->b, dst);
        case Op::AddC:
            if (isMul(n->a)) return mulAdd(n, dst);
            [[fallthrough]];
        case Op::SubC:
        case Op::MulC: {
            int a = gen(n->a, -1);
            top_ = mark;
            int d = target(dst);
            Code op = n->op() == Op::AddC ? Code::Add : n->op() == Op::SubC ? Code::Sub : Code::Mul;
            emit(op, d, a, constant(n->num));
            return d;
        }
        case Op::CSub: {
            int a = gen(n->a, -1);
            top_ = mark;
            int d = target(dst);
            emit(Code::Sub, d, constant(n->num), a);
            return d;
        }
        case Op::Sub:
            return binary(Code::Sub, n->a, n->b, dst);
        case Op::Mul:
            return binary(Code::Mul, n->a, n->b, dst);
        case Op::Div:
            return binary(Code::Div, n->a, n->b, dst);
        case Op::Pow:
            return binary(Code::Pow, n->a, n->b, dst);
        case Op::PowInt: {
            int a = gen(n->a, -1);
            top_ = mark;
            int d = target(dst);
            emit(Code::PowI, d, a, n->index);
            return d;
        }
        case Op::Math1: {
            int a = gen(n->a, -1);
            top_ = mark;
            int d = target(dst);
            emit(Code::Math1, d, a, 0, 0, n->ptr);
            return d;
        }
        case Op::BuiltinN: {
            int base = args(n);
            int d = target(dst);
            emit(Code::BuiltinN, d, base, 0, n->nkids, n->ptr);
            return d;
        }
        case Op::If: {
            int jnp;
            const Node* k = n->a;
            if (k->op() == Op::Sub || k->op() == Op::SubC || k->op() == Op::CSub) {
                int x = k->op() == Op::CSub ? constant(k->num) : gen(k->a, -1);
                int y = k->op() == Op::Sub    ? gen(k->b, -1)
                        : k->op() == Op::SubC ? constant(k->num)
                                              : gen(k->a, -1);
                top_ = mark;
                jnp = emit(Code::JNPSub, 0, x, y);
            } else {
                int cond = gen(k, -1);
                top_ = mark;
                jnp = emit(Code::JNP, 0, cond);
            }
            int d = target(dst);
            const std::size_t known = ensuredList_.size();
            gen(n->b, d);
            forgetVarsAfter(known);
            int jmp = emit(Code::Jmp);
            img_.code[jnp].c = here();
            gen(n->c, d);
            forgetVarsAfter(known);
            img_.code[jmp].c = here();
            return d;
        }
        case Op::Select: {
            int index = gen(n->kids[0], -1);
            top_ = mark;
            int d = target(dst);
            const int cases = n->nkids - 1;
            int sel = emit(Code::Sel, d, index, cases, 0, n->info);
            for (int k = 0; k < cases; ++k) emit(Code::Jmp);
            std::vector<int> exits;
            const std::size_t known = ensuredList_.size();
            for (int k = 1; k <= cases; ++k) {
                img_.code[sel + k].c = here();
                gen(n->kids[k], d);
                forgetVarsAfter(known);
                if (k < cases) exits.push_back(emit(Code::Jmp));
            }
            for (int e : exits) img_.code[e].c = here();
            img_.code[sel].c = here();
            return d;
        }
        case Op::CallUser: {
            int base = args(n);
            int d = target(dst);
            emit(Code::Call, d, base, static_cast<const FunctionInfo*>(n->ptr)->index, n->nkids,
                 n->info);
            return d;
        }
        case Op::CallParamFn: {
            int base = args(n);
            int d = target(dst);
            emit(Code::CallId, d, base, n->index, n->nkids, n->info);
            return d;
        }
        case Op::Chan: {
            int a = gen(n->a, -1);
            top_ = mark;
            int d = target(dst);
            emit(Code::Chan, d, a, n->index, 0, n->info);
            return d;
        }
        case Op::Error: {
            emit(Code::Error, 0, 0, 0, 0, n->info);
            return place(constant(0), dst);
        }
    }
    return place(constant(0), dst);
}

}  // namespace rp::calc
